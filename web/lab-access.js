// The parallel DOM of one lab: beside its canvas (which a screen reader cannot read), a
// <section class="lab-access"> of native HTML kept in step with the app through its API: the
// lessons as buttons, the lesson's parameters as labelled controls (param_specs: the same
// ParamSpec that drives the ImGui slider and the CLI), the step buttons, a text description of
// what the view shows (describe), and the event log's newest line as a polite live region.
//
// Visually it is hidden (clipped, as screen-reader-only text) until the keyboard enters it: Tab
// from the canvas lands in it, and while focus is inside it shows as a panel over the app's side
// panel (showPlace), or the lab's bottom. Tab from its last control leaves the lab: nothing
// traps the keyboard.
//
// It polls the app on a short timer (not while the page is hidden) and touches the DOM only
// where something changed. Nothing received is parsed as HTML: text goes in as textContent.
'use strict';

class CSpaceLabAccess {
  /**
   * root: the lab's [data-lab] element; canvas: its canvas; api: its CSpaceLabApi; options:
   * {ui: 'full'|'minimal'} (a minimal lab, an embed, offers no lesson list, as its app does not).
   */
  constructor(root, canvas, api, options = {}) {
    this.root = root;
    this.canvas = canvas;
    this.api = api;
    this.options = options;
    this.id = 'lab-access-' + (CSpaceLabAccess.count = (CSpaceLabAccess.count || 0) + 1);
    this.seen = {};                 // what the DOM shows now, per part (to touch only changes)
    this.lastAnnounced = -Infinity;  // when the live region last changed (ms)
    this.pendingLine = null;         // a newer log line waiting for the rate limit
    this.announceTimer = 0;
    this.watchers = [];              // the late copies' (lab-*-access.js) show(status, page)
    this.build();
    this.timer = setInterval(() => this.poll(), CSpaceLabAccess.POLL_MS);
    this.poll();
  }

  el(tag, props = {}, parent = null) {
    const node = document.createElement(tag);
    for (const [k, v] of Object.entries(props)) {
      if (k === 'text') node.textContent = v;
      else if (k === 'className') node.className = v;
      else node.setAttribute(k, v);
    }
    if (parent) parent.appendChild(node);
    return node;
  }

  build() {
    const s = this.section = this.el('section', { className: 'lab-access', 'aria-labelledby': this.id + '-title' });
    this.title = this.el('h2', { id: this.id + '-title', text: 'C-Space Lab' }, s);
    if (this.options.ui !== 'minimal') {
      const nav = this.el('nav', { 'aria-label': 'Lessons' }, s);
      this.lessonList = this.el('ul', { className: 'lab-access-lessons' }, nav);
    }
    this.el('h3', { text: 'Parameters' }, s);
    this.params = this.el('div', { className: 'lab-access-params' }, s);
    this.stepHeading = this.el('h3', { text: 'Steps' }, s);
    this.steps = this.el('div', { className: 'lab-access-steps', role: 'group', 'aria-label': 'Step controls' }, s);
    this.stepButtons = {};
    for (const [key, label, call] of [
      ['back', 'Back', () => this.api.call('step_back', { background: true })],
      ['step', 'Step', () => this.api.step()],
      ['phase', 'Finish phase', () => this.api.call('finish_phase', { background: true })],
      ['run', 'Run all', () => this.api.call('run', { background: true })],
      ['play', 'Play', () => this.api.call('play', { on: !this.seen.playing })],
      ['reset', 'Reset', () => this.api.reset()],
    ]) {
      const b = this.stepButtons[key] = this.el('button', { type: 'button', text: label }, this.steps);
      // aria-disabled, not disabled: a focused button that became unavailable (Step at the end)
      // keeps the focus, so the panel stays open and the reader where it was.
      b.addEventListener('click', () => {
        if (b.getAttribute('aria-disabled') !== 'true') this.act(call);
      });
    }
    this.stepButtons.play.setAttribute('aria-pressed', 'false');  // a toggle: a reader says "pressed" while playing
    // The speed of Play, as the app's slider (1 to 5000 steps a second).
    const speedRow = this.el('div', { className: 'lab-access-param' }, this.steps);
    this.el('label', { for: this.id + '-speed', text: 'Play speed (steps per second)' }, speedRow);
    this.speed = this.el('input', { id: this.id + '-speed', type: 'number', min: '1', max: '5000', step: '1' }, speedRow);
    this.speed.addEventListener('change', () => this.act(() => this.api.call('play', { speed: Number(this.speed.value) })));
    this.el('h3', { text: 'What the view shows' }, s);
    this.description = this.el('p', { className: 'lab-access-description', role: 'region',
                                      'aria-label': 'Description of the view' }, s);
    this.el('h3', { text: 'Latest event' }, s);
    // Polite: read out after what the reader is saying; at most one a second (announce()).
    this.live = this.el('p', { className: 'lab-access-log', 'aria-live': 'polite', 'aria-atomic': 'true' }, s);
    this.buildDisplay(s);
    // After the canvas and the app's text proxy: the keyboard reaches it right after the canvas.
    this.root.appendChild(s);
  }

