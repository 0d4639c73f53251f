// The page around one C-Space Lab instance: what a link or a page's data-lab attribute asks
// for, autosave with a bounded history of previous work, restores that cannot brick the lab,
// tabs that do not overwrite each other, Share and Embed dialogs, import and export, and the
// input rules of an embed (the wheel scrolls the page until the lab has focus).
//
// Everything the user or a link supplies is handled as data: parsed with JSON.parse or the
// strict parsers of lab-url.js, shown with textContent or as an <textarea>'s value, passed to the
// app as JSON. Problems become the app's one-line notice; nothing is ever written as HTML.
//
// Storage, per lab, `cspacelab:v1:<page path>:<id>:` and
//   work             the autosave of the tab that holds the lease
//   history:<entry>  previous work: what a link, a reset or a restore replaced, work that could
//                    not be restored, another tab's work. One key each, so that tabs never
//                    rewrite each other's entries and a small one fits where a large one does not
//   restoring:<tab>  a restore in progress (what, where it is kept) until frames were drawn
//                    after it: a start that finds one of a gone tab opens clean
//   lease            {tab, beat}: the tab that writes `work`; another saves to its own entry
'use strict';

(function (global) {
  const U = global.CSpaceLabUrl;
  const STORAGE_PREFIX = 'cspacelab:v1:';
  const WORK_FORMAT = 'cspacelab-work';
  const ENTRY_FORMAT = 'cspacelab-previous-work';
  const MARKER_FORMAT = 'cspacelab-restoring';
  const MAX_IMPORT_BYTES = 2 * 1024 * 1024;
  const AUTOSAVE_POLL_MS = 600;
  const AUTOSAVE_QUIET_MS = 1000;   // save once nothing changed for this long...
  const AUTOSAVE_MAX_WAIT_MS = 4000; // ...or at least this often while things keep changing
  // The history: at most this many entries and characters (Chromium gives an origin about 5
  // million characters, and the work itself needs room too).
  const HISTORY_MAX = 10;
  const HISTORY_MAX_CHARS = 1500000;
  const MAX_STEPS = 100000000;  // what the app's run_to takes (count_arg in src/app/shell/app.cpp)
  const MARKER_FRAMES = 3;      // a restore is done once the app drew this many frames after it
  const BEAT_MS = 1000;
  // A marker or a lease not refreshed for this long belongs to a tab that froze, crashed or
  // closed. A hidden tab draws no frames, and after 5 minutes Chrome runs its timers about once a
  // minute: its marker says `hidden`, and is not judged by its age.
  const MARKER_STALE_MS = 6000;
  const LEASE_STALE_MS = 10000;
  const REASONS = { link: 'before a link', reset: 'before reset', crash: 'could not be restored', tab: 'another tab',
                    restore: 'before restoring other work', previous: 'previous work' };
  const FULL_TEXT = 'changes are not being saved: storage for this site is full. File > Export scene keeps a copy.';

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


  // Where Share links point from a lab opened as a file: an address the instructor gave once.
  const SHARE_BASE = STORAGE_PREFIX + 'share-base';
  function shareBase(set) {
    try {
      if (set === undefined) return global.localStorage.getItem(SHARE_BASE);
      global.localStorage.setItem(SHARE_BASE, set);
    } catch {
      // no storage: asked again next time
    }
    return null;
  }

  /** {url} of the lab's address on the web (http or https, no ? or #), or {error}. */
  function webAddress(text) {
    const t = String(text).trim();
    if (!t) return { error: 'Give the lab\'s address, such as https://your.site/cspacelab/ or the address of the uploaded file.' };
    let u;
    try {
      u = new URL(t);
    } catch {
      return { error: `${U.excerpt(t, 60)} is not an address: it starts with https:// or http://.` };
    }
    if (u.protocol !== 'https:' && u.protocol !== 'http:') return { error: `A link for others starts with https:// or http://, not ${u.protocol}//.` };
    if (u.username || u.password) return { error: 'The address must not hold a user name or password.' };
    if (u.search || u.hash) return { error: 'The address of the lab itself, without ? or #: the link adds its own.' };
    return { url: u.href };
  }

  const randomId = () => Array.from(global.crypto.getRandomValues(new Uint8Array(6)), (b) => b.toString(16).padStart(2, '0')).join('');
  const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
  const live = (beat, staleMs, now = Date.now()) => typeof beat === 'number' && now - beat <= staleMs && beat <= now + 60000;
  const describe = (e) => U.excerpt(String(e && e.message ? e.message : e), 120).slice(1, -1);

  // The wasm failing (a trap, an Emscripten abort). A page's scripts throw RangeError and
  // SyntaxError too: those count only out of _csl_call or a frame (attach(), lab.js).
  const isTrap = (e) => !!global.WebAssembly && e instanceof WebAssembly.RuntimeError;

  function timeText(t) {
    const d = new Date(t);
    const time = d.toLocaleTimeString([], { hour: '2-digit', minute: '2-digit', second: '2-digit' });
    return d.toDateString() === new Date().toDateString() ? time : d.toLocaleDateString([], { day: 'numeric', month: 'short' }) + ' ' + time;
  }

  function validWork(r) {
    return !!r && r.format === WORK_FORMAT && r.version === 1 && typeof r.current === 'string' &&
      !!r.lessons && typeof r.lessons === 'object' && !Array.isArray(r.lessons);
  }

  /** What makes two work records the same work (not when they were saved). */
  const workText = (r) => JSON.stringify({ config: r.config, current: r.current, lessons: r.lessons });

  // The look the student chose in the app's File > Display ({scheme, contrast}; one per origin,
  // every lab on it: a student who needs high contrast needs it in every lab they meet).
  const LOOK = STORAGE_PREFIX + 'look';
  const SCHEMES = ['system', 'light', 'dark'];
  const CONTRASTS = ['system', 'normal', 'high'];
  const storedLook = (look) => {
    try {
      if (look) return global.localStorage.setItem(LOOK, JSON.stringify(look));
      const v = JSON.parse(global.localStorage.getItem(LOOK) || 'null');
      const out = {};
      if (v && SCHEMES.includes(v.scheme)) out.scheme = v.scheme;
      if (v && CONTRASTS.includes(v.contrast)) out.contrast = v.contrast;
      return out;
    } catch {
      return {};
    }
  };

  // ---- storage: one lab's keys, without the wasm (a lab that stopped still offers its work) --

  // Whether this browser saw the welcome (one flag per origin; no storage: never shown).
  const WELCOMED = STORAGE_PREFIX + 'welcomed';
  const welcomed = (see) => {
    try {
      return see ? global.localStorage.setItem(WELCOMED, '1') : global.localStorage.getItem(WELCOMED);
    } catch {
      return '1';
    }
  };

  class WorkStore {
    constructor(scope, id) {
      this.prefix = STORAGE_PREFIX + scope + ':' + id + ':';
      this.dropped = { full: 0, bound: 0 };
      try {
        // Reading is its own question: a full origin still reads.
        global.localStorage.getItem(this.prefix + 'work');
        this.storage = global.localStorage;
      } catch {
        this.storage = null;
      }
    }

    get readable() { return this.storage !== null; }

    get(slot) {
      try {
        return this.storage ? this.storage.getItem(this.prefix + slot) : null;
      } catch {
        return null;
      }
    }

    /** The value parsed; null when absent or not JSON. */
    json(slot) {
      try {
        return JSON.parse(this.get(slot));
      } catch {
        return null;
      }
    }

    remove(slot) {
      try {
        if (this.storage) this.storage.removeItem(this.prefix + slot);
      } catch {
        // the key stays
      }
    }

    /** The slots of this lab that start with `head`. */
    slots(head) {
      const out = [];
      try {
        for (let i = 0; this.storage && i < this.storage.length; ++i) {
          const k = this.storage.key(i);
          if (k && k.startsWith(this.prefix + head)) out.push(k.slice(this.prefix.length));
        }
      } catch {
        // a storage that went away: none
      }
      return out;
    }

    /**
     * Writes a slot. When the origin is full, drops the oldest history entries (not those in
     * `keep`) until it fits, unless trim is false. {ok, full}.
     */
    set(slot, text, keep = [], trim = true) {
      for (;;) {
        try {
          if (!this.storage) return { ok: false, full: false };
          this.storage.setItem(this.prefix + slot, text);
          return { ok: true, full: false };
        } catch (e) {
          if (!(e && (e.name === 'QuotaExceededError' || e.name === 'NS_ERROR_DOM_QUOTA_REACHED'))) return { ok: false, full: false };
          const victim = trim && this.entries().reverse().find((x) => !keep.includes(x.id) && 'history:' + x.id !== slot);
          if (!victim) return { ok: false, full: true };
          this.remove('history:' + victim.id);
          this.dropped.full += 1;
        }
      }
    }

    /** Whether saves have room: 1 KB more fits, or there is history to drop (only a real save drops it). */
    roomy() {
      const r = this.set('probe', 'x'.repeat(1024), [], false);
      this.remove('probe');
      return r.ok || this.slots('history:').length > 0;
    }

    /** History entries, newest first: {id, savedAt, reason, lesson, failed, work | link, size}. */
    entries() {
      const out = [];
      for (const slot of this.slots('history:')) {
        const text = this.get(slot);
        let e = null;
        try {
          e = JSON.parse(text);
        } catch {
          continue;
        }
        if (!e || e.format !== ENTRY_FORMAT || typeof e.savedAt !== 'number' ||
            !(e.work ? validWork(e.work) : e.link && typeof e.link.query === 'string')) continue;
        out.push(Object.assign(e, { id: slot.slice(8), size: text.length }));
      }
      return out.sort((a, b) => b.savedAt - a.savedAt || (a.id < b.id ? 1 : -1));
    }

    entry(id) {
      return this.entries().find((e) => e.id === id) || null;
    }

    /** Writes entry `id` (new or in place), then keeps the history within its bounds. {ok, full}. */
    putEntry(id, entry, keep = []) {
      const value = Object.assign({ format: ENTRY_FORMAT, version: 1, savedAt: Date.now(), lesson: '', failed: false }, entry);
      const r = this.set('history:' + id, JSON.stringify(value), keep.concat(id));
      if (!r.ok) return r;
      let list = this.entries();
      let chars = list.reduce((n, e) => n + e.size, 0);
      while (list.length > HISTORY_MAX || (chars > HISTORY_MAX_CHARS && list.length > 1)) {
        const victim = list.slice().reverse().find((e) => !keep.includes(e.id) && e.id !== id);
        if (!victim) break;
        this.remove('history:' + victim.id);
        list = list.filter((e) => e !== victim);
        chars -= victim.size;
        this.dropped.bound += 1;
      }
      return r;
    }

    markers() {
      return this.slots('restoring:').map((slot) => this.json(slot)).filter((m) => m && m.format === MARKER_FORMAT && typeof m.tab === 'string');
    }

    lease() {
      const l = this.json('lease');
      return l && typeof l.tab === 'string' && typeof l.beat === 'number' ? l : null;
    }
  }

  class LabShell {
    /**
     * root: the [data-lab] element; canvas: its canvas; api: its CSpaceLabApi, or null until
     * attach() (the shell is made before the wasm, so that a failure at start still offers the
     * saved work). options: {config: query string, ui: 'full'|'minimal', storageId, scope, home:
     * URL of the full lab (share links), base: URL of the folder with the lab's files, single:
     * bool (the single-file build), guardWheel: bool (the wheel scrolls the page until focused),
     * task: the task text shown above the canvas, lab-task.js's normalise() (Share and Embed keep it)}
     */
    constructor(root, canvas, api, options) {
      this.root = root;
      this.canvas = canvas;
      this.options = options;
      this.store = new WorkStore(options.scope, options.storageId);
      this.tab = randomId();                // this page load: its lease, marker and own entry
      this.tabEntryId = 'tab-' + this.tab;  // where it saves while another tab holds the lease
      this.role = 'owner';                  // 'owner' writes the work slot, 'second' its own entry
      this.lastSaved = null;
      this.dirtySince = 0;
      this.changedAt = 0;
      this.pendingCaptures = [];
      this.dialog = null;
      this.timing = { ready: performance.now(), firstFrame: null };
      this.problems = [];
      this.frames = 0;          // frames drawn (postMainLoop)
      this.inFrame = false;     // between preMainLoop and postMainLoop: a throw there is a trap
      this.marker = null;       // this tab's restore in progress
      this.dead = false;        // the wasm failed: storage and the DOM are left
      this.cleanText = null;    // the untouched defaults of a clean start (not worth keeping)
      this.notes = [];          // for the next notice: saves that failed, history dropped
      this.historyIds = [];
      this.api = null;
      if (api) this.attach(api);
    }

    /** Takes the API; its methods are wrapped so that the wasm failing in any call stops the lab cleanly. */
    attach(api) {
      this.api = api;
      this.timing.ready = performance.now();  // the module is ready (web_budgets reports it)
      const proto = Object.getPrototypeOf(api);
      for (const name of Object.getOwnPropertyNames(proto)) {
        const d = Object.getOwnPropertyDescriptor(proto, name);
        if (name === 'constructor' || typeof d.value !== 'function') continue;
        const shell = this;
        api[name] = function guarded(...args) {
          if (shell.dead) throw new Error('C-Space Lab has stopped: ' + shell.deathText);
          const calls = shell.calls;
          try {
            return proto[name].apply(this, args);
          } catch (e) {
            // A SyntaxError after _csl_call returned: its response was not JSON.
            if (isTrap(e) || (e instanceof SyntaxError && shell.calls !== calls)) shell.trap(e);
            throw e;
          }
        };
      }
      const raw = api.module._csl_call;  // the wasm's one entry point, whoever calls it
      this.calls = 0;
      api.module._csl_call = (ptr) => {
        try {
          return raw(ptr);
        } catch (e) {
          this.trap(e);
          throw e;
        } finally {
          this.calls += 1;
        }
      };
    }

    // ---- start ------------------------------------------------------------------------------

    /**
     * The browser's prefers-reduced-motion, now and whenever it changes: the app then moves
     * nothing by itself (WCAG 2.3.3). Set before the link applies, which may start an exercise.
     */
    watchReducedMotion() {
      const query = typeof matchMedia === 'function' ? matchMedia('(prefers-reduced-motion: reduce)') : null;
      if (!query) return false;
      query.addEventListener('change', () => {
        if (!this.dead) this.api.pageState({ reduced_motion: query.matches });
      });
      return query.matches;
    }

    /**
     * What the browser prefers for the look, now and whenever it changes: dark colours
     * (prefers-color-scheme) and more contrast (prefers-contrast: more, or forced colours as
     * Windows' contrast themes set them). The app follows them unless the student chose.
     */
    watchLook() {
      const queries = typeof matchMedia === 'function'
        ? { dark: matchMedia('(prefers-color-scheme: dark)'), more: matchMedia('(prefers-contrast: more)'),
            forced: matchMedia('(forced-colors: active)') }
        : null;
      if (!queries) return {};
      const now = () => ({ system_dark: queries.dark.matches, system_high_contrast: queries.more.matches || queries.forced.matches });
      for (const q of Object.values(queries)) {
        q.addEventListener('change', () => {
          if (!this.dead) this.showLook(this.api.pageState(now()));
        });
      }
      return now();
    }

    /** The lab's element says the look in use (data-look="dark high"): the page's dialogs follow it. */
    showLook(state) {
      if (!state || !state.look) return;
      this.root.dataset.look = (state.look.dark ? 'dark' : 'light') + (state.look.high_contrast ? ' high' : '');
    }

    /** The look a link asks for (scheme=, contrast=) over the one the student chose before. */
    lookChoice(values) {
      const look = storedLook();
      if (values.has('scheme') && SCHEMES.includes(values.get('scheme'))) look.scheme = values.get('scheme');
      if (values.has('contrast') && CONTRASTS.includes(values.get('contrast'))) look.contrast = values.get('contrast');
      return look;
    }

    async init() {
      const api = this.api;
      let notes = [];
      try {
        this.lessons = api.lessons();
        this.bundled = api.bundledScenes();
        this.installFrameHook();
        this.installInput();
        // A first visit without a link: the panel offers the homework map (once; "welcome-seen").
        const config = U.parseConfig(this.options.config).values;
        const welcome = this.options.ui !== 'minimal' && !U.hasState(config) && welcomed() === null;
        this.showLook(api.pageState({ attached: true, minimal: this.options.ui === 'minimal', welcome,
                                      reduced_motion: this.watchReducedMotion(), ...this.watchLook(),
                                      ...this.lookChoice(config) }));
        api.module.cslPageAction = (name) => setTimeout(() => this.action(name), 0);
        this.restrict(false);  // nothing the instructor hid is drawn while the link applies
        notes = await this.start();
      } catch (e) {
        if (this.dead) return;  // the crash panel says it
        console.error('C-Space Lab: the page shell failed', e);
        notes.push(`Something failed while the lab started (${describe(e)}); what could be applied is shown.`);
        if (this.marker && this.markerFrame === null) this.restoreDone(false);
      } finally {
        if (!this.dead) {  // whatever happened above, work from here on is saved
          try {
            const bad = this.restrict(true);
            if (bad.length) notes.push('Not used from the link: ' + bad.join('; ') + '.');
          } catch (e) {
            if (!this.dead) notes.push(`The link's lock, hide or reveal could not be applied (${describe(e)}).`);
          }
          this.started = true;
          this.startAutosave();
          this.startHeartbeat();
        }
      }
      if (this.dead) return;
      this.refreshHistory();
      if (notes.length) api.notify(notes.join(' '), 15);
    }

    /**
     * The link's lock, hide and reveal (lab-url.js restrictionsOf) for the app's "restrict",
     * which checks the words against the link's lesson. First (withLocks false) hide and reveal
     * alone, before the link applies, so that no hidden answer is drawn meanwhile; then, once it
     * applied, the locks too: they hold each lesson to what the link (or the saved work of this
     * link) set. Every start reads them from the link or data-lab again, so a reload keeps them.
     * Returns the words the app left out (second call only).
     */
    restrict(withLocks) {
      const values = U.parseConfig(this.options.config).values;
      const { restrictions, problems } = U.restrictionsOf(values);
      if (!Object.keys(restrictions).length) {
        this.restrictions = null;
        return withLocks ? problems : [];
      }
      const args = Object.assign({}, restrictions);
      const lesson = this.linkLesson(values);
      if (lesson) args.lesson = lesson;
      if (!withLocks) delete args.lock;
      const r = this.api.call('restrict', args);
      this.restrictions = r;
      return withLocks ? problems.concat(r.problems) : [];
    }

    /** The lesson a link opens (its problem's, for a problem link), or null (the app's first). */
    linkLesson(values) {
      if (values.has('problem')) {
        const raw = String(values.get('problem')).toUpperCase();
        const id = /^\d+$/.test(raw) ? 'P' + raw : raw;
        const p = this.api.call('homework').find((x) => x.id === id);
        return p ? p.lesson : null;
      }
      const id = values.get('lesson');
      return id && (this.lessons || []).some((l) => l.id === id) ? id : null;
    }

    /** What a link written here keeps of the instructor's: {lock, hide, reveal} (Share, Embed, Open in full). */
    linkRestrictions() {
      const r = this.restrictions;
      const out = {};
      if (!r) return out;
      if (r.lock) out.lock = r.lock;
      if (r.hide) out.hide = r.hide;
      if (r.reveal && r.reveal !== 'never') out.reveal = r.reveal;
      return out;
    }

    lessonName(id) {
      const l = (this.lessons || []).find((x) => x.id === id);
      return l ? l.name : id;
    }

    /** The start proper; returns the sentences of the notice. */
    async start() {
      const store = this.store;
      const parsed = U.parseConfig(this.options.config);
      const problems = parsed.problems.slice();  // the link's and the saved work's bad parts
      const notes = [];
      const configKey = U.hasState(parsed.values) ? U.stateKey(parsed.values) : null;
      if (store.readable) {
        this.migratePrevious();
        this.claimLease();
      }
      // Restores other starts left unfinished (they crashed or froze the lab): open clean.
      const leftovers = store.readable ? await this.leftoverMarkers() : [];
      const retry = leftovers.find((m) => m.choice === 'retry');
      const failed = leftovers.filter((m) => m !== retry);
      let offer = null;
      for (const m of failed) {
        const o = this.preserve(m);
        if (o && (!offer || o.slot)) offer = o;
        if (o && o.slot) this.protectWork = true;  // no room to keep it aside: nothing is saved over it
      }
      if (retry) store.remove('restoring:' + retry.tab);

      let opened = '';
      let restored = false;
      if (failed.length) {
        // Clean: the lessons' defaults; the link counts as seen, so a reload does not meet it again.
        this.config = configKey;
        this.cleanText = workText(this.captureWork());
      } else {
        const saved = this.store.json('work');
        if (store.get('work') !== null && !validWork(saved)) problems.push('the saved work in this browser could not be read');
        if (validWork(saved)) {
          this.beginRestore('your saved work', { kind: 'work' });
          problems.push(...this.restoreWork(saved, 'your saved work').map((p) => 'saved work: ' + p));
          restored = true;
        }
        if (configKey && !(restored && saved.config === configKey)) {
          // A link not seen before, over the saved work: work of its lesson goes to the history.
          const before = this.captureWork();
          this.beginRestore('the link', { kind: 'link', query: this.options.config, config: configKey });
          problems.push(...(await this.applyConfig(parsed.values)));
          const lesson = this.api.status().lesson;
          if (restored && before.lessons[lesson] && !sameJson(before.lessons[lesson], this.api.snapshot(lesson)))
            opened = this.pushHistory(before, 'link').ok ? 'kept' : 'lost';
        } else if (parsed.values.has('problem')) {
          // A problem link seen before: the saved work stands, the card comes back.
          const seed = parsed.values.get('seed') || '';
          try {
            this.api.call('open_problem', { id: parsed.values.get('problem'), seed: /^\d{1,15}$/.test(seed) ? Number(seed) : undefined, preset: false });
          } catch {
            // named when the link was first opened
          }
        }
        this.config = configKey;
      }
      if (this.role === 'second') this.lastSaved = workText(this.captureWork());  // its entry: changes only
      this.restoreDone(this.saveNow());
      if (retry && retry.source.kind === 'history') await this.restoreEntry(retry.source.id, true);

      const full = store.readable && !store.roomy();
      this.saveFailed = full;
      if (problems.length) notes.push('Not used from the link: ' + problems.join('; ') + '. The lesson\'s defaults stand in for these.');
      if (this.options.task && this.options.task.problem) notes.push(this.options.task.problem);
      if (opened === 'kept') notes.push('Opened the link. Your previous work is kept: "Restore my previous work" brings it back.');
      if (opened === 'lost') notes.push('Opened the link. Your previous work stays the saved work until this one is saved: there is no room to keep both.');
      if (!store.readable) notes.push('Autosave is off: this page may not use the browser\'s storage.');
      else if (full) notes.push((restored ? 'Your saved work was restored; ' : 'Nothing is lost, but ') + FULL_TEXT);
      notes.push(this.droppedText());
      this.notes.length = 0;
      if (this.role === 'second') notes.push(this.secondTabText());
      if (failed.length) notes.push('Opened with the lessons\' defaults: your work could not be restored (see the dialog).');
      this.problems = problems;
      if (offer) setTimeout(() => this.showRecovery(offer), 0);
      return notes.filter(Boolean);
    }

    /** What the history lost since the last notice ('' if nothing). */
    droppedText() {
      const { full, bound } = this.store.dropped;
      this.store.dropped = { full: 0, bound: 0 };
      const n = (k) => `The oldest previous work (${k} ${k === 1 ? 'entry' : 'entries'}) was dropped`;
      return [full ? n(full) + ' to make room: storage for this site is full.' : '',
              bound ? n(bound) + `: the history keeps the newest ${HISTORY_MAX}.` : ''].filter(Boolean).join(' ');
    }

    secondTabText() {
      return 'This lab is also open in another tab. So that neither tab overwrites the other, this tab saves its work ' +
             'separately: File > "another tab" brings it back.';
    }

    /** The single "previous work" slot of earlier versions moves into the history. */
    migratePrevious() {
      const old = this.store.json('previous');
      if (this.store.get('previous') === null || (validWork(old) && !this.pushHistory(old, 'previous', old.savedAt).ok)) return;
      this.store.remove('previous');
    }

    /**
     * Markers of starts whose tab is gone (it trapped, froze or closed mid-restore), and retry
     * requests. A marker of a tab that may still be restoring is waited for until it goes, its
     * tab proves alive (its beat moves on) or it goes stale: a start that raced a healthy one
     * must not open clean.
     */
    async leftoverMarkers() {
      for (const begun = Date.now(); ;) {
        const now = Date.now();
        const markers = this.store.markers();
        // A hidden page's marker is not judged by its age (its timers may run once a minute).
        const gone = markers.filter((m) => m.trapped || m.choice || (!m.hidden && !live(m.beat, MARKER_STALE_MS, now)));
        const young = markers.filter((m) => !gone.includes(m) && !m.hidden && m.beat - m.startedAt < 2 * BEAT_MS);
        if (!young.length || now - begun > MARKER_STALE_MS + 2 * BEAT_MS) {
          const lease = this.store.lease();
          if (lease && gone.some((m) => m.tab === lease.tab)) this.takeLease();  // its lease went with it
          return gone;
        }
        await sleep(250);
      }
    }

    /**
     * Keeps what a failed restore was about in the history (storage only), so that the clean
     * start's autosave cannot overwrite it, and clears its marker once it is safe. Returns what
     * the dialog offers: {id} of an entry, {slot} when there was no room (the work slot keeps
     * it), or null.
     */
    preserve(m) {
      const s = m.source || {};
      const work = this.store.json('work');
      const info = { marker: m, what: String(m.what || 'your work'), error: String(m.error || '') };
      let id = null;
      const e = s.kind === 'history' ? this.store.entry(s.id) : null;
      if (e) {
        this.store.putEntry(e.id, Object.assign(e, { failed: true }));
        id = e.id;
        if (validWork(work)) this.pushHistory(work, 'restore', undefined, false, [e.id]);
      } else if (s.kind === 'link' && typeof s.query === 'string') {
        if (validWork(work)) this.pushHistory(work, 'link');
        const linkId = this.newEntryId();
        const link = { query: s.query, config: s.config || null };
        if (this.store.putEntry(linkId, { reason: 'crash', failed: true, lesson: U.parseConfig(s.query).values.get('lesson') || '', link }).ok) id = linkId;
      } else if (validWork(work)) {
        id = this.pushHistory(work, 'crash', undefined, true).id;
      }
      if (!id && validWork(work)) return Object.assign(info, { slot: true });  // the marker stays
      this.store.remove('restoring:' + m.tab);
      return id ? Object.assign(info, { id }) : null;
    }

    newEntryId() {
      return Date.now().toString(36) + '-' + randomId().slice(0, 6);
    }

    /** Keeps a work record in the history; the same work kept before moves up. {ok, full, id}. */
    pushHistory(record, reason, savedAt = Date.now(), failed = false, keep = []) {
      const text = workText(record);
      const same = this.store.entries().filter((e) => e.work && !e.id.startsWith('tab-') && !keep.includes(e.id) && workText(e.work) === text);
      const id = this.newEntryId();
      const work = { format: WORK_FORMAT, version: 1, config: record.config === undefined ? null : record.config,
                     current: record.current, lessons: record.lessons, savedAt: record.savedAt || savedAt };
      const r = this.store.putEntry(id, { reason, savedAt, failed, lesson: record.current, work }, keep);
      if (r.ok) for (const e of same) this.store.remove('history:' + e.id);
      return Object.assign(r, { id: r.ok ? id : null });
    }

    /** Applies a link's values over a fresh lesson, part by part; returns the problems. */
    async applyConfig(values) {
      const api = this.api;
      const problems = [];
      // Each part on its own: a bad one is named in the notice and the rest still applies. A trap
      // is not a bad part: it stops here (the crash panel takes over).
      const part = (what, fn) => {
        try {
          fn();
        } catch (e) {
          if (this.dead) throw e;
          problems.push(what(e));
        }
      };
      if (values.has('problem')) {
        // A homework problem: its lesson and preset; &seed= fixes its numbers.
        const raw = values.get('problem');
        const args = { id: raw };
        if (values.has('seed')) {
          const seed = values.get('seed');
          if (/^\d{1,15}$/.test(seed)) args.seed = Number(seed);
          else problems.push(`seed ${U.excerpt(seed)} (a whole number of at most 15 digits)`);
        }
        part((e) => `problem ${U.excerpt(raw)} (${e.message})`, () => api.call('open_problem', args));
        for (const key of values.keys())
          if (key !== 'problem' && key !== 'seed' && !U.PRESENTATION.has(key) && !U.RESTRICTION_KEYS.includes(key))
            problems.push(`${key} (a problem link sets up its own)`);
        return problems;
      }
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
      let opened = false;
      if (scene) part((e) => 'scene: ' + e.message, () => { api.restore({ lesson, scene }); opened = true; });
      if (!opened) part((e) => `lesson: ${e.message}`, () => api.restore({ lesson }));
      let template = {};
      part((e) => `parameters: ${e.message}`, () => { template = api.snapshot().params || {}; });
      for (const [key, raw] of values) {
        if (U.RESERVED.has(key)) continue;
        if (!Object.prototype.hasOwnProperty.call(template, key)) {
          problems.push(`${key} (not a parameter of ${this.lessonName(lesson)})`);
          continue;
        }
        part((e) => `${key} ${U.excerpt(raw)} (${e.message})`, () => api.setParams({ [key]: U.parseValue(raw, template[key]) }));
      }
      if (values.has('steps')) {
        const raw = values.get('steps');
        if (!U.STEPS.test(raw)) problems.push(`steps ${U.excerpt(raw)} (not a whole number of steps)`);
        else if (Number(raw) > MAX_STEPS) problems.push(`steps ${U.excerpt(raw)} (more than the lab's ${MAX_STEPS} steps)`);
        else part((e) => `steps ${U.excerpt(raw)} (${e.message})`, () => api.call('run_to', { steps: Number(raw), background: true }));
      }
      if (values.has('camera')) {
        const raw = values.get('camera');
        part((e) => `camera ${U.excerpt(raw)} (${e.message.replace(/^camera: /, '')})`,
             () => api.call('set_camera', { camera: U.parseCamera(raw) }));
      }
      try {
        api.call('note_restored', { from: 'the link' });  // the log's first line says so
      } catch (e) {
        if (this.dead) throw e;  // (it cannot fail otherwise: there is a lesson on screen)
      }
      if (values.has('ui') && !['full', 'minimal'].includes(values.get('ui')))
        problems.push(`ui ${U.excerpt(values.get('ui'))} (full or minimal)`);
      if (values.has('scheme') && !SCHEMES.includes(values.get('scheme')))
        problems.push(`scheme ${U.excerpt(values.get('scheme'))} (${SCHEMES.join(', ')})`);
      if (values.has('contrast') && !CONTRASTS.includes(values.get('contrast')))
        problems.push(`contrast ${U.excerpt(values.get('contrast'))} (${CONTRASTS.join(', ')})`);
      if (values.has('id') && !U.ID.test(values.get('id')))
        problems.push(`id ${U.excerpt(values.get('id'))} (letters, digits, - and _)`);
      return problems;
    }


    // ---- restore markers: a restore that crashes or freezes the lab must not do it again ----

    /** "Restore in progress", before it: what, and where that work is kept. */
    beginRestore(what, source) {
      const now = Date.now();
      this.marker = { format: MARKER_FORMAT, version: 1, tab: this.tab, what, source, startedAt: now, beat: now };
      this.markerFrame = null;
      this.writeMarker();
    }

    writeMarker() {
      if (this.marker) this.store.set('restoring:' + this.tab, JSON.stringify(Object.assign(this.marker, { hidden: document.hidden })));
    }

    /** Its synchronous part is over (and saved, if savedOk: the work is then where this tab saves). */
    restoreDone(savedOk) {
      if (!this.marker || this.dead) return;
      if (savedOk) this.marker.source = this.ownSource();
      this.markerFrame = this.frames;
      this.marker.beat = Date.now();
      this.writeMarker();
    }

    ownSource() {
      return this.role === 'owner' ? { kind: 'work' } : { kind: 'history', id: this.tabEntryId };
    }

    /** After each frame: the marker goes once MARKER_FRAMES were drawn and the app is not busy. */
    frameDone() {
      const n = this.frames - this.markerFrame;
      if (!this.marker || this.markerFrame === null || this.dead || n < MARKER_FRAMES || (n > MARKER_FRAMES && n % 5)) return;
      try {
        if (this.api.status().busy) return;  // a background run is not done (absent: not busy)
      } catch {
        return;
      }
      this.endRestore();
    }

    endRestore() {
      this.store.remove('restoring:' + this.tab);
      this.marker = null;
      this.markerFrame = null;
    }

    /** The wasm failed (a trap, an abort): stop, keep what is saved, offer it in the lab's place. */
    trap(error) {
      if (this.dead) return;
      this.dead = true;
      this.deathText = describe(error).replace(/^(RuntimeError|Error): /, '');
      console.error('C-Space Lab stopped:', error);
      clearInterval(this.autosaveTimer);
      clearInterval(this.heartbeatTimer);
      if (this.store.readable) {
        // The next start opens clean and offers the work: a crash while working may have been
        // saved already and would come back with the restore.
        if (!this.marker) this.beginRestore('your work', this.ownSource());
        Object.assign(this.marker, { trapped: true, error: this.deathText });
        this.writeMarker();
        this.releaseLease();
      }
      if (this.api) this.api.module.cslPageAction = () => {};
      this.showCrashPanel();
    }

    // ---- tabs: one writes the work slot, the others their own history entry ----------------

    claimLease() {
      const lease = this.store.lease();
      if (lease && lease.tab !== this.tab && live(lease.beat, LEASE_STALE_MS)) this.role = 'second';
      else this.takeLease();
    }

    takeLease() {
      this.role = 'owner';
      this.store.set('lease', JSON.stringify({ tab: this.tab, beat: Date.now() }), [], false);
    }

    releaseLease() {
      const lease = this.store.lease();
      if (lease && lease.tab === this.tab) this.store.remove('lease');
    }

    /** Another tab writes the work slot: this one keeps its work in its own entry. */
    becomeSecond() {
      if (this.role === 'second' || this.dead) return;
      this.role = 'second';
      this.lastSaved = null;
      if (this.marker) this.marker.source = this.ownSource();
      this.saveNow();
      this.refreshHistory();
      this.say(this.secondTabText(), 12);
    }

    /** The lease holder is gone: this tab takes the work slot; what that tab left there goes to the history. */
    becomeOwner() {
      if (this.role === 'owner' || this.dead) return;
      this.takeLease();
      const left = this.store.json('work');
      if (validWork(left) && workText(left) !== workText(this.captureWork())) this.pushHistory(left, 'tab');
      this.lastSaved = null;
      if (this.saveNow()) this.store.remove('history:' + this.tabEntryId);
      if (this.marker) this.marker.source = this.ownSource();
      this.refreshHistory();
    }

    startHeartbeat() {
      if (!this.store.readable) return;
      this.heartbeatTimer = setInterval(() => {
        const lease = this.store.lease();
        const other = lease && lease.tab !== this.tab && live(lease.beat, LEASE_STALE_MS);
        if (this.role === 'owner' && other) this.becomeSecond();
        else if (this.role === 'owner') this.takeLease();
        else if (!other) this.becomeOwner();
        if (this.marker) {
          this.marker.beat = Date.now();
          this.writeMarker();
        }
      }, BEAT_MS);
      global.addEventListener('storage', (e) => {
        if (this.dead || e.storageArea !== this.store.storage || !e.key || !e.key.startsWith(this.store.prefix)) return;
        const slot = e.key.slice(this.store.prefix.length);
        const lease = this.store.lease();
        // A tab took the lease (or two tabs both thought they held it: the lease decides), or gave it up.
        if ((slot === 'lease' || slot === 'work') && lease && lease.tab !== this.tab) this.becomeSecond();
        else if (slot === 'lease' && !lease) this.becomeOwner();
        if (slot.startsWith('history:')) {
          clearTimeout(this.historyTimer);
          this.historyTimer = setTimeout(() => this.refreshHistory(), 200);
        }
      });
      global.addEventListener('pageshow', (e) => {
        if (e.persisted && !this.dead) this.claimLease();  // back from the back-forward cache
      });
    }

    // ---- work: capture, restore, save -------------------------------------------------------

    /** {format, version, config, current, lessons: {id: snapshot}} of every open lesson. */
    captureWork() {
      const lessons = {};
      for (const l of this.api.lessons()) if (l.open) lessons[l.id] = this.api.snapshot(l.id);
      return { format: WORK_FORMAT, version: 1, config: this.config === undefined ? null : this.config,
               current: this.api.status().lesson, lessons };
    }

    /**
     * Restores a work record lesson by lesson; returns the problems (those lessons stay as they
     * are). `from` ("your saved work") starts each restored lesson's log.
     */
    restoreWork(record, from) {
      const problems = [];
      const known = new Set(this.lessons.map((l) => l.id));
      for (const [id, snapshot] of Object.entries(record.lessons).slice(0, 64)) {
        if (!known.has(id)) continue;  // a lesson this version does not have
        if (!snapshot || typeof snapshot !== 'object') continue;
        try {
          // background: a long replay goes on over frames (progress and Cancel in the app).
          this.api.restore(Object.assign({}, snapshot, { lesson: id, background: true, from }));
        } catch (e) {
          if (this.dead) throw e;
          problems.push(`${this.lessonName(id)}: ${e.message}`);
          // A view or parameters a newer version names differently must not cost the work: the
          // rest without the views' cameras, else the scene alone.
          const fallbacks = [];
          if (snapshot.camera) fallbacks.push(Object.assign({}, snapshot, { lesson: id, background: true, from, camera: undefined }));
          if (snapshot.scene) fallbacks.push({ lesson: id, scene: snapshot.scene, from });
          for (const fallback of fallbacks) {
            try {
              this.api.restore(fallback);
              break;
            } catch (e2) {
              if (this.dead) throw e2;
              // the scene itself is bad: the lesson stays as it was
            }
          }
        }
      }
      if (known.has(record.current)) {
        try {
          this.api.selectLesson(record.current);
        } catch (e) {
          if (this.dead) throw e;  // (lock=lesson: the lab stays on its lesson)
        }
      }
      return problems;
    }


    /** Saves what is on screen to the work slot (or this tab's own entry). True when it is there (saved now or before). */
    saveNow() {
      if (this.dead || !this.api || !this.store.readable) return false;
      let work;
      try {
        work = this.captureWork();
      } catch {
        return false;  // the app stopped (trap() shows it)
      }
      const text = workText(work);
      // (A second tab's start is "saved" unwritten: it is the work slot's, not in its entry.)
      if (text === this.lastSaved) return this.role === 'owner' || this.store.get('history:' + this.tabEntryId) !== null;
      const lease = this.role === 'owner' && this.store.lease();
      if (lease && lease.tab !== this.tab && live(lease.beat, LEASE_STALE_MS)) {
        this.becomeSecond();  // saves to its entry
        return this.lastSaved === text;
      }
      const record = Object.assign(work, { savedAt: Date.now() });
      const r = this.protectWork ? { ok: false, full: true }
        : this.role === 'owner' ? this.store.set('work', JSON.stringify(record))
        : this.store.putEntry(this.tabEntryId, { reason: 'tab', lesson: record.current, savedAt: record.savedAt, work: record });
      this.dirtySince = 0;
      // What to tell waits for the next notice (say()): an action's own notice would replace it.
      if (this.started) {
        if (this.store.dropped.full) this.refreshHistory();  // the File menu lists what is left
        this.notes.push(this.droppedText());  // '' when nothing was dropped
      }
      if (r.ok) {
        this.lastSaved = text;
        if (this.saveFailed && this.started) this.notes.push('Saving works again.');
        this.saveFailed = false;
        if (this.role === 'second') this.refreshHistory();
        return true;
      }
      if (!this.saveFailed && !this.protectWork) this.notes.push(r.full ? 'Your work is not saved: ' + FULL_TEXT : 'Your work could not be saved in this browser.');
      this.saveFailed = true;
      return false;
    }

    /** The app's notice: `text`, and what saving had to tell since the last one. */
    say(text, seconds = 8) {
      const all = [text, ...this.notes.splice(0)].filter(Boolean).join(' ');
      if (all && !this.dead) this.api.notify(all, seconds);
    }

    startAutosave() {
      const poll = () => {
        if (this.dead) return;
        let text;
        try {
          text = workText(this.captureWork());
        } catch {
          return;  // the app stopped (trap() shows it)
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
        if (now - this.changedAt >= AUTOSAVE_QUIET_MS || now - this.dirtySince >= AUTOSAVE_MAX_WAIT_MS) {
          this.saveNow();
          this.say('', 10);
        }
      };
      this.autosaveTimer = setInterval(poll, AUTOSAVE_POLL_MS);
      // Leaving or hiding the page saves at once: a reload right after an edit keeps it.
      global.addEventListener('pagehide', () => {
        this.saveNow();
        if (this.dead) return;
        // A page that leaves alive did not fail its restore, whether it drew its frames or not (a
        // reload right after the start, a tab closed unseen): the marker only outlives a trap,
        // which sets dead, or a freeze, where this handler never runs.
        if (this.marker) this.endRestore();
        this.releaseLease();
      });
      document.addEventListener('visibilitychange', () => {
        if (document.hidden) this.saveNow();
        if (this.marker && !this.dead) {
          this.marker.beat = Date.now();
          this.writeMarker();  // hidden or not
        }
      });
    }

    // ---- the history of previous work --------------------------------------------------------

    entryLabel(e) {
      const why = (REASONS[e.reason] || 'previous work') + (e.failed && e.reason !== 'crash' ? ', could not be restored' : '');
      const what = e.link ? 'a link' + (e.lesson ? ' to ' + this.lessonName(e.lesson) : '') : this.lessonName(e.lesson || e.work.current);
      return `${timeText(e.savedAt)} · ${why} · ${what}`.slice(0, 200);
    }

    /** Tells the app what the history holds (the File menu's list, the top bar's button). */
    refreshHistory() {
      if (this.dead || !this.api) return [];
      const list = this.store.entries().filter((e) => e.id !== this.tabEntryId).slice(0, 20);
      this.historyIds = list.map((e) => e.id);
      this.api.pageState({ previous: list.length ? 'your work of ' + new Date(list[0].savedAt).toLocaleString() : '',
                           history: list.map((e) => ({ label: this.entryLabel(e) })) });
      return list;
    }

    /** Restores a history entry; what is on screen goes into the history first (nothing is lost). */
    async restoreEntry(id, quiet = false) {
      const entry = id ? this.store.entry(id) : null;
      if (!entry) {
        this.api.notify('That previous work is not there any more (another tab may have restored it).', 6);
        this.refreshHistory();
        return false;
      }
      const current = this.captureWork();
      if (workText(current) !== this.cleanText && !this.pushHistory(current, 'restore', undefined, false, [id]).ok) {
        this.api.notify('Not restored: what is on screen could not be kept first (storage for this site is full). File > Export scene keeps a copy.', 10);
        return false;
      }
      const label = this.entryLabel(entry);
      this.beginRestore('your work of ' + label, { kind: 'history', id });
      const problems = entry.work ? this.restoreWork(entry.work, 'previous work') : await this.applyConfig(U.parseConfig(entry.link.query).values);
      this.cleanText = null;
      const saved = this.saveNow();
      if (saved) this.store.remove('history:' + id);  // it is the work now
      this.restoreDone(saved);
      this.refreshHistory();
      if (!quiet || problems.length)
        this.say(problems.length ? `Restored ${label}, except: ${problems.join('; ')}` : `Restored ${label}. What you had is in File > previous work.`, 8);
      return true;
    }

    /** An entry as a file to keep: its work (and, on top, the current lesson's scene, which File > Import takes) or its link. */
    exportEntry(e) {
      const stamp = new Date(e.savedAt).toISOString().slice(0, 19).replace(/[:T]/g, '-');
      const w = e.work;
      const file = e.link ? { format: 'cspacelab-link', version: 1, savedAt: e.savedAt, url: this.options.home + '?' + e.link.query.replace(/^\?/, '') }
        : Object.assign({ format: WORK_FORMAT, version: 1, savedAt: w.savedAt || e.savedAt, current: w.current, lessons: w.lessons },
                        w.lessons[w.current] && w.lessons[w.current].scene ? { scene: w.lessons[w.current].scene } : {});
      this.downloadJson(`cspacelab-${e.link ? 'link' : 'work'}-${stamp}.json`, file);
    }

    // ---- actions (the app's buttons) --------------------------------------------------------

    async action(name) {
      if (this.dead) return undefined;
      try {
        const history = /^restore-history:(\d{1,2})$/.exec(name);
        if (history) return await this.restoreEntry(this.historyIds[Number(history[1])]);
        switch (name) {
          case 'welcome-seen': return welcomed(true);
          case 'look': {  // File > Display: keep the choice for every later visit
            const state = this.api.pageState({});
            this.showLook(state);
            return storedLook({ scheme: state.scheme, contrast: state.contrast });
          }
          case 'share': return await this.share();
          case 'embed': return await this.embed();
          case 'import': return this.pickFile();
          case 'export-scene': return this.exportScene();
          case 'export-png': return await this.exportPng();
          case 'export-state': return this.exportState();
          case 'reset': return this.resetLesson();
          case 'restore-previous': return await this.restorePrevious();
          case 'open-full': return await this.openFull();
          case 'author': return this.openAuthor ? await this.openAuthor() : undefined;  // set by lab.js
          default: return undefined;
        }
      } catch (e) {
        if (!this.dead) this.api.notify(`${name}: ${e && e.message ? e.message : e}`, 8);
        return undefined;
      }
    }

    /** The link that reproduces what is on screen: {url, problems}. */
    async shareLink(extra = {}, home = this.options.home) {
      // The instructor's lock and hide go on with the link: a student passing it on keeps them.
      extra = Object.assign(this.options.task && this.options.task.text ? { task: this.options.task.text } : {},
                            this.linkRestrictions(), extra);
      const { query, problems } = await U.buildQuery(this.api.snapshot(), this.bundled, extra);
      return { url: home + '?' + query, query, problems };
    }

    async share() {
      const { url, query, problems } = await this.shareLink();
      if (/^file:/i.test(url)) return this.shareFromFile(query, problems);
      const copied = await this.copy(url);
      const lines = [];
      if (copied) lines.push('The link is on the clipboard. It opens this lesson with this scene, these parameters and seed, at this step, zoomed and turned as the views are now.');
      else lines.push('Copy the link below (the browser did not let the page use the clipboard).');
      if (problems.length) lines.push('Not exact: ' + problems.join('; ') + '. Export the scene as JSON to pass it on whole.');
      this.showDialog('Share this state', lines, [{ label: 'Link', value: url, rows: 3 }]);
      this.api.notify(copied ? 'Link copied to the clipboard.' : 'Copy the link from the dialog.', 4);
      return url;
    }

    async embed() {
      const label = this.lessonName(this.api.status().lesson);
      const { query } = await U.buildQuery(this.api.snapshot(), this.bundled, this.linkRestrictions());
      const id = 'lab-' + U.hash(query + Date.now()).slice(0, 6);
      const fields = this.embedSnippets(query, id, label, this.options.task ? this.options.task.text : '');
      const dialog = this.showDialog('Embed this lab', ['This lab as it is now, for a course page. The embed keeps each student\'s own work in their browser.'], fields);
      // The task text (optional), written into both snippets as it is typed.
      const areas = Array.from(dialog.querySelectorAll('.lab-dialog-field textarea'));
      const T = global.CSpaceLabTask;
      this.editField(dialog.querySelector('.lab-dialog-actions'), {
        label: `Task shown above the lab (optional; plain text, each line a paragraph, at most ${T.MAX} characters)`,
        value: this.options.task ? this.options.task.text : '', rows: 3, className: 'lab-dialog-task',
        onInput: (text) => {
          const task = T.normalise(text);
          this.embedSnippets(query, id, label, task.text).forEach((f, i) => { areas[i].value = f.value; });
          return task.problem ? { error: task.problem.replace('are shown', 'go into the snippets') }
                              : { note: `${task.length} of ${T.MAX} characters` };
        },
      });
      return fields;
    }

    /** The Embed dialog's snippets for a state (`query`), an autosave id, a title and a task text. */
    embedSnippets(query, id, label, task) {
      const withTask = task ? '&task=' + U.encodeValue(task) : '';
      // The task sits above the canvas, inside the lab's height: that much taller, the canvas keeps its 600 px.
      const height = 600 + global.CSpaceLabTask.height(global.CSpaceLabTask.normalise(task));
      const title = `title="C-Space Lab: ${escapeAttribute(label)}" allow="clipboard-write"></iframe>`;
      if (this.options.single) {
        const file = location.pathname.split('/').pop() || 'cspacelab-single.html';
        return [{ label: 'Upload this file next to your page, then put this where the lab goes', rows: 3,
                  value: `<iframe src="${escapeAttribute(file + '?' + query + withTask + '&ui=minimal&id=' + id)}" width="100%" height="${height}" ` +
                         `style="border:0" ${title}` }];
      }
      const base = this.options.base;
      // (A line break in an attribute is kept by HTML, but editors of course pages may fold it: &#10;.)
      const taskAttribute = task ? ` data-lab-task="${escapeAttribute(task).replace(/\n/g, '&#10;')}"` : '';
      return [
        { label: 'An iframe (works in any page and most LMSs)', rows: 3,
          value: `<iframe src="${escapeAttribute(base + 'embed.html?' + query + withTask + '&id=' + id)}" width="100%" height="${height}" ` +
                 `style="border:0" ${title}` },
        { label: 'Or a script tag (several labs on one page, each in its own element)', rows: 4,
          value: `<div id="${id}" data-lab="${escapeAttribute(query + '&ui=minimal')}"${taskAttribute} style="height:${height}px"></div>\n` +
                 `<script src="${escapeAttribute(base + 'lab.js')}" defer></script>` },
      ];
    }

    /**
     * An editable field of a dialog, put before `before`: a label, a text field (a textarea when
     * `rows` is given) and a line under it for onInput(text)'s {note} or {error}, run at once and
     * at every change. Returns the field.
     */
    editField(before, { label, value = '', rows = 0, type = 'text', className = '', placeholder = '', onInput }) {
      const input = rows ? el('textarea', { rows, spellcheck: true }) : el('input', { type, spellcheck: false, placeholder });
      input.value = value;
      const note = el('p', { class: 'lab-dialog-note', id: 'lab-dialog-note-' + randomId() });
      note.setAttribute('aria-live', 'polite');
      input.setAttribute('aria-describedby', note.id);
      const wrap = el('label', { class: 'lab-dialog-field lab-dialog-edit ' + className }, [el('span', { text: label }), input]);
      before.parentNode.insertBefore(wrap, before);
      before.parentNode.insertBefore(note, before);
      const update = () => {
        const r = onInput(input.value) || {};
        note.textContent = r.error || r.note || '';
        note.classList.toggle('lab-dialog-error', !!r.error);
        if (r.error) input.setAttribute('aria-invalid', 'true');
        else input.removeAttribute('aria-invalid');
      };
      input.addEventListener('input', update);
      update();
      return input;
    }

    /**
     * Share from a lab opened as a file (file://: the single-file build from disk): that address
     * opens only on this computer. Offers the scene as a file, and a link against the lab's address
     * on the web that the instructor gives (http or https; remembered in this browser).
     */
    shareFromFile(query, problems) {
      const here = location.href.split(/[?#]/)[0];
      let link = null;
      const dialog = this.showDialog('Share this state', [
        `This lab is a file on this computer (${U.excerpt(decodeURI(here), 80).slice(1, -1)}): a link to it opens only here, so no one else can open it.`,
        'Send the scene as a file instead (Export scene, below), or give the address where this lab is on the web ' +
        '(your course site, or where you uploaded this file): the link is then made against it.',
        ...(problems.length ? ['Not exact: ' + problems.join('; ') + '.'] : []),
      ], [{ label: 'Link', value: '', rows: 3 }], [
        { name: 'export-scene', label: 'Export scene (JSON)', primary: true, run: (b) => { this.exportScene(); b.textContent = 'Exported'; } },
      ]);
      const area = dialog.querySelector('.lab-dialog-field textarea');
      const copy = area.closest('.lab-dialog-field').nextSibling.querySelector('button');
      const input = this.editField(area.closest('.lab-dialog-field'), {
        label: 'The lab\'s address on the web (https://… or http://…)', type: 'url', value: shareBase() || '',
        placeholder: 'https://your.site/cspacelab/', className: 'lab-dialog-base',
        onInput: (text) => {
          const r = webAddress(text);
          link = r.url ? r.url + '?' + query : null;
          area.value = link || '';
          copy.disabled = !link;
          if (r.url) shareBase(r.url);
          return r.url ? { note: 'Remembered in this browser for the next Share.' } : { error: r.error };
        },
      });
      input.focus({ preventScroll: true });
      this.api.notify('A link to a file on this computer cannot be sent: see the dialog.', 6);
      return link;
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
        const text = await file.text();
        if (U.tooDeep(text)) return fail(`is nested more than ${U.LIMITS.depth} levels deep`);
        value = JSON.parse(text);
      } catch {
        return fail('is not JSON');
      }
      if (value && typeof value === 'object' && !Array.isArray(value) && typeof value.format === 'string' &&
          value.format.startsWith('cspacelab-') && value.scene && typeof value.scene === 'object')
        value = value.scene;  // an exported roadmap/state file: its scene
      if (!value || typeof value !== 'object' || Array.isArray(value)) return fail('is not a scene (a JSON object)');
      if (this.api.status().restrictions.scene) return fail('was not imported: the scene is fixed by your instructor (lock=scene)');
      // A scene the app cannot draw must not come back at every start: protected like a restore.
      this.beginRestore('an imported scene', { kind: 'work' });
      try {
        this.api.setScene(value);
      } catch (e) {
        if (this.dead) throw e;
        this.endRestore();
        return fail(`is not a scene this lesson can use: ${e.message}`);
      }
      this.cleanText = null;
      this.restoreDone(this.saveNow());
      this.say(`Imported ${name}.`, 4);
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
      this.api.module.preMainLoop = () => this.framePre();
      this.api.module.postMainLoop = () => this.framePost();
    }

    /** Module.preMainLoop: a stopped lab draws no more (false skips the frame). */
    framePre() {
      if (this.dead) return false;
      this.inFrame = true;
      return undefined;
    }

    /**
     * Module.postMainLoop, after each frame and in its task: the WebGL drawing buffer still
     * holds the frame (a PNG needs no preserveDrawingBuffer).
     */
    framePost() {
      this.inFrame = false;
      this.frames += 1;
      if (this.timing.firstFrame === null) this.timing.firstFrame = performance.now();
      if (this.pendingCaptures.length) this.captureNow(this.pendingCaptures.splice(0));
      if (this.onFrame) this.onFrame();  // (lab-print.js keeps a copy of the picture)
      this.frameDone();
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


    /** The lesson back to its default (the app asked first); what it replaced goes to the history. */
    resetLesson() {
      const lesson = this.api.status().lesson;
      const before = this.captureWork();
      this.api.restore({ lesson });
      if (sameJson(before.lessons[lesson], this.api.snapshot(lesson))) return this.api.notify(`${this.lessonName(lesson)} is at its default already.`, 5);
      if (this.store.readable && !this.pushHistory(before, 'reset').ok) {
        this.restoreWork(before);  // without room to keep it, the work stays
        return this.api.notify('Not reset: your work could not be kept first (storage for this site is full). File > Export scene keeps a copy.', 10);
      }
      this.cleanText = null;
      this.refreshHistory();
      this.saveNow();
      // (A lock holds the scene and parameters the link set: reset brings those back.)
      const to = this.restrictions && this.restrictions.lock ? 'to what your instructor set up' : 'to its default';
      return this.say(`${this.lessonName(lesson)} is back ${to}. "Restore my previous work" undoes this. ${this.droppedText()}`, 8);
    }

    /** The newest previous work (the top bar's button): pressed twice, it undoes itself. */
    async restorePrevious() {
      const list = this.refreshHistory();
      if (list.length) return this.restoreEntry(list[0].id);
      this.api.notify('There is no previous work to restore.', 5);
      return false;
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


    // ---- dialogs (DOM, over the canvas: real text fields and buttons) -----------------------

    /**
     * A dialog over the lab: a title, paragraphs, read-only fields with Copy, and buttons
     * ({name, label, primary, run}). closeLabel null: no Close; crash: over a lab that stopped.
     */
    showDialog(title, paragraphs, fields, buttons = [], { closeLabel = 'Close', crash = false } = {}) {
      this.closeDialog();
      const titleId = 'lab-dialog-title-' + randomId();
      const box = el('div', { class: 'lab-dialog-box' });
      box.appendChild(el('h2', { id: titleId, text: title }));
      for (const p of paragraphs) box.appendChild(el('p', { text: p }));
      for (const f of fields) {
        const area = el('textarea', { value: f.value, readOnly: true, rows: f.rows || 3, spellcheck: false });
        area.addEventListener('focus', () => area.select());
        const copy = el('button', { type: 'button', text: 'Copy' });
        copy.addEventListener('click', async () => {
          copy.textContent = (await this.copy(area.value)) ? 'Copied' : 'Select and copy by hand';
        });
        box.appendChild(el('label', { class: 'lab-dialog-field' }, [el('span', { text: f.label }), area]));
        box.appendChild(el('div', { class: 'lab-dialog-row' }, [copy]));
      }
      if (closeLabel) buttons = buttons.concat({ name: 'close', label: closeLabel, close: true, run: () => this.closeDialog() });
      const row = el('div', { class: 'lab-dialog-row lab-dialog-actions' });
      for (const b of buttons) {
        const button = el('button', { type: 'button', text: b.label, class: b.primary ? 'lab-dialog-primary' : b.close ? 'lab-dialog-close' : '' });
        button.dataset.action = b.name;
        button.addEventListener('click', () => b.run(button));
        row.appendChild(button);
      }
      box.appendChild(row);
      const dialog = el('div', { class: 'lab-dialog' + (crash ? ' lab-crash' : ''), role: 'dialog' }, [box]);
      dialog.setAttribute('aria-modal', 'true');
      dialog.setAttribute('aria-labelledby', titleId);
      dialog.addEventListener('keydown', (e) => {
        if (e.key === 'Escape' && closeLabel) this.closeDialog();
        if (e.key !== 'Tab') return;
        // Modal: Tab cycles within the dialog.
        const items = Array.from(dialog.querySelectorAll('button, textarea, input'));
        const i = items.indexOf(document.activeElement);
        const to = e.shiftKey ? (i <= 0 ? items.length - 1 : -1) : (i === items.length - 1 ? 0 : -1);
        if (to >= 0) {
          items[to].focus();
          e.preventDefault();
        }
      });
      dialog.addEventListener('mousedown', (e) => {
        if (e.target === dialog && closeLabel) this.closeDialog();
      });
      this.root.appendChild(dialog);
      this.dialog = dialog;
      const first = dialog.querySelector('textarea') || row.firstChild;
      first.focus({ preventScroll: true });
      return dialog;
    }

    closeDialog() {
      if (!this.dialog) return;
      this.dialog.remove();
      this.dialog = null;
      if (!this.dead) this.canvas.focus({ preventScroll: true });
    }

    /** The three choices for work that could not be restored: {retry, discard} run the first and the last. */
    choices(entry, retry, discard) {
      return [{ name: 'retry', label: 'Try to restore it again', primary: true, run: retry },
              { name: 'export', label: 'Export it (JSON file)', run: (b) => { this.exportEntry(entry); b.textContent = 'Exported'; } },
              { name: 'discard', label: 'Discard it', run: discard }];
    }

    /** A reload whose start restores the marker's work (and opens clean again if it fails again). */
    retryByReload(m) {
      m.choice = 'retry';
      this.store.set('restoring:' + m.tab, JSON.stringify(m));
      global.location.reload();
    }

    /** After a clean start: the work that could not be restored (in the history already) and what to do with it. */
    showRecovery(offer) {
      const m = offer.marker;
      const entry = offer.id ? this.store.entry(offer.id) : this.subjectOf(m);
      if (this.dead || !entry) return;
      const cause = m.trapped ? `the lab stopped (${offer.error})` : 'the page stopped responding';
      this.showDialog('Your work could not be restored', [
        `Last time ${cause} ${offer.what === 'your work' ? 'while you worked' : 'while restoring ' + offer.what}. So that ` +
        'this cannot happen again at every start, the lab opened with the lessons\' defaults.',
        offer.id ? `That work is kept: File > "${this.entryLabel(entry)}".`
                 : 'That work is still the saved work: there is no room to keep it aside, so nothing here is saved until you decide.',
      ], [], this.choices(entry, () => {
        this.closeDialog();
        return offer.id ? this.action('restore-history:' + this.historyIds.indexOf(offer.id)) : this.retryByReload(m);
      }, () => {
        if (offer.id) this.store.remove('history:' + offer.id);
        else this.discard(m);
        this.protectWork = false;
        this.closeDialog();
        this.refreshHistory();
        this.saveNow();
        this.api.notify('Discarded the work that could not be restored.', 5);
      }), { closeLabel: 'Decide later' });
    }

    /** The wasm failed: a message in the lab's place, with the same choices (export and discard need only storage). */
    showCrashPanel() {
      const m = this.marker;
      const subject = m && this.subjectOf(m);
      const status = this.root.querySelector('.lab-status');
      if (status) status.hidden = true;
      const text = [`The lab's engine failed: ${this.deathText}.`];
      let buttons;
      if (subject) {
        text.push(m.what === 'your work' ? `Your work saved in this browser at ${timeText(subject.savedAt)} is kept.`
                                         : `It stopped while restoring ${m.what}, which is kept in this browser.`,
                  '"Try to restore it again" reloads the page; if it fails again, the lab opens with the defaults and offers it once more.');
        buttons = this.choices(subject, () => this.retryByReload(m), () => {
          this.discard(m);
          global.location.reload();
        });
      } else {
        text.push(this.store.readable ? 'Nothing of yours was saved in this browser before it stopped.' : 'This page may not use the browser\'s storage, so nothing was saved.');
        buttons = [{ name: 'reload', label: 'Reload the lab', primary: true, run: () => global.location.reload() }];
      }
      this.showDialog('C-Space Lab stopped', text, [], buttons, { closeLabel: null, crash: true });
    }

    /** What a marker's restore was about, as an entry to export, or null. */
    subjectOf(m) {
      const s = m.source || {};
      const e = s.kind === 'history' && this.store.entry(s.id);
      if (e) return e;
      if (s.kind === 'link') return { savedAt: m.startedAt, link: { query: s.query } };
      const work = this.store.json('work');
      return validWork(work) ? { savedAt: work.savedAt || Date.now(), work } : null;
    }

    /**
     * Drops what a failed restore was about. The work slot is emptied, not removed: it remembers
     * the link it came from, so the same address does not bring the failing state back (for a
     * failed link, the work it would have replaced stays, with the link marked as seen). Once
     * another tab took over (the marker is gone, or it holds the lease), only the tab's own entry goes.
     */
    discard(m) {
      const s = m.source || {};
      const lease = this.store.lease();
      const ours = this.store.get('restoring:' + m.tab) !== null && !(lease && lease.tab !== this.tab && live(lease.beat, LEASE_STALE_MS));
      if (s.kind === 'history') {
        if (ours || s.id === 'tab-' + m.tab) this.store.remove('history:' + s.id);
      } else if (ours) {
        const work = this.store.json('work');
        const kept = s.kind === 'link' && validWork(work) ? work : { format: WORK_FORMAT, version: 1, current: '', lessons: {} };
        kept.config = s.kind === 'link' ? s.config || null : validWork(work) ? work.config : null;
        this.store.set('work', JSON.stringify(kept));
      }
      this.store.remove('restoring:' + m.tab);
    }

    // ---- input: focus, wheel, drag and drop -------------------------------------------------

    focused() {
      // The canvas, or the textarea that takes typed text while a field of the app has the keyboard.
      const a = document.activeElement;
      return (a === this.canvas || a === this.canvas.cslText) && document.hasFocus();
    }

    installInput() {
      const { root, canvas } = this;
      // SDL takes mousedown (and cancels it, which would keep focus away): focus on pointerdown.
      canvas.addEventListener('pointerdown', () => {
        if (document.activeElement !== canvas) canvas.focus({ preventScroll: true });
      });
      canvas.addEventListener('contextmenu', (e) => e.preventDefault());
      // Tab leaves the lab, as it leaves any control: SDL cancels every Tab on the canvas, which
      // made the canvas a keyboard trap. Stopped here, on the way down, SDL never sees it and the
      // browser moves the focus on (to the lab's own HTML, lab-access.js, then the page). While
      // one of the app's text fields has the keyboard, its proxy has the focus and passes its
      // keys to the canvas as untrusted events: those go through, so Tab steps between the
      // app's fields (Esc leaves the field, and then Tab leaves the lab).
      root.addEventListener('keydown', (e) => {
        if (e.key !== 'Tab' || e.ctrlKey || e.altKey || e.metaKey || !e.isTrusted) return;
        if (e.target === canvas && document.activeElement === canvas) e.stopPropagation();
      }, { capture: true });
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
        if (files.length) this.importFile(files[0]).catch(() => {});  // a trap: the crash panel says it
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

  LabShell.isTrap = isTrap;
  global.CSpaceLabShell = LabShell;
})(typeof window !== 'undefined' ? window : globalThis);
