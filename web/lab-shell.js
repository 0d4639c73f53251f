// The page around one C-Space Lab instance: what a link or a page's data-lab attribute asks
// for, autosave to localStorage (with a "previous work" slot that nothing overwrites silently),
// Share and Embed dialogs, import and export, and the input rules of an embed (the wheel
// scrolls the page until the lab has focus; a click gives it focus).
//
// Everything the user or a link supplies is handled as data: parsed with JSON.parse or the
// strict parsers of lab-url.js, shown with textContent or as an <textarea>'s value, passed to the
// app as JSON. Problems become the app's one-line notice; nothing is ever written as HTML.
'use strict';

(function (global) {
  const U = global.CSpaceLabUrl;
  const STORAGE_PREFIX = 'cspacelab:v1:';
  const WORK_FORMAT = 'cspacelab-work';
  const MAX_IMPORT_BYTES = 2 * 1024 * 1024;
  const AUTOSAVE_POLL_MS = 600;
  const AUTOSAVE_QUIET_MS = 1000;   // save once nothing changed for this long...
  const AUTOSAVE_MAX_WAIT_MS = 4000; // ...or at least this often while things keep changing

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

  function sameJson(a, b) {
    return JSON.stringify(a) === JSON.stringify(b);
  }

  function slug(text) {
    return String(text).toLowerCase().replace(/[^a-z0-9]+/g, '-').replace(/^-|-$/g, '').slice(0, 40) || 'scene';
  }

  function escapeAttribute(text) {
    return String(text).replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
  }

  /** localStorage, or null where the page may not use it (sandboxed iframes, privacy modes). */
  function openStorage() {
    try {
      const s = global.localStorage;
      const probe = STORAGE_PREFIX + 'probe';
      s.setItem(probe, '1');
      s.removeItem(probe);
      return s;
    } catch {
      return null;
    }
  }

  class LabShell {
    /**
     * root: the [data-lab] element; canvas: its canvas; api: its CSpaceLabApi.
     * options: {config: query string, ui: 'full'|'minimal', storageId, scope, home: URL of the
     * full lab (share links), base: URL of the folder with the lab's files, single: bool
     * (the single-file build), guardWheel: bool (the wheel scrolls the page until focused)}
     */
    constructor(root, canvas, api, options) {
      this.root = root;
      this.canvas = canvas;
      this.api = api;
      this.options = options;
      this.storage = openStorage();
      this.lastSaved = null;
      this.dirtySince = 0;
      this.changedAt = 0;
      this.pendingCaptures = [];
      this.dialog = null;
      this.timing = { ready: performance.now(), firstFrame: null };
      this.problems = [];
    }

    // ---- start ------------------------------------------------------------------------------

    async init() {
      const api = this.api;
      this.lessons = api.lessons();
      this.bundled = api.bundledScenes();
      this.installFrameHook();
      this.installInput();
      api.pageState({ attached: true, minimal: this.options.ui === 'minimal' });
      api.module.cslPageAction = (name) => setTimeout(() => this.action(name), 0);

      const parsed = U.parseConfig(this.options.config);
      const notices = parsed.problems.slice();
      const configKey = U.hasState(parsed.values) ? U.stateKey(parsed.values) : null;
      const saved = this.readSlot('work', notices);
      if (saved) notices.push(...this.restoreWork(saved).map((p) => 'saved work: ' + p));

      let opened = false;
      if (configKey && !(saved && saved.config === configKey)) {
        // A link (or a page's data-lab) not seen before: its state, over what was saved. If that
        // replaces work of the same lesson, the work goes to the "previous work" slot first.
        const before = this.captureWork();
        notices.push(...(await this.applyConfig(parsed.values)));
        const after = this.captureWork();
        const lesson = after.current;
        if (saved && before.lessons[lesson] && !sameJson(before.lessons[lesson], after.lessons[lesson])) {
          this.writeSlot('previous', Object.assign(before, { savedAt: Date.now() }));
          opened = true;
        }
      }
      this.config = configKey;
      this.updatePreviousLabel();
      this.saveNow();

      if (notices.length) {
        api.notify('Not used from the link: ' + notices.join('; ') + '. The lesson\'s defaults stand in for these.', 15);
      } else if (opened) {
        api.notify('Opened the link. Your previous work is kept: "Restore my previous work" brings it back.', 10);
      }
      if (!this.storage) api.notify('Autosave is off: this page may not use the browser\'s storage.', 8);
      this.problems = notices;
      this.startAutosave();
    }

    lessonName(id) {
      const l = this.lessons.find((x) => x.id === id);
      return l ? l.name : id;
    }

    /** Applies a link's values over a fresh lesson, part by part; returns the problems. */
    async applyConfig(values) {
      const api = this.api;
      const problems = [];
      let lesson = this.lessons[0].id;  // the app's first lesson, as on a fresh start
      if (values.has('lesson')) {
        const raw = values.get('lesson');
        if (U.NAME.test(raw) && this.lessons.some((l) => l.id === raw)) lesson = raw;
        else problems.push(`lesson ${U.excerpt(raw)} (there is no such lesson)`);
      }
      let scene = null;
      if (values.has('scene')) {
        const raw = values.get('scene');
        if (U.NAME.test(raw) && Object.prototype.hasOwnProperty.call(this.bundled, raw)) {
          scene = this.bundled[raw];
        } else if (U.NAME.test(raw)) {
          problems.push(`scene ${U.excerpt(raw)} (no bundled scene has that name; there are ${Object.keys(this.bundled).join(', ')})`);
        } else {
          try {
            scene = await U.decodeScene(raw);
          } catch (e) {
            problems.push('scene: ' + e.message);
          }
        }
      }
      try {
        api.restore(scene ? { lesson, scene } : { lesson });
      } catch (e) {
        problems.push('scene: ' + e.message);
        api.restore({ lesson });
      }
      const template = api.snapshot().params || {};
      for (const [key, raw] of values) {
        if (U.RESERVED.has(key)) continue;
        if (!Object.prototype.hasOwnProperty.call(template, key)) {
          problems.push(`${key} (not a parameter of ${this.lessonName(lesson)})`);
          continue;
        }
        try {
          api.setParams({ [key]: U.parseValue(raw, template[key]) });
        } catch (e) {
          problems.push(`${key} ${U.excerpt(raw)} (${e.message})`);
        }
      }
      if (values.has('steps')) {
        const raw = values.get('steps');
        if (U.STEPS.test(raw)) api.runTo(Number(raw));
        else problems.push(`steps ${U.excerpt(raw)} (not a whole number of steps)`);
      }
      if (values.has('ui') && !['full', 'minimal'].includes(values.get('ui')))
        problems.push(`ui ${U.excerpt(values.get('ui'))} (full or minimal)`);
      if (values.has('id') && !U.ID.test(values.get('id')))
        problems.push(`id ${U.excerpt(values.get('id'))} (letters, digits, - and _)`);
      return problems;
    }

    // ---- storage ----------------------------------------------------------------------------

    key(slot) {
      return STORAGE_PREFIX + this.options.scope + ':' + this.options.storageId + ':' + slot;
    }

    readSlot(slot, problems = []) {
      if (!this.storage) return null;
      let text;
      try {
        text = this.storage.getItem(this.key(slot));
      } catch {
        return null;
      }
      if (text === null) return null;
      try {
        const record = JSON.parse(text);
        if (record && record.format === WORK_FORMAT && record.version === 1 && typeof record.current === 'string' &&
            record.lessons && typeof record.lessons === 'object' && !Array.isArray(record.lessons))
          return record;
      } catch {
        // fall through
      }
      problems.push(`the ${slot === 'work' ? 'saved work' : 'previous work'} in this browser could not be read`);
      return null;
    }

    writeSlot(slot, record) {
      if (!this.storage) return false;
      try {
        this.storage.setItem(this.key(slot), JSON.stringify(record));
        return true;
      } catch {
        if (!this.warnedQuota) this.api.notify('Autosave failed: the browser\'s storage for this site is full.', 8);
        this.warnedQuota = true;
        return false;
      }
    }

    /** {format, version, config, current, lessons: {id: snapshot}} of every open lesson. */
    captureWork() {
      const lessons = {};
      for (const l of this.api.lessons()) if (l.open) lessons[l.id] = this.api.snapshot(l.id);
      return { format: WORK_FORMAT, version: 1, config: this.config === undefined ? null : this.config,
               current: this.api.status().lesson, lessons };
    }

    /** Restores a work record lesson by lesson; returns the problems (those lessons stay as they are). */
    restoreWork(record) {
      const problems = [];
      const known = new Set(this.lessons.map((l) => l.id));
      for (const [id, snapshot] of Object.entries(record.lessons).slice(0, 64)) {
        if (!known.has(id)) continue;  // a lesson this version does not have
        if (!snapshot || typeof snapshot !== 'object') continue;
        try {
          this.api.restore(Object.assign({}, snapshot, { lesson: id }));
        } catch (e) {
          problems.push(`${this.lessonName(id)}: ${e.message}`);
          // Parameters a newer version names differently must not cost the scene: keep what fits.
          try {
            if (snapshot.scene) this.api.restore({ lesson: id, scene: snapshot.scene });
          } catch {
            // the scene itself is bad: the lesson stays as it was
          }
        }
      }
      if (known.has(record.current)) this.api.selectLesson(record.current);
      return problems;
    }

    workText(record) {
      return JSON.stringify({ config: record.config, current: record.current, lessons: record.lessons });
    }

    saveNow() {
      const work = this.captureWork();
      const text = this.workText(work);
      if (text === this.lastSaved) return;
      if (this.writeSlot('work', Object.assign(work, { savedAt: Date.now() }))) this.lastSaved = text;
      this.dirtySince = 0;
    }

    startAutosave() {
      const poll = () => {
        let text;
        try {
          text = this.workText(this.captureWork());
        } catch {
          return;  // the app stopped (an abort is shown by the loader)
        }
        const now = Date.now();
        if (text === this.lastSaved) {
          this.dirtySince = 0;
          return;
        }
        if (text !== this.pendingText) {
          this.pendingText = text;
          this.changedAt = now;
        }
        if (!this.dirtySince) this.dirtySince = now;
        if (now - this.changedAt >= AUTOSAVE_QUIET_MS || now - this.dirtySince >= AUTOSAVE_MAX_WAIT_MS) this.saveNow();
      };
      this.autosaveTimer = setInterval(poll, AUTOSAVE_POLL_MS);
      // Leaving or hiding the page saves at once: a reload right after an edit keeps it.
      global.addEventListener('pagehide', () => this.saveNow());
      document.addEventListener('visibilitychange', () => {
        if (document.visibilityState === 'hidden') this.saveNow();
      });
    }

    updatePreviousLabel() {
      const previous = this.readSlot('previous');
      const label = previous ? 'your work of ' + new Date(previous.savedAt || 0).toLocaleString() : '';
      this.api.pageState({ previous: label });
      return previous;
    }

    // ---- actions (the app's buttons) --------------------------------------------------------

    async action(name) {
      try {
        switch (name) {
          case 'share': return await this.share();
          case 'embed': return await this.embed();
          case 'import': return this.pickFile();
          case 'export-scene': return this.exportScene();
          case 'export-png': return await this.exportPng();
          case 'export-state': return this.exportState();
          case 'reset': return this.resetLesson();
          case 'restore-previous': return this.restorePrevious();
          case 'open-full': return await this.openFull();
          default: return undefined;
        }
      } catch (e) {
        this.api.notify(`${name}: ${e && e.message ? e.message : e}`, 8);
        return undefined;
      }
    }

    /** The link that reproduces what is on screen: {url, problems}. */
    async shareLink(extra = {}, home = this.options.home) {
      const { query, problems } = await U.buildQuery(this.api.snapshot(), this.bundled, extra);
      return { url: home + '?' + query, query, problems };
    }

    async share() {
      const { url, problems } = await this.shareLink();
      const copied = await this.copy(url);
      const lines = [];
      if (copied) lines.push('The link is on the clipboard. It opens this lesson with this scene, these parameters and seed, at this step.');
      else lines.push('Copy the link below (the browser did not let the page use the clipboard).');
      if (problems.length) lines.push('Not exact: ' + problems.join('; ') + '. Export the scene as JSON to pass it on whole.');
      this.showDialog('Share this state', lines, [{ label: 'Link', value: url, rows: 3 }]);
      this.api.notify(copied ? 'Link copied to the clipboard.' : 'Copy the link from the dialog.', 4);
      return url;
    }

    async embed() {
      const label = this.lessonName(this.api.status().lesson);
      const { query } = await U.buildQuery(this.api.snapshot(), this.bundled);
      const id = 'lab-' + U.hash(query + Date.now()).slice(0, 6);
      let fields;
      if (this.options.single) {
        const file = location.pathname.split('/').pop() || 'cspacelab-single.html';
        fields = [{ label: 'Upload this file next to your page, then put this where the lab goes', rows: 3,
                    value: `<iframe src="${escapeAttribute(file + '?' + query + '&ui=minimal&id=' + id)}" width="100%" height="600" ` +
                           `style="border:0" title="C-Space Lab: ${escapeAttribute(label)}" allow="clipboard-write"></iframe>` }];
      } else {
        const base = this.options.base;
        fields = [
          { label: 'An iframe (works in any page and most LMSs)', rows: 3,
            value: `<iframe src="${escapeAttribute(base + 'embed.html?' + query + '&id=' + id)}" width="100%" height="600" ` +
                   `style="border:0" title="C-Space Lab: ${escapeAttribute(label)}" allow="clipboard-write"></iframe>` },
          { label: 'Or a script tag (several labs on one page, each in its own element)', rows: 4,
            value: `<div id="${id}" data-lab="${escapeAttribute(query + '&ui=minimal')}" style="height:600px"></div>\n` +
                   `<script src="${escapeAttribute(base + 'lab.js')}" defer></script>` },
        ];
      }
      this.showDialog('Embed this lab', ['This lab as it is now, for a course page. The embed keeps each student\'s own work in their browser.'], fields);
      return fields;
    }

    pickFile() {
      if (!this.fileInput) {
        this.fileInput = el('input', { type: 'file', accept: '.json,application/json', hidden: true, class: 'lab-file' });
        this.fileInput.addEventListener('change', () => {
          const file = this.fileInput.files && this.fileInput.files[0];
          this.fileInput.value = '';
          if (file) this.importFile(file);
        });
        this.root.appendChild(this.fileInput);
      }
      this.fileInput.click();
    }

    /** Loads a scene file (or an exported state holding one) into the current lesson; a bad file changes nothing. */
    async importFile(file) {
      const name = U.excerpt(file.name || 'the file', 40);
      const fail = (why) => {
        this.api.notify(`Import: ${name} ${why}. Nothing changed.`, 10);
        return false;
      };
      if (file.size > MAX_IMPORT_BYTES) return fail(`is ${U.sizeText(file.size)}; a scene file is at most ${U.sizeText(MAX_IMPORT_BYTES)}`);
      let value;
      try {
        value = JSON.parse(await file.text());
      } catch {
        return fail('is not JSON');
      }
      if (value && typeof value === 'object' && !Array.isArray(value) && typeof value.format === 'string' &&
          value.format.startsWith('cspacelab-') && value.scene && typeof value.scene === 'object')
        value = value.scene;  // an exported roadmap/state file: its scene
      if (!value || typeof value !== 'object' || Array.isArray(value)) return fail('is not a scene (a JSON object)');
      try {
        this.api.setScene(value);
      } catch (e) {
        return fail(`is not a scene this lesson can use: ${e.message}`);
      }
      this.api.notify(`Imported ${name}.`, 4);
      this.saveNow();
      return true;
    }

    download(name, blob) {
      const url = URL.createObjectURL(blob);
      const a = el('a', { href: url, download: name, rel: 'noopener', hidden: true });
      this.root.appendChild(a);
      a.click();
      a.remove();
      setTimeout(() => URL.revokeObjectURL(url), 30000);
    }

    downloadJson(name, value) {
      this.download(name, new Blob([JSON.stringify(value, null, 2) + '\n'], { type: 'application/json' }));
    }

    exportScene() {
      const scene = this.api.getScene();
      this.downloadJson(`${slug(scene.name || this.api.status().lesson)}.json`, scene);
    }

    exportState() {
      const snapshot = this.api.snapshot();
      const state = this.api.state({ roadmap: true });
      const roadmap = state.vertices !== undefined;
      this.downloadJson(`cspacelab-${snapshot.lesson}-${roadmap ? 'roadmap' : 'state'}-step${snapshot.steps}.json`, {
        format: roadmap ? 'cspacelab-roadmap' : 'cspacelab-state',
        version: 1,
        lesson: snapshot.lesson,
        params: snapshot.params,
        steps: snapshot.steps,
        scene: snapshot.scene,
        state,
      });
    }

    /** A PNG of the lesson's main view (or the whole canvas), read right after a frame is drawn. */
    capturePng() {
      return new Promise((resolve, reject) => this.pendingCaptures.push({ resolve, reject }));
    }

    async exportPng() {
      const blob = await this.capturePng();
      this.download(`cspacelab-${this.api.status().lesson}-step${this.api.snapshot().steps}.png`, blob);
      return blob;
    }

    installFrameHook() {
      // Emscripten calls Module.postMainLoop after each frame, in the same task: the WebGL
      // drawing buffer still holds the frame there (no preserveDrawingBuffer needed).
      this.api.module.postMainLoop = () => {
        if (this.timing.firstFrame === null) this.timing.firstFrame = performance.now();
        if (this.pendingCaptures.length) this.captureNow(this.pendingCaptures.splice(0));
      };
    }

    captureNow(waiting) {
      try {
        const canvas = this.canvas;
        const ratio = canvas.width / Math.max(1, canvas.clientWidth);
        let x = 0, y = 0, w = canvas.width, h = canvas.height;
        try {
          const v = this.api.view([], 'workspace');
          x = Math.max(0, Math.floor(v.canvas_min[0] * ratio));
          y = Math.max(0, Math.floor(v.canvas_min[1] * ratio));
          w = Math.min(canvas.width - x, Math.ceil((v.canvas_max[0] - v.canvas_min[0]) * ratio));
          h = Math.min(canvas.height - y, Math.ceil((v.canvas_max[1] - v.canvas_min[1]) * ratio));
        } catch {
          // a lesson without a workspace view: the whole canvas
        }
        const out = el('canvas', { width: Math.max(1, w), height: Math.max(1, h) });
        out.getContext('2d').drawImage(canvas, x, y, w, h, 0, 0, w, h);
        out.toBlob((blob) => {
          for (const p of waiting) blob ? p.resolve(blob) : p.reject(new Error('the browser could not make a PNG'));
        }, 'image/png');
      } catch (e) {
        for (const p of waiting) p.reject(e);
      }
    }

    resetLesson() {
      const lesson = this.api.status().lesson;
      const work = this.captureWork();
      this.writeSlot('previous', Object.assign(work, { savedAt: Date.now() }));
      this.api.restore({ lesson });
      this.updatePreviousLabel();
      this.saveNow();
      this.api.notify(`${this.lessonName(lesson)} is back to its default. "Restore my previous work" undoes this.`, 8);
    }

    /** Swaps the work and the previous work: nothing is lost, and doing it twice undoes it. */
    restorePrevious() {
      const previous = this.readSlot('previous');
      if (!previous) {
        this.api.notify('There is no previous work to restore.', 5);
        this.api.pageState({ previous: '' });
        return;
      }
      const now = this.captureWork();
      const problems = this.restoreWork(previous);
      this.writeSlot('previous', Object.assign(now, { savedAt: Date.now() }));
      this.updatePreviousLabel();
      this.saveNow();
      this.api.notify(problems.length ? 'Restored your previous work, except: ' + problems.join('; ')
                                      : 'Restored your previous work. What you had is now the previous work.', 8);
    }

    async openFull() {
      const { url } = await this.shareLink();
      global.open(url, '_blank', 'noopener');
    }

    async copy(text) {
      try {
        if (navigator.clipboard && global.isSecureContext !== false) {
          await navigator.clipboard.writeText(text);
          return true;
        }
      } catch {
        // denied or unavailable: the old way below
      }
      const area = el('textarea', { value: text, readOnly: true, class: 'lab-offscreen' });
      this.root.appendChild(area);
      area.select();
      let ok = false;
      try {
        ok = document.execCommand('copy');
      } catch {
        ok = false;
      }
      area.remove();
      return ok;
    }

    // ---- dialog (DOM, over the canvas: real text fields that copy like any other) ---------

    showDialog(title, paragraphs, fields) {
      this.closeDialog();
      const titleId = 'lab-dialog-title-' + Math.random().toString(36).slice(2, 8);
      const box = el('div', { class: 'lab-dialog-box' });
      box.appendChild(el('h2', { id: titleId, text: title }));
      for (const p of paragraphs) box.appendChild(el('p', { text: p }));
      for (const f of fields) {
        const area = el('textarea', { value: f.value, readOnly: true, rows: f.rows || 3, spellcheck: false });
        area.addEventListener('focus', () => area.select());
        const copy = el('button', { type: 'button', text: 'Copy' });
        copy.addEventListener('click', async () => {
          copy.textContent = (await this.copy(f.value)) ? 'Copied' : 'Select and copy by hand';
        });
        box.appendChild(el('label', { class: 'lab-dialog-field' }, [el('span', { text: f.label }), area]));
        box.appendChild(el('div', { class: 'lab-dialog-row' }, [copy]));
      }
      const close = el('button', { type: 'button', class: 'lab-dialog-close', text: 'Close' });
      close.addEventListener('click', () => this.closeDialog());
      box.appendChild(el('div', { class: 'lab-dialog-row' }, [close]));
      const dialog = el('div', { class: 'lab-dialog', role: 'dialog' }, [box]);
      dialog.setAttribute('aria-modal', 'true');
      dialog.setAttribute('aria-labelledby', titleId);
      dialog.addEventListener('keydown', (e) => {
        if (e.key === 'Escape') this.closeDialog();
      });
      dialog.addEventListener('mousedown', (e) => {
        if (e.target === dialog) this.closeDialog();
      });
      this.root.appendChild(dialog);
      this.dialog = dialog;
      const first = dialog.querySelector('textarea') || close;
      first.focus({ preventScroll: true });
      return dialog;
    }

    closeDialog() {
      if (!this.dialog) return;
      this.dialog.remove();
      this.dialog = null;
      this.canvas.focus({ preventScroll: true });
    }

    // ---- input: focus, wheel, drag and drop -------------------------------------------------

    focused() {
      return document.activeElement === this.canvas && document.hasFocus();
    }

    installInput() {
      const { root, canvas } = this;
      // SDL takes mousedown (and cancels it, which would keep focus away): focus on pointerdown.
      canvas.addEventListener('pointerdown', () => {
        if (document.activeElement !== canvas) canvas.focus({ preventScroll: true });
      });
      canvas.addEventListener('contextmenu', (e) => e.preventDefault());
      // SDL's wheel listener on the canvas cancels the event (no page scroll). Until the lab has
      // focus the event stops here, on the way down: SDL never sees it and the page scrolls.
      root.addEventListener('wheel', (e) => {
        if (!this.options.guardWheel || e.target !== canvas || this.focused()) return;
        e.stopPropagation();
        this.hint('Click the lab first to zoom with the wheel');
      }, { capture: true, passive: true });
      // Drag and drop of a scene file onto the lab.
      const hasFiles = (e) => e.dataTransfer && Array.from(e.dataTransfer.types || []).includes('Files');
      root.addEventListener('dragover', (e) => {
        if (!hasFiles(e)) return;
        e.preventDefault();
        e.dataTransfer.dropEffect = 'copy';
        root.classList.add('lab-drop');
      });
      root.addEventListener('dragleave', (e) => {
        if (e.target === root || e.target === canvas) root.classList.remove('lab-drop');
      });
      root.addEventListener('drop', (e) => {
        root.classList.remove('lab-drop');
        if (!hasFiles(e)) return;
        e.preventDefault();
        const files = e.dataTransfer.files;
        if (files.length > 1) this.api.notify('Drop one scene file at a time; the first one is read.', 5);
        if (files.length) this.importFile(files[0]);
      });
    }

    hint(text) {
      if (!this.hintEl) {
        this.hintEl = el('div', { class: 'lab-hint', role: 'status' });
        this.root.appendChild(this.hintEl);
      }
      this.hintEl.textContent = text;
      this.hintEl.hidden = false;
      clearTimeout(this.hintTimer);
      this.hintTimer = setTimeout(() => { this.hintEl.hidden = true; }, 1500);
    }
  }

  global.CSpaceLabShell = LabShell;
})(typeof window !== 'undefined' ? window : globalThis);