  // Display: the app's File > Display as two native selects (the page keeps the choice).
  buildDisplay(s) {
    this.el('h3', { text: 'Display' }, s);
    const group = this.el('div', { className: 'lab-access-display', role: 'group', 'aria-label': 'Display' }, s);
    this.display = {};
    for (const [key, label, options] of [
      ['scheme', 'Colours', [['system', 'like the system'], ['light', 'light'], ['dark', 'dark']]],
      ['contrast', 'Contrast', [['system', 'like the system'], ['normal', 'normal'], ['high', 'high']]],
    ]) {
      const row = this.el('div', { className: 'lab-access-param' }, group);
      const id = `${this.id}-${key}`;
      this.el('label', { for: id, text: label }, row);
      const select = this.display[key] = this.el('select', { id }, row);
      for (const [value, text] of options) this.el('option', { value, text }, select);
      select.addEventListener('change', () => this.act(() => {
        this.api.pageState({ [key]: select.value });
        const action = this.api.module && this.api.module.cslPageAction;
        if (typeof action === 'function') action('look');  // remembered, and the page follows
      }));
    }
  }

  showDisplay(state) {
    for (const key of ['scheme', 'contrast']) {
      const select = this.display[key];
      if (state[key] && select.value !== state[key] && document.activeElement !== select) select.value = state[key];
    }
  }

  act(call) {
    try {
      call();
    } catch (e) {
      this.announce(e.message);
    }
    this.poll();
  }

  stop() {
    clearInterval(this.timer);
    clearTimeout(this.announceTimer);
    this.section.remove();
  }

  poll() {
    if (document.hidden || !this.section.isConnected) return;
    let status, specs, text, log, page;
    try {
      status = this.api.status();
      specs = this.api.paramSpecs();
      text = this.api.describe();
      log = this.api.log();
      this.showDisplay(page = this.api.pageState());
    } catch {
      return;  // a lab that stopped: its shell shows why; the section keeps its last state
    }
    this.showPlace(status.layout || {});
    this.showLessons(status.lesson, (status.restrictions || {}).locked_lesson || null);
    this.showParams(status.lesson, specs);
    this.showSteps(status.stepping || { controls: false }, !!status.busy);
    if (text !== this.seen.text) this.description.textContent = this.seen.text = text;
    const newest = log.length ? log[log.length - 1] : null;
    const key = newest ? newest.step + '\u0000' + newest.text : '';
    if (key !== this.seen.log) {
      // First poll: where the lesson stands, not news. No line: '' (not stale).
      const first = this.seen.log === undefined;
      this.seen.log = key;
      if (!first) this.announce(newest?.text ?? '');
    }
    for (const show of this.watchers) {
      try {
        show(status, page);
      } catch (e) {
        console.warn('C-Space Lab:', e);  // one copy's fault: the others go on
      }
    }
  }

