// The instructor's Author view: builds an assignment file (core/teaching/assignment.hpp) from
// homework exercises and the lab's own states, previews it as a student, and exports the file
// and its SCORM 1.2 and 2004 zips. Loaded by lab.js only when it is opened (author=1, or File >
// Author an assignment...), with lab-scorm-package.js, which builds the zips exactly as
// scripts/scorm-package.mjs does.
//
// A DOM dialog over the lab (real fields: the keyboard, a screen reader and the browser's own
// text editing work by construction). The rules stay core's: the draft is checked by the app's
// assignment_validate, the parser behind assignment_open and `cspacelab assignment validate`,
// and its messages (each naming the item and field) are shown as they are.
//
// The draft keeps every field as typed (numbers too, as text) in localStorage under
// cspacelab:v1:author:<page path>, on every keystroke: a bad value is reported, never dropped,
// and a reload finds it again. Only the file built from it has numbers.
'use strict';

(function (global) {
  const STORE_PREFIX = 'cspacelab:v1:author:';
  const NUMBER = /^-?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d{1,3})?$/;
  const CHECK_DELAY_MS = 250;
  const KINDS = { exercise: 'Exercise', explore: 'Explore', task: 'Task' };

  function el(tag, props = {}, children = []) {
    const node = document.createElement(tag);
    for (const [k, v] of Object.entries(props)) {
      if (k === 'text') node.textContent = v;
      else if (k === 'class') node.className = v;
      else if (k in node) node[k] = v;
      else node.setAttribute(k, v);
    }
    for (const c of children) node.appendChild(c);
    return node;
  }

  let uid = 0;
  const nextId = (what) => `lab-author-${what}-${++uid}`;

  /** A number field's text as the file has it: a number, left out when empty, else the text (core says why not). */
  function numberOf(text) {
    const t = String(text || '').trim();
    if (t === '') return undefined;
    return NUMBER.test(t) ? Number(t) : t;
  }

  /** An empty draft: every field a string, as typed. */
  function emptyDraft() {
    return { title: '', description: '', pass: '', seed_key: '', items: [] };
  }

  // A stored draft in the shape the dialog edits: another version's, or one edited by hand, had
  // a number for a title or an item of no kind, and the dialog ended in a TypeError. Text fields
  // become text, items of an unknown kind are dropped, and core names what is still wrong.
  function normalDraft(d) {
    const text = (v, or = '') => (typeof v === 'string' ? v : typeof v === 'number' ? String(v) : or);
    const out = emptyDraft();
    for (const k of Object.keys(out)) if (k !== 'items') out[k] = text(d[k]);
    const plain = (v) => v && typeof v === 'object' && !Array.isArray(v);
    out.items = d.items.filter((it) => plain(it) && ['exercise', 'explore', 'task'].includes(it.kind)).map((it) => {
      const item = { kind: it.kind, title: text(it.title), points: text(it.points, it.kind === 'explore' ? '0' : '1') };
      if (it.kind !== 'explore') item.tries = text(it.tries);
      if (it.kind === 'exercise') {
        Object.assign(item, { problem: text(it.problem, 'P1'), seedMode: it.seedMode === 'fixed' ? 'fixed' : 'learner',
                              seed: text(it.seed), tolerance: text(it.tolerance) });
      } else {
        Object.assign(item, { prompt: text(it.prompt), lesson: text(it.lesson, 'step-prm'),
                              scene: plain(it.scene) ? it.scene : null, params: plain(it.params) ? it.params : {} });
        // A check stored as an object (by hand) is kept, as the text the dialog edits.
        if (it.kind === 'task') item.check = plain(it.check) ? JSON.stringify(it.check) : text(it.check, '{"all": []}');
      }
      return item;
    });
    return out;
  }

  /** The scalar leaves of a state() object as [pointer, value] (for writing a task's check). */
  function leaves(value, pointer = '', out = []) {
    if (out.length >= 200) return out;
    if (value === null || typeof value !== 'object') {
      if (pointer) out.push([pointer, value]);
    } else if (Array.isArray(value)) {
      if (value.length <= 4) value.forEach((v, i) => leaves(v, pointer + '/' + i, out));
    } else {
      for (const [k, v] of Object.entries(value)) leaves(v, pointer + '/' + k.replace(/~/g, '~0').replace(/\//g, '~1'), out);
    }
    return out;
  }

  class CSpaceLabAuthor {
    constructor(root, api, { base, load }) {
      this.root = root;
      this.api = api;
      this.base = base;
      this.load = load;
      this.key = STORE_PREFIX + location.pathname;
      this.draft = this.readDraft();
      this.dialog = null;
      this.previewing = null;  // {snapshot, bar} while the draft is shown as a student sees it
      this.checkTimer = 0;
      this.result = { valid: false, errors: [] };
      this.ensureStyles();
    }

    // ---- the draft ------------------------------------------------------------------------

    readDraft() {
      try {
        const raw = localStorage.getItem(this.key);
        if (raw) {
          const d = JSON.parse(raw);
          if (d && typeof d === 'object' && Array.isArray(d.items)) return normalDraft(d);
        }
      } catch {
        // no storage (a private window) or not ours: start empty
      }
      return emptyDraft();
    }

    saveDraft() {
      try {
        localStorage.setItem(this.key, JSON.stringify(this.draft));
        this.storageNote = '';
      } catch {
        this.storageNote = 'The draft cannot be kept in this browser (storage is full or off): export it to keep it.';
      }
    }

    /** The assignment file the draft makes (format, version, the fields given; numbers as numbers where they are). */
    file() {
      const d = this.draft;
      const f = { format: 'cspacelab-assignment', version: 1, title: d.title };
      if (d.description.trim()) f.description = d.description;
      if (numberOf(d.pass) !== undefined) f.pass = numberOf(d.pass);
      if (d.seed_key.trim()) f.seed_key = d.seed_key;
      f.items = d.items.map((it) => {
        const o = { kind: it.kind };
        if (it.title.trim()) o.title = it.title;
        if (it.kind === 'exercise') {
          o.problem = it.problem;
          o.seed = it.seedMode === 'fixed' ? numberOf(it.seed) : 'learner';
          if (o.seed === undefined) o.seed = '';  // "fixed" with no number: core says what a seed is
        } else {
          o.prompt = it.prompt;
          o.lesson = it.lesson;
          if (it.scene) o.scene = it.scene;
          if (it.params && Object.keys(it.params).length) o.params = it.params;
        }
        if (numberOf(it.points) !== undefined) o.points = numberOf(it.points);
        if (it.kind === 'exercise' && numberOf(it.tolerance) !== undefined) o.tolerance = numberOf(it.tolerance);
        // Empty: any number of tries; anything else goes to core, which says what "tries" takes.
        if (it.kind !== 'explore' && numberOf(it.tries) !== undefined) o.tries = numberOf(it.tries);
        if (it.kind === 'task') {
          try {
            o.check = JSON.parse(it.check);
          } catch {
            o.check = it.check;  // core: "check: a condition object"; the syntax error is shown too
          }
        }
        return o;
      });
      return f;
    }

    /** The file's JSON text, as exported and packaged. */
    fileText() {
      return JSON.stringify(this.file(), null, 2) + '\n';
    }

    /** The draft checked by core: {valid, errors, assignment?, max_points?}, plus JSON syntax errors of checks. */
    check() {
      let r;
      try {
        r = this.api.call('assignment_validate', { assignment: this.file() });
      } catch (e) {
        r = { valid: false, errors: [e && e.message ? e.message : String(e)] };
      }
      const syntax = [];
      this.draft.items.forEach((it, i) => {
        if (it.kind !== 'task') return;
        try {
          JSON.parse(it.check);
        } catch (e) {
          syntax.push(`items[${i}]${it.title ? ` ("${it.title}")` : ''}: check: not JSON (${e.message})`);
        }
      });
      this.result = Object.assign({}, r, { errors: [...syntax, ...r.errors], valid: r.valid && !syntax.length });
      return this.result;
    }

    /** After any edit: keep the draft, re-check soon (typing stays fluent). */
    changed() {
      this.saveDraft();
      clearTimeout(this.checkTimer);
      this.checkTimer = setTimeout(() => this.showCheck(), CHECK_DELAY_MS);
    }

    // ---- items ------------------------------------------------------------------------------

    addExercise(problem) {
      this.draft.items.push({ kind: 'exercise', title: '', problem, seedMode: 'learner', seed: '', points: '1', tolerance: '', tries: '' });
      this.afterAdd();
    }

    /** An explore or task item holding the lab's current lesson, scene and parameters. */
    addFromLab(kind) {
      const s = this.api.snapshot();
      const item = { kind, title: '', prompt: '', lesson: s.lesson, scene: s.scene || null, params: s.params || {},
                     points: kind === 'task' ? '1' : '0' };
      if (kind === 'task') item.check = '{"all": []}';
      this.draft.items.push(item);
      this.afterAdd();
    }

    /** Replaces an item's lab state with the lab's current one. */
    retake(i) {
      const s = this.api.snapshot();
      Object.assign(this.draft.items[i], { lesson: s.lesson, scene: s.scene || null, params: s.params || {} });
      this.saveDraft();
      this.render(`[data-item="${i}"] .lab-author-retake`);
    }

    afterAdd() {
      this.saveDraft();
      const i = this.draft.items.length - 1;
      this.render(`[data-item="${i}"] input, [data-item="${i}"] select`);
    }

    move(i, by) {
      const items = this.draft.items;
      const j = i + by;
      if (j < 0 || j >= items.length) return;
      [items[i], items[j]] = [items[j], items[i]];
      this.saveDraft();
      // Focus stays with the moved item: on the same button, or the other one at an end.
      const end = by < 0 ? j === 0 : j === items.length - 1;
      this.render(`[data-item="${j}"] .lab-author-${(by < 0) !== end ? 'up' : 'down'}`);
    }

    remove(i) {
      this.draft.items.splice(i, 1);
      this.saveDraft();
      this.render(this.draft.items.length ? `[data-item="${Math.min(i, this.draft.items.length - 1)}"] .lab-author-remove` : '.lab-author-add button');
    }

    /** Appends a term to a task's check ({"all": [...]}, made so if it is another condition). */
    addTerm(i, pointer, op, valueText) {
      const it = this.draft.items[i];
      let cond;
      try {
        cond = JSON.parse(it.check);
      } catch {
        return 'The check is not JSON yet: fix it first (nothing was added).';
      }
      let value = valueText.trim();
      if (NUMBER.test(value)) value = Number(value);
      else if (value === 'true' || value === 'false') value = value === 'true';
      else if (op !== 'equals') return `"${valueText}" is not a number: at most and at least compare numbers.`;
      const term = op === 'equals' ? { pointer, equals: value } : op === 'max' ? { pointer, max: value } : { pointer, min: value };
      if (!cond || typeof cond !== 'object' || !Array.isArray(cond.all)) cond = { all: cond && Object.keys(cond).length ? [cond] : [] };
      cond.all.push(term);
      it.check = JSON.stringify(cond);
      this.saveDraft();
      return '';
    }

    // ---- the view ---------------------------------------------------------------------------

    ensureStyles() {
      if (document.querySelector('link[data-lab-author-css]')) return;
      document.head.appendChild(el('link', { rel: 'stylesheet', href: this.base + 'lab-author.css', 'data-lab-author-css': '' }));
    }

    open() {
      if (this.previewing) return;
      if (!this.dialog) this.render();
      this.dialog.hidden = false;
      const first = this.dialog.querySelector('input');
      if (first) first.focus();
    }

    close() {
      if (!this.dialog) return;
      this.dialog.hidden = true;
      const canvas = this.root.querySelector('canvas');
      if (canvas) canvas.focus({ preventScroll: true });
    }

    /** Builds the dialog again from the draft; focus goes to `focus` (a selector) if given. */
    render(focus) {
      const old = this.dialog;
      const titleId = nextId('title');
      const box = el('div', { class: 'lab-dialog-box lab-author-box' });
      box.appendChild(el('h2', { id: titleId, text: 'Author an assignment' }));
      box.appendChild(el('p', { text: 'Build an assignment from homework exercises and the lab as it is now. ' +
        'Close this view to set up the lab, then add an explore item or a task from it. The draft is kept in this browser.' }));
      box.appendChild(this.headFields());
      const list = el('ol', { class: 'lab-author-items', 'aria-label': 'Items' });
      this.draft.items.forEach((it, i) => list.appendChild(this.itemView(it, i)));
      box.appendChild(list);
      box.appendChild(this.addRow());
      this.summary = el('p', { class: 'lab-author-summary', role: 'status' });
      this.errorList = el('ul', { class: 'lab-author-errors', 'aria-live': 'polite', 'aria-label': 'Problems' });
      box.appendChild(this.summary);
      box.appendChild(this.errorList);
      this.note = el('p', { class: 'lab-dialog-note lab-author-note', role: 'status' });
      box.appendChild(this.note);
      box.appendChild(this.actionRow());

      const dialog = el('div', { class: 'lab-dialog lab-author', role: 'dialog' }, [box]);
      dialog.setAttribute('aria-modal', 'true');
      dialog.setAttribute('aria-labelledby', titleId);
      dialog.addEventListener('keydown', (e) => {
        e.stopPropagation();  // the lab's keyboard shortcuts are not for these fields
        if (e.key === 'Escape') {
          e.preventDefault();
          this.close();
        } else if (e.key === 'Tab') {  // modal: Tab cycles within the dialog
          const items = Array.from(dialog.querySelectorAll('button, textarea, input, select')).filter((n) => !n.disabled);
          const at = items.indexOf(document.activeElement);
          if (e.shiftKey && at <= 0) {
            e.preventDefault();
            items[items.length - 1].focus();
          } else if (!e.shiftKey && at === items.length - 1) {
            e.preventDefault();
            items[0].focus();
          }
        }
      });
      if (old) {
        dialog.hidden = old.hidden;
        old.replaceWith(dialog);
      } else {
        this.root.appendChild(dialog);
      }
      this.dialog = dialog;
      this.showCheck();
      if (focus) {
        const target = dialog.querySelector(focus);
        if (target) target.focus();
      }
    }

    /** A labelled field bound to draft[key] (every keystroke kept). */
    field(label, obj, key, { multiline = false, hint = '', cls = '' } = {}) {
      const id = nextId('field');
      const input = multiline ? el('textarea', { id, rows: 3 }) : el('input', { id, type: 'text', spellcheck: false });
      input.value = obj[key] == null ? '' : String(obj[key]);
      input.dataset.field = key;
      input.addEventListener('input', () => {
        obj[key] = input.value;
        this.changed();
      });
      const wrap = el('div', { class: 'lab-author-field ' + cls }, [el('label', { for: id, text: label }), input]);
      if (hint) {
        const h = el('span', { class: 'lab-author-hint', id: id + '-hint', text: hint });
        input.setAttribute('aria-describedby', h.id);
        wrap.appendChild(h);
      }
      return wrap;
    }

    headFields() {
      const d = this.draft;
      return el('fieldset', { class: 'lab-author-head' }, [
        el('legend', { text: 'Assignment' }),
        this.field('Title', d, 'title', { cls: 'lab-author-wide' }),
        this.field('Description (optional)', d, 'description', { multiline: true, cls: 'lab-author-wide' }),
        this.field('Pass mark', d, 'pass', { hint: 'the scaled score that passes, 0 to 1 (default 0.6)' }),
        this.field('Seed key (optional)', d, 'seed_key', { hint: 'per-learner numbers derive from it; keep it when you edit the title' }),
      ]);
    }

    itemView(it, i) {
      const li = el('li', { class: 'lab-author-item' });
      li.dataset.item = String(i);
      const headId = nextId('item');
      const what = it.kind === 'exercise' ? `${KINDS.exercise} ${it.problem}` : `${KINDS[it.kind]}: ${it.lesson}`;
      li.appendChild(el('h3', { id: headId, text: `Item ${i + 1}: ${what}` }));
      li.setAttribute('aria-labelledby', headId);
      const fields = el('div', { class: 'lab-author-fields' });
      fields.appendChild(this.field('Title' + (it.kind === 'exercise' ? ' (optional)' : ''), it, 'title', { cls: 'lab-author-wide' }));
      if (it.kind !== 'exercise') fields.appendChild(this.field('Prompt', it, 'prompt', { multiline: true, cls: 'lab-author-wide' }));
      fields.appendChild(this.field('Points', it, 'points', { hint: '0 to 1000' }));
      if (it.kind !== 'explore')
        fields.appendChild(this.field('Tries (optional)', it, 'tries', { hint: 'checks a student may make, 1 to 100; empty: any number' }));
      if (it.kind === 'exercise') {
        const id = nextId('seed');
        const mode = el('select', { id });
        mode.appendChild(el('option', { value: 'learner', text: 'each learner their own' }));
        mode.appendChild(el('option', { value: 'fixed', text: 'fixed (everyone the same)' }));
        mode.value = it.seedMode;
        mode.dataset.field = 'seedMode';
        fields.appendChild(el('div', { class: 'lab-author-field' }, [el('label', { for: id, text: 'Numbers' }), mode]));
        const seed = this.field('Seed', it, 'seed', { hint: 'a whole number, for fixed numbers' });
        seed.hidden = it.seedMode !== 'fixed';
        mode.addEventListener('change', () => {
          it.seedMode = mode.value;
          seed.hidden = it.seedMode !== 'fixed';
          this.changed();
        });
        fields.appendChild(seed);
        fields.appendChild(this.field('Tolerance (optional)', it, 'tolerance', { hint: 'accepted error, numeric answers (P8-P13) only' }));
      } else {
        const n = Object.keys(it.params || {}).length;
        fields.appendChild(el('p', { class: 'lab-author-state', text: `Lab state: lesson ${it.lesson}, ${it.scene ? 'its scene' : 'the lesson\'s scene'}, ${n} parameter${n === 1 ? '' : 's'}.` }));
      }
      if (it.kind === 'task') {
        fields.appendChild(this.field('Check (a condition on the lesson\'s state, JSON)', it, 'check', {
          multiline: true, cls: 'lab-author-wide lab-author-check',
          hint: '{"pointer": "/solved", "equals": true}, {"pointer": "/params/samples", "max": 50}, {"all": [...]}, {"any": [...]}' }));
        fields.appendChild(this.termBuilder(it, i));
      }
      li.appendChild(fields);
      const buttons = [
        ['Move up', 'lab-author-up', () => this.move(i, -1), i === 0],
        ['Move down', 'lab-author-down', () => this.move(i, 1), i === this.draft.items.length - 1],
        ['Remove', 'lab-author-remove', () => this.remove(i), false],
      ];
      if (it.kind !== 'exercise') buttons.unshift(['Take the lab\'s state now', 'lab-author-retake', () => this.retake(i), false]);
      const row = el('div', { class: 'lab-dialog-row lab-author-item-actions' });
      for (const [label, cls, fn, disabled] of buttons) {
        const b = el('button', { type: 'button', text: label, class: cls, disabled });
        b.setAttribute('aria-label', `${label}: item ${i + 1}`);
        b.addEventListener('click', fn);
        row.appendChild(b);
      }
      li.appendChild(row);
      li.appendChild(el('ul', { class: 'lab-author-item-errors', 'aria-label': `Problems of item ${i + 1}` }));
      return li;
    }

    /** Writing a check from the lab's state: a field of state() now, a comparison, a value. */
    termBuilder(it, i) {
      const box = el('div', { class: 'lab-author-terms lab-author-wide' });
      let state = null;
      try {
        state = this.api.state();
      } catch {
        // a lesson still working: the list is empty, the JSON can still be typed
      }
      const sameLesson = state && this.api.snapshot().lesson === it.lesson;
      const pid = nextId('pointer');
      const pointer = el('select', { id: pid });
      for (const [p, v] of sameLesson ? leaves(state) : []) pointer.appendChild(el('option', { value: p, text: `${p} (now ${JSON.stringify(v)})` }));
      const oid = nextId('op');
      const op = el('select', { id: oid });
      for (const [v, t] of [['equals', 'equals'], ['max', 'at most'], ['min', 'at least']]) op.appendChild(el('option', { value: v, text: t }));
      const vid = nextId('value');
      const value = el('input', { id: vid, type: 'text', spellcheck: false });
      const add = el('button', { type: 'button', text: 'Add to the check', class: 'lab-author-add-term', disabled: !sameLesson });
      const note = el('span', { class: 'lab-author-hint', role: 'status',
        text: sameLesson ? 'Adds one condition on the lab\'s state to the check (all must hold).'
          : `Show lesson ${it.lesson} in the lab to pick a field of its state.` });
      add.addEventListener('click', () => {
        const problem = this.addTerm(i, pointer.value, op.value, value.value);
        if (problem) {
          note.textContent = problem;
          return;
        }
        this.render(`[data-item="${i}"] .lab-author-add-term`);
      });
      box.append(
        el('div', { class: 'lab-author-field' }, [el('label', { for: pid, text: 'Field of the state' }), pointer]),
        el('div', { class: 'lab-author-field' }, [el('label', { for: oid, text: 'Is' }), op]),
        el('div', { class: 'lab-author-field' }, [el('label', { for: vid, text: 'Value' }), value]),
        el('div', { class: 'lab-dialog-row' }, [add]), note);
      return box;
    }

    addRow() {
      const row = el('fieldset', { class: 'lab-author-add' }, [el('legend', { text: 'Add an item' })]);
      const id = nextId('problem');
      const pick = el('select', { id });
      let problems = [];
      try {
        problems = this.api.homework();
      } catch {
        // the list is the app's; without it, P1 to P13 by number
      }
      if (!problems.length) for (let n = 1; n <= 13; ++n) problems.push({ id: 'P' + n, title: '' });
      for (const p of problems) pick.appendChild(el('option', { value: p.id, text: p.title ? `${p.id}: ${p.title}` : p.id }));
      const ex = el('button', { type: 'button', text: 'Add exercise' });
      ex.addEventListener('click', () => this.addExercise(pick.value));
      const explore = el('button', { type: 'button', text: 'Add explore item (the lab now)' });
      explore.addEventListener('click', () => this.addFromLab('explore'));
      const task = el('button', { type: 'button', text: 'Add task (the lab now)' });
      task.addEventListener('click', () => this.addFromLab('task'));
      row.append(el('div', { class: 'lab-author-field' }, [el('label', { for: id, text: 'Homework problem' }), pick]),
                 el('div', { class: 'lab-dialog-row' }, [ex, explore, task]));
      return row;
    }

    actionRow() {
      const row = el('div', { class: 'lab-dialog-row lab-dialog-actions lab-author-actions' });
      const actions = [
        ['Preview as a student', () => this.preview(), true],
        ['Export JSON', () => this.exportJson()],
        ['Export SCORM 1.2', () => this.exportScorm('1.2')],
        ['Export SCORM 2004', () => this.exportScorm('2004')],
        ['Start over', () => this.clear()],
        ['Close', () => this.close()],
      ];
      for (const [label, fn, primary] of actions) {
        const b = el('button', { type: 'button', text: label, class: primary ? 'lab-dialog-primary' : '' });
        b.addEventListener('click', async () => {
          try {
            await fn();
          } catch (e) {
            this.say(`${label}: ${e && e.message ? e.message : e}`, true);
          }
        });
        row.appendChild(b);
      }
      return row;
    }

    say(text, error = false) {
      if (!this.note) return;
      this.note.textContent = text;
      this.note.classList.toggle('lab-dialog-error', error);
    }

    /** Shows core's verdict: every problem in the list, and each item's under the item. */
    showCheck() {
      if (!this.dialog) return;
      const r = this.check();
      this.errorList.textContent = '';
      for (const ul of this.dialog.querySelectorAll('.lab-author-item-errors')) ul.textContent = '';
      for (const e of r.errors) {
        this.errorList.appendChild(el('li', { text: e }));
        const m = /^items\[(\d+)\]/.exec(e);
        const ul = m && this.dialog.querySelector(`[data-item="${m[1]}"] .lab-author-item-errors`);
        if (ul) ul.appendChild(el('li', { text: e }));
      }
      const n = this.draft.items.length;
      this.summary.textContent = r.valid
        ? `Valid: ${n} item${n === 1 ? '' : 's'}, ${r.max_points} point${r.max_points === 1 ? '' : 's'} in all.`
        : `Not valid yet: ${r.errors.length} problem${r.errors.length === 1 ? '' : 's'}.`;
      this.summary.classList.toggle('lab-dialog-error', !r.valid);
      if (this.storageNote) this.say(this.storageNote, true);
    }

    /** The checked file, or throws with core's first problems. */
    valid() {
      const r = this.check();
      this.showCheck();
      if (!r.valid) throw new Error(`the assignment is not valid: ${r.errors.slice(0, 3).join('; ')}${r.errors.length > 3 ? '; …' : ''}`);
      return r;
    }

    /** The file's name, from the title: letters, digits and '-' ("week-3-c-spaces"). */
    baseName() {
      const s = this.draft.title.toLowerCase().replace(/[^a-z0-9]+/g, '-').replace(/^-+|-+$/g, '').slice(0, 60);
      return s || 'assignment';
    }

    download(name, blob) {
      const url = URL.createObjectURL(blob);
      const a = el('a', { href: url, download: name });
      a.hidden = true;
      this.root.appendChild(a);
      a.click();
      a.remove();
      setTimeout(() => URL.revokeObjectURL(url), 60000);
    }

    exportJson() {
      this.valid();
      const name = this.baseName() + '.json';
      this.download(name, new Blob([this.fileText()], { type: 'application/json' }));
      this.say(`Exported ${name}.`);
    }

    /** The SCORM zip for `version`, built here from the site this page came from. */
    async exportScorm(version) {
      const checked = this.valid().assignment;
      const P = global.CSpaceLabScormPackage;
      this.say(`Building the SCORM ${version} package…`);
      const get = async (file) => {
        const r = await fetch(new URL(file, this.base).href, { cache: 'no-cache' });
        if (!r.ok) throw new Error(`${file}: the site answered ${r.status}`);
        return new Uint8Array(await r.arrayBuffer());
      };
      const list = JSON.parse(new TextDecoder().decode(await get(P.SITE_LIST)));
      if (!list || !Array.isArray(list.files)) throw new Error(`${P.SITE_LIST} is not the site's file list`);
      const site = [];
      for (const name of list.files) site.push({ name, data: await get(name) });
      const indexHtml = new TextDecoder().decode(await get('index.html'));
      const name = this.baseName();
      const entries = P.packageEntries({ version, checked, name, assignmentBytes: new TextEncoder().encode(this.fileText()), indexHtml, site });
      const deflate = async (data) => {
        const stream = new Blob([data]).stream().pipeThrough(new CompressionStream('deflate-raw'));
        return new Uint8Array(await new Response(stream).arrayBuffer());
      };
      const zip = await P.writeZip(entries, deflate);
      const file = P.zipName(name, version);
      this.download(file, new Blob([zip], { type: 'application/zip' }));
      this.say(`Exported ${file} (${entries.length} files, ${Math.round(zip.length / 1024)} KB).`);
    }

    clear() {
      if (this.draft.items.length || this.draft.title) {
        // One more chance: the draft goes to a file first only if asked; a confirm is plain and reachable.
        if (!global.confirm('Start over? The draft (title, items) is deleted from this browser.')) return;
      }
      this.draft = emptyDraft();
      this.saveDraft();
      this.render('input');
      this.say('Started a new draft.');
    }

    // ---- preview ----------------------------------------------------------------------------

    /** The draft in assignment mode, as a student sees it; the lab and the draft come back after. */
    async preview() {
      const r = this.valid();
      let open = true;
      try {
        this.api.call('assignment_state');
      } catch {
        open = false;
      }
      if (open) throw new Error('an assignment is open in this lab: preview in a lab without one');
      if (this.root.cspacelabAccess && typeof global.CSpaceLabAssignmentAccess === 'undefined') {
        await this.load('lab-assignment-access.js');
        global.CSpaceLabAssignmentAccess(this.root.cspacelabAccess);
      }
      const snapshot = this.api.snapshot();
      this.api.call('assignment_open', { assignment: r.assignment, learner: 'preview' });
      this.dialog.hidden = true;
      const back = el('button', { type: 'button', text: 'Back to the draft', class: 'lab-dialog-primary' });
      const bar = el('div', { class: 'lab-author-preview', role: 'region', 'aria-label': 'Preview' }, [
        el('span', { text: 'Previewing as a student (learner "preview"): nothing is recorded.' }), back]);
      back.addEventListener('click', () => this.endPreview());
      this.root.appendChild(bar);
      this.previewing = { snapshot, bar };
      back.focus();
    }

    endPreview() {
      if (!this.previewing) return;
      const { snapshot, bar } = this.previewing;
      this.previewing = null;
      bar.remove();
      try {
        this.api.call('assignment_close');
        this.api.restore(snapshot);
      } catch (e) {
        this.say(`The lab could not go back to how it was: ${e && e.message ? e.message : e}`, true);
      }
      this.open();
    }
  }

  global.CSpaceLabAuthor = CSpaceLabAuthor;
})(window);