  // Shown, the section covers the app's side panel in the wide layout (whose controls it
  // repeats), not the views a step changes; elsewhere (narrow, the phone's tabs) the lab's bottom.
  showPlace(layout) {
    const views = layout.mode === 'wide' ? layout.views || [] : [];
    const side = views.length ? Math.floor(Math.min(...views.map((v) => v.x))) : 0;
    if (side === this.seen.side) return;
    this.seen.side = side;
    this.section.style.setProperty('--lab-side', side + 'px');
    this.section.classList.toggle('lab-access-side', side >= 280);
  }

  /** A late copy's show(status, page): called on each poll (one status a poll for all), and now. */
  watch(show) {
    this.watchers.push(show);
    try {
      show(this.api.status(), this.api.pageState());
    } catch { /* a lab that stopped: its shell shows why */ }
  }

  /** Text set only where it changed: a rewrite would move a screen reader's place in it. */
  static put(node, text) {
    if (node.textContent !== text) node.textContent = text;
  }

  /** Into a live region: emptied, then set, so that the same words twice are read twice. */
  static say(region, text) {
    region.textContent = '';
    setTimeout(() => { region.textContent = text; }, 50);
  }

  // Play: a line a second (the newest). A step: at once.
  announce(line) {
    this.pendingLine = line;
    if (this.announceTimer) return;
    const wait = this.seen.playing ? this.lastAnnounced + CSpaceLabAccess.ANNOUNCE_MS - performance.now() : 0;
    const say = () => {
      this.announceTimer = 0;
      this.lastAnnounced = performance.now();
      this.live.textContent = this.pendingLine;
      this.pendingLine = null;
    };
    if (wait <= 0) say();
    else this.announceTimer = setTimeout(say, wait);
  }

  // `locked`: the lesson the instructor keeps the lab on (lock=lesson), or null.
  showLessons(current, locked) {
    if (!this.lessons) {
      this.lessons = this.api.lessons();
      for (const l of this.lessonList ? this.lessons : []) {
        const b = this.el('button', { type: 'button', text: l.name, 'data-lesson': l.id },
                          this.el('li', {}, this.lessonList));
        b.addEventListener('click', () => this.act(() => this.api.selectLesson(l.id)));
      }
    }
    if (current === this.seen.lesson && locked === this.seen.lockedLesson) return;
    this.seen.lesson = current;
    this.seen.lockedLesson = locked;
    for (const b of this.lessonList ? this.lessonList.querySelectorAll('button') : []) {
      if (b.dataset.lesson === current) b.setAttribute('aria-current', 'true');
      else b.removeAttribute('aria-current');
      b.disabled = !!locked && b.dataset.lesson !== locked;
      b.title = b.disabled ? 'fixed by your instructor: this lab stays on its lesson' : '';
    }
    const info = this.lessons.find((l) => l.id === current);
    this.title.textContent = 'C-Space Lab: ' + (info ? info.name : current);
  }

  // ---- parameters ----------------------------------------------------------------------------

  showParams(lesson, specs) {
    const shape = lesson + '\u0000' + specs.map((p) => p.name + ':' + p.kind).join(',');
    if (shape !== this.seen.paramShape) {
      this.seen.paramShape = shape;
      this.params.textContent = '';
      this.controls = new Map();
      for (const spec of specs) this.controls.set(spec.name, this.makeControl(spec));
    }
    for (const spec of specs) {
      const c = this.controls.get(spec.name);
      c.spec = spec;
      // A control being typed into keeps what is typed until its change is sent.
      if (!c.typing) this.setValue(c, spec.value);
      // Fixed by the instructor (lock=): shown, not changeable, and said so beside it.
      if (c.input.disabled !== !!spec.locked) {
        c.input.disabled = !!spec.locked;
        c.fixed.textContent = spec.locked ? 'fixed by your instructor' : '';
      }
    }
  }

  makeControl(spec) {
    const id = `${this.id}-p-${spec.name}`;
    const row = this.el('div', { className: 'lab-access-param' }, this.params);
    // The unit, unless the label says it already ("samples n", not "samples n (samples)").
    const unit = spec.unit && !spec.label.includes(spec.unit) ? ` (${spec.unit})` : '';
    const label = this.el('label', { for: id, text: spec.label + unit }, row);
    let input;
    if (spec.kind === 'choice') {
      input = this.el('select', { id }, row);
      for (const c of spec.choices) this.el('option', { value: c, text: c }, input);
    } else {
      input = this.el('input', { id }, row);
      if (spec.kind === 'boolean') input.type = 'checkbox';
      else if (spec.kind === 'integer' || spec.kind === 'number') {
        input.type = 'number';
        if (spec.min !== null) input.min = spec.min;
        if (spec.max !== null) input.max = spec.max;
        input.step = spec.step !== null ? spec.step : 'any';
      } else {
        input.type = 'text';
        input.spellcheck = false;
      }
    }
    if (spec.kind === 'boolean') row.insertBefore(input, label);  // a checkbox before its label
    input.name = spec.name;
    const help = this.el('span', { id: id + '-help', className: 'lab-access-help', text: spec.help }, row);
    const fixed = this.el('span', { id: id + '-fixed', className: 'lab-access-fixed' }, row);
    const error = this.el('span', { id: id + '-error', className: 'lab-access-error' }, row);
    input.setAttribute('aria-describedby', `${spec.help ? help.id + ' ' : ''}${fixed.id} ${error.id}`);
    const control = { input, error, fixed, spec, row };
    input.addEventListener('input', () => { control.typing = true; });
    input.addEventListener('change', () => this.change(control));
    return control;
  }

  setValue(c, value) {
    if (c.spec.kind === 'boolean') c.input.checked = !!value;
    else if (Array.isArray(value)) c.input.value = value.join(', ');
    else c.input.value = String(value);
  }

  // The control's text as the JSON value set_params takes, or throws the reason.
  parse(c) {
    const { kind, list } = c.spec;
    const text = c.input.value.trim();
    const number = (t) => {
      if (!/^-?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(t)) throw new Error(`${c.spec.name}: "${t}" is not a number`);
      return Number(t);
    };
    if (kind === 'boolean') return c.input.checked;
    if (kind === 'choice') return c.input.value;
    if (kind === 'integer' || kind === 'number') return number(text);  // the app checks the range
    if (list) return text.split(',').map((t) => number(t.trim()));
    return c.input.value;
  }

  change(c) {
    c.typing = false;
    let message = '';
    try {
      this.api.setParams({ [c.spec.name]: this.parse(c) });
    } catch (e) {
      message = e.message;  // the app's refusal ("samples: an integer in [0, 20000] in the lab")
    }
    c.error.textContent = message;
    if (message) {
      c.input.setAttribute('aria-invalid', 'true');
      this.setValue(c, c.spec.value);  // the app kept its value: show it
    } else {
      c.input.removeAttribute('aria-invalid');
    }
    this.poll();
  }

  // ---- steps ---------------------------------------------------------------------------------

  showSteps(stepping, busy) {
    const key = [stepping.controls, stepping.steps, stepping.finished, busy, stepping.playing, stepping.speed].join();
    if (key === this.seen.steps) return;
    this.seen.steps = key;
    this.seen.playing = !!stepping.playing;
    this.steps.hidden = this.stepHeading.hidden = !stepping.controls;
    const b = this.stepButtons;
    const off = (button, yes) => button.setAttribute('aria-disabled', String(yes));
    off(b.back, busy || stepping.steps === 0);
    for (const button of [b.step, b.phase, b.run]) off(button, busy || stepping.finished);
    off(b.reset, busy);
    off(b.play, busy || (stepping.finished && !stepping.playing));
    b.play.setAttribute('aria-pressed', String(!!stepping.playing));
    if (typeof stepping.speed === 'number' && document.activeElement !== this.speed)
      this.speed.value = String(Math.round(stepping.speed));
  }
}

CSpaceLabAccess.POLL_MS = 200;
CSpaceLabAccess.ANNOUNCE_MS = 1000;

if (typeof window !== 'undefined') window.CSpaceLabAccess = CSpaceLabAccess;
