// The page around one C-Space Lab instance: what a link or a page's data-lab attribute asks
// for, autosave to localStorage (with a bounded history of previous work that nothing
// overwrites silently), restores that cannot brick the lab, tabs that do not overwrite each
// other, Share and Embed dialogs, import and export, and the input rules of an embed (the wheel
// scrolls the page until the lab has focus; a click gives it focus).
//
// Everything the user or a link supplies is handled as data: parsed with JSON.parse or the
// strict parsers of lab-url.js, shown with textContent or as an <textarea>'s value, passed to the
// app as JSON. Problems become the app's one-line notice; nothing is ever written as HTML.
//
// Storage, per lab (`cspacelab:v1:<page path>:<id>:` + one of):
//   work              the autosaved work of the tab that holds the lease (below)
//   history:<entry>   previous work, one key per entry: what a link, a reset or a restore
//                     replaced, work that could not be restored, another tab's work
//   restoring:<tab>   "a restore is in progress" (what, and where it is kept), until the app
//                     has drawn frames after it: a start that finds one left over opens clean
//   lease             {tab, beat}: the tab that writes `work`; others save to their own entry
// One key per entry (not one list) so that two tabs never rewrite each other's entries, and a
// small entry can still be written when a large one cannot.
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
  // The history of previous work: newest first, at most this many entries and characters (the
  // origin has about 5 million characters in Chromium; the work itself needs room too).
  const HISTORY_MAX_ENTRIES = 10;
  const HISTORY_MAX_CHARS = 1500000;
  // The app's run_to takes at most 1e8 steps (count_arg in src/app/app.cpp); a link's pattern
  // allows 9 digits, so the shell checks the rest.
  const MAX_STEPS = 100000000;
  // A restore is done once the app has drawn this many frames after it (and is not busy).
  const MARKER_FRAMES = 3;
  const HEARTBEAT_MS = 1000;
  // A restore marker or a lease not refreshed for this long belongs to a tab that froze, crashed
  // or closed. Timers of hidden tabs still run about once a second, so these are generous.
  const MARKER_STALE_MS = 6000;
  const LEASE_STALE_MS = 10000;
  // Space a start wants for its saves; when even this does not fit, saving is reported off.
  const PROBE_CHARS = 1024;
  const REASONS = {
    link: 'before a link',
    reset: 'before reset',
    crash: 'could not be restored',
    tab: 'another tab',
    restore: 'before restoring other work',
    previous: 'previous work',
  };
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

  function randomId() {
    const bytes = new Uint8Array(6);
    if (global.crypto && global.crypto.getRandomValues) global.crypto.getRandomValues(bytes);
    else for (let i = 0; i < bytes.length; ++i) bytes[i] = Math.floor(Math.random() * 256);
    return Array.from(bytes, (b) => b.toString(16).padStart(2, '0')).join('');
  }

  function sleep(ms) {
    return new Promise((resolve) => setTimeout(resolve, ms));
  }

  function isQuotaError(e) {
    return !!e && (e.name === 'QuotaExceededError' || e.name === 'NS_ERROR_DOM_QUOTA_REACHED' || e.code === 22 || e.code === 1014);
  }

  /**
   * Whether an exception out of the app is the wasm failing (a trap, a stack overflow in it, a
   * response that is not JSON any more) rather than a command's refusal, which is a plain Error
   * with the app's message.
   */
  function isTrap(e) {
    if (!e || typeof e !== 'object') return false;
    if (typeof WebAssembly === 'object' && WebAssembly.RuntimeError && e instanceof WebAssembly.RuntimeError) return true;
    return e.name === 'RuntimeError' || e instanceof RangeError || e instanceof SyntaxError || e.cslTrap === true;
  }

  function describeError(e) {
    const text = e && e.message ? e.message : String(e);
    return U.excerpt(text.replace(/^(RuntimeError|Error): /, ''), 120).slice(1, -1);
  }

  function timeText(t) {
    const d = new Date(t);
    const now = new Date();
    const time = d.toLocaleTimeString([], { hour: '2-digit', minute: '2-digit', second: '2-digit' });
    if (d.toDateString() === now.toDateString()) return time;
    return d.toLocaleDateString([], { day: 'numeric', month: 'short' }) + ' ' + time;
  }

  function validWork(record) {
    return !!record && record.format === WORK_FORMAT && record.version === 1 && typeof record.current === 'string' &&
      !!record.lessons && typeof record.lessons === 'object' && !Array.isArray(record.lessons);
  }

  /** What decides whether two work records are the same work (not when they were saved). */
  function workText(record) {
    return JSON.stringify({ config: record.config, current: record.current, lessons: record.lessons });
  }

  // ---- storage: one lab's keys, usable without the wasm (the crash panel needs it) ----------

  class WorkStore {
    constructor(scope, id) {
      this.prefix = STORAGE_PREFIX + scope + ':' + id + ':';
      this.storage = null;
      this.dropped = { full: 0, bound: 0 };
      try {
        // Reading and writing are separate questions: a full origin still reads.
        const s = global.localStorage;
        s.getItem(this.prefix + 'work');
        this.storage = s;
      } catch {
        this.storage = null;
      }
    }

    get readable() { return this.storage !== null; }

    key(slot) { return this.prefix + slot; }

    get(slot) {
      if (!this.storage) return null;
      try {
        return this.storage.getItem(this.key(slot));
      } catch {
        return null;
      }
    }

    /** The value parsed, null when absent, undefined when it is there but not JSON. */
    getJson(slot) {
      const text = this.get(slot);
      if (text === null) return null;
      try {
        return JSON.parse(text);
      } catch {
        return undefined;
      }
    }

    remove(slot) {
      if (!this.storage) return;
      try {
        this.storage.removeItem(this.key(slot));
      } catch {
        // nothing to do: the key stays
      }
    }

    /** Slots of this lab that start with `head` (e.g. 'history:'). */
    slots(head) {
      const out = [];
      if (!this.storage) return out;
      const full = this.prefix + head;
      try {
        for (let i = 0; i < this.storage.length; ++i) {
          const k = this.storage.key(i);
          if (k && k.startsWith(full)) out.push(k.slice(this.prefix.length));
        }
      } catch {
        // a storage that went away: none
      }
      return out;
    }

    /**
     * Writes `text` to `slot`. When the origin is full it frees room by dropping the oldest
     * history entries (never those in `keep`) and tries again. {ok, dropped: entries dropped,
     * full: the origin was full}.
     */
    set(slot, text, keep = [], { trim = true } = {}) {
      const result = { ok: false, dropped: 0, full: false };
      if (!this.storage) return result;
      for (;;) {
        try {
          this.storage.setItem(this.key(slot), text);
          result.ok = true;
          return result;
        } catch (e) {
          if (!isQuotaError(e)) return result;
          result.full = true;
          const victim = trim && this.entries().reverse().find((x) => !keep.includes(x.id) && 'history:' + x.id !== slot);
          if (!victim) return result;
          this.remove('history:' + victim.id);
          result.dropped += 1;
          this.dropped.full += 1;
        }
      }
    }

    /** History entries dropped since the last call, {full: to make room, bound: beyond the bounds}. */
    takeDropped() {
      const d = this.dropped;
      this.dropped = { full: 0, bound: 0 };
      return d;
    }

    /** Whether `chars` more characters fit (trimming history if needed): {ok, dropped}. */
    probe(chars = PROBE_CHARS) {
      const r = this.set('probe', 'x'.repeat(chars));
      this.remove('probe');
      return r;
    }

    // -- the history of previous work

    /** Every readable entry, newest first: {id, savedAt, reason, lesson, failed, work | link, size}. */
    entries() {
      const out = [];
      for (const slot of this.slots('history:')) {
        const text = this.get(slot);
        if (text === null) continue;
        let e;
        try {
          e = JSON.parse(text);
        } catch {
          continue;
        }
        if (!e || e.format !== ENTRY_FORMAT || typeof e.savedAt !== 'number') continue;
        const ok = e.work ? validWork(e.work) : !!(e.link && typeof e.link.query === 'string');
        if (!ok) continue;
        out.push(Object.assign(e, { id: slot.slice('history:'.length), size: text.length }));
      }
      return out.sort((a, b) => b.savedAt - a.savedAt || (a.id < b.id ? 1 : -1));
    }

    entry(id) {
      return this.entries().find((e) => e.id === id) || null;
    }

    /**
     * Writes an entry (a new one, or `id` in place), then keeps the history within its bounds by
     * dropping the oldest entries (never this one). {ok, dropped, full}.
     */
    putEntry(id, entry, keep = []) {
      const value = { format: ENTRY_FORMAT, version: 1, savedAt: entry.savedAt || Date.now(), reason: entry.reason,
                      lesson: entry.lesson || '', failed: !!entry.failed };
      if (entry.work) value.work = entry.work;
      else value.link = entry.link;
      const r = this.set('history:' + id, JSON.stringify(value), keep.concat([id]));
      if (r.ok) r.dropped += this.trim(keep.concat([id]));
      return r;
    }

    removeEntry(id) {
      this.remove('history:' + id);
    }

    /** Drops the oldest entries beyond the bounds; returns how many. */
    trim(keep = []) {
      let dropped = 0;
      let list = this.entries();
      let chars = list.reduce((n, e) => n + e.size, 0);
      while (list.length > HISTORY_MAX_ENTRIES || (chars > HISTORY_MAX_CHARS && list.length > 1)) {
        const victim = list.slice().reverse().find((e) => !keep.includes(e.id));
        if (!victim) break;
        this.removeEntry(victim.id);
        list = list.filter((e) => e !== victim);
        chars -= victim.size;
        dropped += 1;
        this.dropped.bound += 1;
      }
      return dropped;
    }

    // -- restore markers and the lease

    markers() {
      const out = [];
      for (const slot of this.slots('restoring:')) {
        const m = this.getJson(slot);
        if (m && m.format === MARKER_FORMAT && typeof m.tab === 'string') out.push(m);
        else if (m !== null) out.push({ format: MARKER_FORMAT, tab: slot.slice('restoring:'.length), unreadable: true });
      }
      return out;
    }

    setMarker(marker, keep = []) {
      return this.set('restoring:' + marker.tab, JSON.stringify(marker), keep);
    }

    clearMarker(tab) {
      this.remove('restoring:' + tab);
    }

    lease() {
      const l = this.getJson('lease');
      return l && typeof l.tab === 'string' && typeof l.beat === 'number' ? l : null;
    }
  }

  /** Whether a lease or a marker was refreshed recently enough to belong to a live tab. */
  function fresh(beat, staleMs, now = Date.now()) {
    return typeof beat === 'number' && now - beat <= staleMs && beat <= now + 60000;
  }

  class LabShell {
    /**
     * root: the [data-lab] element; canvas: its canvas; api: its CSpaceLabApi, or null until
     * attach() (the shell exists before the wasm does, so that a failure while it starts can
     * still offer the saved work). options: {config: query string, ui: 'full'|'minimal',
     * storageId, scope, home: URL of the full lab (share links), base: URL of the folder with the
     * lab's files, single: bool (the single-file build), guardWheel: bool (the wheel scrolls the
     * page until focused)}
     */
    constructor(root, canvas, api, options) {
      this.root = root;
      this.canvas = canvas;
      this.options = options;
      this.store = new WorkStore(options.scope, options.storageId);
      this.tab = randomId();                // this page load: its lease, its marker, its own entry
      this.tabEntryId = 'tab-' + this.tab;  // where this tab saves while another tab holds the lease
      this.role = 'owner';                  // 'owner' writes the work slot, 'second' its own entry
      this.lastSaved = null;
      this.dirtySince = 0;
      this.changedAt = 0;
      this.pendingCaptures = [];
      this.dialog = null;
      this.timing = { ready: performance.now(), firstFrame: null };
      this.problems = [];
      this.frames = 0;           // frames completed (Module.postMainLoop)
      this.inFrame = false;      // between preMainLoop and postMainLoop: a throw there is a trap
      this.marker = null;        // this tab's restore in progress
      this.dead = false;         // the wasm failed: only storage and the DOM are left
      this.cleanText = null;     // the untouched defaults of a clean start (not worth keeping)
      this.saveFailed = false;
      this.pendingNotes = [];    // sentences for the next notice (saves that failed, history dropped)
      this.historyIds = [];
      this.api = null;
      if (api) this.attach(api);
    }

    /**
     * Takes the app's API. Its methods are wrapped on the instance so that the wasm failing in
     * any call (the shell's or a course page's) stops the lab cleanly and says so.
     */
    attach(api) {
      this.api = api;
      const proto = Object.getPrototypeOf(api);
      for (const name of Object.getOwnPropertyNames(proto)) {
        const d = Object.getOwnPropertyDescriptor(proto, name);
        if (name === 'constructor' || !d || typeof d.value !== 'function') continue;
        const shell = this;
        api[name] = function guarded(...args) {
          if (shell.dead) throw new Error('C-Space Lab has stopped: ' + shell.deathText);
          try {
            return proto[name].apply(this, args);
          } catch (e) {
            if (isTrap(e)) shell.trap(e);
            throw e;
          }
        };
      }
      // A trap inside the wasm's own entry point, whoever called it.
      const m = api.module;
      const raw = m._csl_call;
      if (typeof raw === 'function') {
        m._csl_call = (ptr) => {
          try {
            return raw(ptr);
          } catch (e) {
            this.trap(e);
            throw e;
          }
        };
      }
    }

    // ---- start ------------------------------------------------------------------------------

    async init() {
      const api = this.api;
      let notes = [];
      try {
        this.lessons = api.lessons();
        this.bundled = api.bundledScenes();
        this.installFrameHook();
        this.installInput();
        api.pageState({ attached: true, minimal: this.options.ui === 'minimal' });
        api.module.cslPageAction = (name) => setTimeout(() => this.action(name), 0);
        notes = await this.start();
      } catch (e) {
        if (this.dead) return;  // the crash panel says what happened
        console.error('C-Space Lab: the page shell failed', e);
        // Not a trap: a restore under way counts as done once frames are drawn, as usual.
        if (this.marker && this.markerDoneFrame === null) this.restoreDone(false);
        notes.push(`Something went wrong while the lab started (${describeError(e)}); what could be applied is shown.`);
      } finally {
        // Whatever happened above, work from here on is saved.
        if (!this.dead) {
          this.started = true;
          this.startAutosave();
          this.startHeartbeat();
        }
      }
      if (this.dead) return;
      this.refreshHistory();
      if (notes.length) api.notify(notes.join(' '), 15);
    }

    lessonName(id) {
      const l = (this.lessons || []).find((x) => x.id === id);
      return l ? l.name : id;
    }

    /** The start proper: returns the sentences of the notice. */
    async start() {
      const store = this.store;
      const parsed = U.parseConfig(this.options.config);
      const problems = parsed.problems.slice();  // the link's (and the saved work's) bad parts
      const notes = [];
      const configKey = U.hasState(parsed.values) ? U.stateKey(parsed.values) : null;

      if (store.readable) {
        this.migratePrevious();
        this.claimLease();
      }
      // A restore another start left unfinished (it crashed or froze the lab): open clean.
      const leftovers = store.readable ? await this.leftoverMarkers() : [];
      const retry = leftovers.find((m) => m.choice === 'retry');
      const failed = leftovers.filter((m) => m !== retry);
      let offer = null;
      for (const m of failed) {
        const r = this.preserveUnrestored(m);
        if (r.offer && !offer) offer = Object.assign(r.offer, { marker: m });
        if (r.stuck) {
          // No room to keep it aside: the work slot keeps it, and this start saves nothing over it.
          this.protectWork = true;
          offer = { slot: true, marker: m, what: m.what, error: m.error };
        }
      }
      if (retry) store.clearMarker(retry.tab);

      let opened = false;
      let restored = false;
      if (failed.length) {
        // Clean: the lessons' defaults, no restore, and the link counts as seen, so that a reload
        // does not run into it again (the dialog offers it).
        this.config = configKey;
        this.cleanText = workText(this.captureWork());
      } else {
        const saved = this.readWork(problems);
        if (saved) {
          this.beginRestore('your saved work', { kind: 'work' });
          problems.push(...this.restoreWork(saved).map((p) => 'saved work: ' + p));
          restored = true;
        }
        if (configKey && !(saved && saved.config === configKey)) {
          // A link (or a page's data-lab) not seen before: its state, over what was saved. If that
          // replaces work of the same lesson, the work goes to the history first.
          const before = this.captureWork();
          this.beginRestore('the link', { kind: 'link', query: this.options.config, config: configKey });
          problems.push(...(await this.applyConfig(parsed.values)));
          const after = this.captureWork();
          const lesson = after.current;
          if (saved && before.lessons[lesson] && !sameJson(before.lessons[lesson], after.lessons[lesson])) {
            const kept = this.pushHistory(before, 'link');
            opened = kept.ok ? 'kept' : 'lost';
          }
        }
        this.config = configKey;
      }
      if (this.role === 'second') this.lastSaved = workText(this.captureWork());  // only changes go to its entry
      const savedOk = this.saveNow();
      this.restoreDone(savedOk);
      if (retry && retry.source && retry.source.kind === 'history') await this.restoreEntry(retry.source.id, { quiet: true });
      if (retry && retry.source && retry.source.kind === 'link' && retry.source.config !== configKey)
        await this.restoreLink(retry.source.query);

      // Room for what comes: a full origin still restored the work above, and the notice says what failed.
      let full = false;
      if (store.readable) {
        const room = store.probe();
        full = !room.ok;
        this.saveFailed = full;
      }

      if (problems.length) notes.push('Not used from the link: ' + problems.join('; ') + '. The lesson\'s defaults stand in for these.');
      if (opened === 'kept') notes.push('Opened the link. Your previous work is kept: "Restore my previous work" brings it back.');
      if (opened === 'lost') notes.push('Opened the link. Your previous work could not be kept in the history (storage for this site is full); it is still the saved work until this one is saved.');
      if (!store.readable) notes.push('Autosave is off: this page may not use the browser\'s storage.');
      else if (full) notes.push((restored ? 'Your saved work was restored; ' : 'Nothing is lost, but ') + FULL_TEXT);
      const dropped = this.droppedText();
      if (dropped) notes.push(dropped);
      if (!full) notes.push(...this.pendingNotes.splice(0).filter((t) => !t.includes(FULL_TEXT)));
      this.pendingNotes.length = 0;
      if (this.role === 'second') notes.push(this.secondTabText());
      if (failed.length) notes.push('Opened with the lessons\' defaults: your work could not be restored (see the dialog).');
      this.problems = problems;
      if (offer) setTimeout(() => this.showRecovery(offer), 0);
      return notes;
    }

    /** What the history lost since the last notice ('' if nothing). */
    droppedText() {
      const { full, bound } = this.store.takeDropped();
      const n = (k) => `${k} ${k === 1 ? 'entry' : 'entries'}`;
      const out = [];
      if (full) out.push(`The oldest previous work (${n(full)}) was dropped to make room: storage for this site is full.`);
      if (bound) out.push(`The oldest previous work (${n(bound)}) was dropped: the history keeps the newest ${HISTORY_MAX_ENTRIES}.`);
      return out.join(' ');
    }

    secondTabText() {
      return 'This lab is also open in another tab. So that neither tab overwrites the other, ' +
             'this tab saves its work separately: File > "another tab" brings it back.';
    }

    readWork(problems) {
      const record = this.store.getJson('work');
      if (record === null) return null;
      if (validWork(record)) return record;
      problems.push('the saved work in this browser could not be read');
      return null;
    }

    /** Moves the single "previous work" slot of earlier versions into the history. */
    migratePrevious() {
      const old = this.store.getJson('previous');
      if (old === null) return;
      if (validWork(old)) {
        const r = this.pushHistory(old, 'previous', { savedAt: typeof old.savedAt === 'number' ? old.savedAt : Date.now() });
        if (!r.ok) return;  // full: it stays where it is
      }
      this.store.remove('previous');
    }

    /**
     * Markers of other starts whose tab is gone (it crashed, froze or was closed mid-restore),
     * and this tab's own retry request. A marker of a tab that is still restoring is waited for
     * (it ends, proves alive, or goes stale): a start that raced a healthy one must not open clean.
     */
    async leftoverMarkers() {
      const begun = Date.now();
      for (;;) {
        const now = Date.now();
        const markers = this.store.markers();
        const leftover = markers.filter((m) => m.unreadable || m.trapped || m.choice || !fresh(m.beat, MARKER_STALE_MS, now));
        const waiting = markers.filter((m) => !leftover.includes(m) && m.beat - m.startedAt < 2 * HEARTBEAT_MS);
        if (!waiting.length || now - begun > MARKER_STALE_MS + 2 * HEARTBEAT_MS) {
          for (const m of leftover) {
            // Its tab is gone, so is its lease.
            const lease = this.store.lease();
            if (lease && lease.tab === m.tab && this.role === 'second') this.takeLease();
          }
          return leftover;
        }
        await sleep(250);
      }
    }

    /**
     * Keeps what a failed restore was about in the history (storage only): the autosave of the
     * clean start must not overwrite it. Returns {offer: the entry the dialog offers, dropped}.
     */
    preserveUnrestored(m) {
      const store = this.store;
      const source = m.source || { kind: 'work' };
      const info = { what: typeof m.what === 'string' ? m.what : 'your work', error: typeof m.error === 'string' ? m.error : '' };
      let dropped = 0;
      let offer = null;
      const keep = (r) => { dropped += r.dropped; return r; };
      const work = store.getJson('work');
      if (source.kind === 'history' && typeof source.id === 'string' && store.entry(source.id)) {
        const e = store.entry(source.id);
        keep(store.putEntry(e.id, Object.assign(e, { failed: true })));
        offer = Object.assign({ id: e.id }, info);
        if (validWork(work)) keep(this.pushHistory(work, 'restore', { keep: [e.id] }));
      } else if (source.kind === 'link' && typeof source.query === 'string') {
        if (validWork(work)) keep(this.pushHistory(work, 'link'));
        const id = this.newEntryId();
        const r = keep(store.putEntry(id, { reason: 'crash', failed: true, lesson: this.linkLesson(source.query),
                                            link: { query: source.query, config: source.config || null } }));
        if (r.ok) offer = Object.assign({ id }, info);
      } else if (validWork(work)) {
        const r = keep(this.pushHistory(work, 'crash', { failed: true }));
        if (r.ok) offer = Object.assign({ id: r.id }, info);
      }
      // Only once it is safe in the history: a marker that stays is handled by the next start.
      const stuck = !offer && validWork(work);
      if (!stuck) store.clearMarker(m.tab);
      return { offer, dropped, stuck };
    }

    linkLesson(query) {
      const { values } = U.parseConfig(query);
      return values.get('lesson') || '';
    }

    newEntryId() {
      return Date.now().toString(36) + '-' + randomId().slice(0, 6);
    }

    /**
     * Keeps a work record in the history (newest first). The same work kept earlier is replaced,
     * not duplicated. {ok, dropped, full, id}.
     */
    pushHistory(record, reason, { savedAt = Date.now(), failed = false, keep = [] } = {}) {
      const store = this.store;
      if (!store.readable) return { ok: false, dropped: 0, full: false, id: null };
      const text = workText(record);
      const same = store.entries().filter((e) => e.work && !e.id.startsWith('tab-') && !keep.includes(e.id) &&
                                                 workText(e.work) === text);
      const id = this.newEntryId();
      const work = { format: WORK_FORMAT, version: 1, config: record.config === undefined ? null : record.config,
                     current: record.current, lessons: record.lessons, savedAt: record.savedAt || savedAt };
      const r = store.putEntry(id, { reason, savedAt, failed, lesson: record.current, work }, keep);
      if (r.ok) for (const e of same) store.removeEntry(e.id);
      r.id = r.ok ? id : null;
      return r;
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
        else part((e) => `steps ${U.excerpt(raw)} (${e.message})`, () => api.runTo(Number(raw)));
      }
      if (values.has('ui') && !['full', 'minimal'].includes(values.get('ui')))
        problems.push(`ui ${U.excerpt(values.get('ui'))} (full or minimal)`);
      if (values.has('id') && !U.ID.test(values.get('id')))
        problems.push(`id ${U.excerpt(values.get('id'))} (letters, digits, - and _)`);
      return problems;
    }

    // ---- restore markers: a restore that crashes or freezes the lab must not do it again ----

    /** Writes "restore in progress" before a restore: what, and where that work is kept. */
    beginRestore(what, source) {
      if (!this.store.readable) return;
      const now = Date.now();
      this.marker = { format: MARKER_FORMAT, version: 1, tab: this.tab, what, source, startedAt: now, beat: now };
      this.markerDoneFrame = null;
      this.store.setMarker(this.marker);
    }

    /**
     * The restore's synchronous part is over. From here the work is the saved work (or this
     * tab's own entry); the marker goes once frames were drawn (frameDone).
     */
    restoreDone(savedOk) {
      if (!this.marker || this.dead) return;
      if (savedOk) this.marker.source = this.ownSource();
      this.markerDoneFrame = this.frames;
      this.hiddenAtDone = document.visibilityState === 'hidden';
      this.marker.beat = Date.now();
      this.store.setMarker(this.marker);
    }

    ownSource() {
      return this.role === 'owner' ? { kind: 'work' } : { kind: 'history', id: this.tabEntryId };
    }

    /** After each frame: the marker goes once MARKER_FRAMES were drawn and the app is not busy. */
    frameDone() {
      if (!this.marker || this.markerDoneFrame === null || this.dead) return;
      const n = this.frames - this.markerDoneFrame;
      if (n < MARKER_FRAMES || (n > MARKER_FRAMES && n % 5 !== 0)) return;
      let busy = false;
      try {
        busy = !!this.api.status().busy;  // a background run: not done yet (absent: not busy)
      } catch {
        return;
      }
      if (!busy) this.endRestore();
    }

    endRestore() {
      if (!this.marker) return;
      this.store.clearMarker(this.tab);
      this.marker = null;
      this.markerDoneFrame = null;
    }

    /** The lab failed (a trap, an abort): stop, keep what is saved, and offer it in the lab's place. */
    trap(error) {
      if (this.dead) return;
      this.dead = true;
      this.deathText = describeError(error);
      console.error('C-Space Lab stopped:', error);
      clearInterval(this.autosaveTimer);
      clearInterval(this.heartbeatTimer);
      this.closeDialog();
      const store = this.store;
      if (store.readable) {
        // The next start opens clean and offers the work: a crash while working may well have
        // been saved already and would come back with the restore.
        const now = Date.now();
        const m = this.marker || { format: MARKER_FORMAT, version: 1, tab: this.tab, what: 'your work',
                                   source: this.ownSource(), startedAt: now, beat: now };
        m.trapped = true;
        m.error = this.deathText;
        this.marker = m;
        store.setMarker(m);
        this.releaseLease();
      }
      if (this.api && this.api.module) this.api.module.cslPageAction = () => {};
      this.showCrashPanel();
    }

    // ---- tabs: one writes the work slot, the others their own history entry ----------------

    claimLease() {
      const lease = this.store.lease();
      if (lease && lease.tab !== this.tab && fresh(lease.beat, LEASE_STALE_MS)) this.role = 'second';
      else this.takeLease();
    }

    takeLease() {
      this.role = 'owner';
      this.store.set('lease', JSON.stringify({ tab: this.tab, beat: Date.now() }), [], { trim: false });
    }

    releaseLease() {
      const lease = this.store.lease();
      if (lease && lease.tab === this.tab) this.store.remove('lease');
    }

    /** Another tab writes the work slot now: this one keeps its work in its own entry. */
    becomeSecond() {
      if (this.role === 'second' || this.dead) return;
      this.role = 'second';
      this.lastSaved = null;
      if (this.marker) this.marker.source = this.ownSource();
      this.saveNow();
      this.refreshHistory();
      this.say(this.secondTabText(), 12);
    }

    /**
     * The tab that held the lease is gone: this one takes over the work slot. What that tab
     * left there goes to the history first (unless it is this tab's work already).
     */
    becomeOwner() {
      if (this.role === 'owner' || this.dead) return;
      this.takeLease();
      const left = this.store.getJson('work');
      const mine = this.captureWork();
      if (validWork(left) && workText(left) !== workText(mine)) this.pushHistory(left, 'tab');
      this.lastSaved = null;
      if (this.saveNow()) this.store.removeEntry(this.tabEntryId);
      if (this.marker) this.marker.source = this.ownSource();
      this.refreshHistory();
    }

    startHeartbeat() {
      if (!this.store.readable) return;
      const beat = () => {
        if (this.dead) return;
        const now = Date.now();
        const lease = this.store.lease();
        if (this.role === 'owner') {
          if (lease && lease.tab !== this.tab && fresh(lease.beat, LEASE_STALE_MS, now)) this.becomeSecond();
          else this.store.set('lease', JSON.stringify({ tab: this.tab, beat: now }), [], { trim: false });
        } else if (!lease || !fresh(lease.beat, LEASE_STALE_MS, now)) {
          this.becomeOwner();
        }
        if (this.marker) {
          this.marker.beat = now;
          this.store.setMarker(this.marker);
        }
      };
      this.heartbeatTimer = setInterval(beat, HEARTBEAT_MS);
      global.addEventListener('storage', (e) => {
        if (this.dead || e.storageArea !== this.store.storage || !e.key || !e.key.startsWith(this.store.prefix)) return;
        const slot = e.key.slice(this.store.prefix.length);
        if (slot === 'lease') {
          const lease = this.store.lease();
          if (!lease) {
            if (this.role === 'second') this.becomeOwner();
          } else if (lease.tab !== this.tab && this.role === 'owner') {
            this.becomeSecond();
          }
        } else if (slot === 'work' && this.role === 'owner') {
          // Two tabs both thought they held the lease: the lease decides.
          const lease = this.store.lease();
          if (lease && lease.tab !== this.tab) this.becomeSecond();
        } else if (slot.startsWith('history:')) {
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
          if (this.dead) throw e;
          problems.push(`${this.lessonName(id)}: ${e.message}`);
          // Parameters a newer version names differently must not cost the scene: keep what fits.
          try {
            if (snapshot.scene) this.api.restore({ lesson: id, scene: snapshot.scene });
          } catch (e2) {
            if (this.dead) throw e2;
            // the scene itself is bad: the lesson stays as it was
          }
        }
      }
      if (known.has(record.current)) this.api.selectLesson(record.current);
      return problems;
    }

    /**
     * Saves what is on screen: to the work slot (the tab holding the lease) or to this tab's own
     * history entry. True when it is saved (or was already).
     */
    saveNow() {
      if (this.dead || !this.api || !this.store.readable) return false;
      let work;
      try {
        work = this.captureWork();
      } catch {
        return false;  // the app stopped (trap() shows it)
      }
      const text = workText(work);
      if (text === this.lastSaved) return true;
      if (this.role === 'owner') {
        const lease = this.store.lease();
        if (lease && lease.tab !== this.tab && fresh(lease.beat, LEASE_STALE_MS)) {
          this.becomeSecond();  // saves through the branch below
          return this.lastSaved === text;
        }
      }
      const record = Object.assign(work, { savedAt: Date.now() });
      let r;
      if (this.protectWork) r = { ok: false, dropped: 0, full: true };  // holds work that could not be kept aside
      else if (this.role === 'owner') r = this.store.set('work', JSON.stringify(record));
      else r = this.store.putEntry(this.tabEntryId, { reason: 'tab', lesson: record.current, savedAt: record.savedAt, work: record });
      this.dirtySince = 0;
      // What to tell goes with the next notice (say()): an action's own notice would replace it.
      if (this.started) {
        const dropped = this.droppedText();
        if (dropped) this.pendingNotes.push(dropped);
      }
      if (r.ok) {
        this.lastSaved = text;
        if (this.saveFailed && this.started) this.pendingNotes.push('Saving works again.');
        this.saveFailed = false;
        if (this.role === 'second') this.refreshHistory();
        return true;
      }
      if (!this.saveFailed && !this.protectWork)
        this.pendingNotes.push(r.full ? 'Your work is not saved: ' + FULL_TEXT : 'Your work could not be saved in this browser.');
      this.saveFailed = true;
      return false;
    }

    /** The app's notice: `text` and what saving had to tell since the last one. */
    say(text, seconds = 8) {
      const all = [text, ...this.pendingNotes.splice(0)].filter(Boolean).join(' ');
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
          if (this.pendingNotes.length) this.say('', 10);
        }
      };
      this.autosaveTimer = setInterval(poll, AUTOSAVE_POLL_MS);
      // Leaving or hiding the page saves at once: a reload right after an edit keeps it.
      global.addEventListener('pagehide', () => {
        this.saveNow();
        if (this.dead) return;
        // A tab opened in the background and closed unseen drew no frames: its restore did not
        // fail, there was just no chance to show it.
        if (this.marker && this.markerDoneFrame !== null && this.hiddenAtDone && this.frames === this.markerDoneFrame)
          this.endRestore();
        this.releaseLease();
      });
      document.addEventListener('visibilitychange', () => {
        if (document.visibilityState === 'hidden') this.saveNow();
      });
    }

    // ---- the history of previous work --------------------------------------------------------

    entryLabel(e) {
      let why = REASONS[e.reason] || 'previous work';
      if (e.failed && e.reason !== 'crash') why += ', could not be restored';
      const what = e.link ? 'a link' + (e.lesson ? ' to ' + this.lessonName(e.lesson) : '') : this.lessonName(e.lesson || (e.work && e.work.current) || '');
      return `${timeText(e.savedAt)} · ${why} · ${what}`.slice(0, 200);
    }

    /** Tells the app what the history holds (the File menu's list, the top bar's button). */
    refreshHistory() {
      if (this.dead || !this.api) return [];
      const list = this.store.entries().filter((e) => e.id !== this.tabEntryId).slice(0, 20);
      this.historyIds = list.map((e) => e.id);
      try {
        this.api.pageState({
          previous: list.length ? 'your work of ' + new Date(list[0].savedAt).toLocaleString() : '',
          history: list.map((e) => ({ label: this.entryLabel(e) })),
        });
      } catch (e) {
        if (this.dead) return [];
        throw e;
      }
      return list;
    }

    /**
     * Restores an entry of the history; what is on screen goes into the history first, so that
     * nothing is lost and the top bar's button undoes it.
     */
    async restoreEntry(id, { quiet = false } = {}) {
      const entry = id ? this.store.entry(id) : null;
      if (!entry) {
        this.api.notify('That previous work is not there any more (another tab may have restored it).', 6);
        this.refreshHistory();
        return false;
      }
      const current = this.captureWork();
      if (workText(current) !== this.cleanText) {
        const kept = this.pushHistory(current, 'restore', { keep: [id] });
        if (!kept.ok) {
          this.api.notify('Not restored: what is on screen could not be kept first (storage for this site is full). ' +
                          'File > Export scene keeps a copy.', 10);
          return false;
        }
      }
      const label = this.entryLabel(entry);
      let problems;
      if (entry.work) {
        this.beginRestore('your work of ' + label, { kind: 'history', id });
        problems = this.restoreWork(entry.work);
      } else {
        this.beginRestore('a link of ' + label, { kind: 'history', id });
        problems = await this.applyConfig(U.parseConfig(entry.link.query).values);
      }
      this.cleanText = null;
      const saved = this.saveNow();
      if (saved) this.store.removeEntry(id);  // it is the work now
      this.restoreDone(saved);
      this.refreshHistory();
      if (!quiet || problems.length) {
        this.say(problems.length ? `Restored ${label}, except: ${problems.join('; ')}`
                                 : `Restored ${label}. What you had is in File > previous work.`, 8);
      }
      return true;
    }

    /** A retry of a link that failed on another page: applied over fresh lessons. */
    async restoreLink(query) {
      this.beginRestore('the link', { kind: 'link', query, config: null });
      const problems = await this.applyConfig(U.parseConfig(query).values);
      this.restoreDone(this.saveNow());
      if (problems.length) this.api.notify('Not used from the link: ' + problems.join('; '), 10);
    }

    /** The work of a history entry as a file to keep (File > Import reads its scene). */
    entryFile(entry) {
      if (entry.link) {
        return { format: 'cspacelab-link', version: 1, savedAt: entry.savedAt, query: entry.link.query,
                 url: this.options.home + (entry.link.query.startsWith('?') ? '' : '?') + entry.link.query };
      }
      const w = entry.work;
      const current = w.lessons[w.current];
      return Object.assign({ format: WORK_FORMAT, version: 1, savedAt: w.savedAt || entry.savedAt, current: w.current,
                             lessons: w.lessons }, current && current.scene ? { scene: current.scene } : {});
    }

    exportEntry(entry) {
      const file = this.entryFile(entry);
      const stamp = new Date(entry.savedAt).toISOString().slice(0, 19).replace(/[:T]/g, '-');
      this.downloadJson(`cspacelab-${entry.link ? 'link' : 'work'}-${stamp}.json`, file);
      return file;
    }

    // ---- actions (the app's buttons) --------------------------------------------------------

    async action(name) {
      if (this.dead) return undefined;
      try {
        const history = /^restore-history:(\d{1,2})$/.exec(name);
        if (history) return await this.restoreEntry(this.historyIds[Number(history[1])]);
        switch (name) {
          case 'share': return await this.share();
          case 'embed': return await this.embed();
          case 'import': return this.pickFile();
          case 'export-scene': return this.exportScene();
          case 'export-png': return await this.exportPng();
          case 'export-state': return this.exportState();
          case 'reset': return this.resetLesson();
          case 'restore-previous': return await this.restorePrevious();
          case 'open-full': return await this.openFull();
          default: return undefined;
        }
      } catch (e) {
        if (this.dead) return undefined;  // the crash panel says it
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

    /** Emscripten's Module.preMainLoop: a stopped lab draws no more (false skips the frame). */
    framePre() {
      if (this.dead) return false;
      this.inFrame = true;
      return undefined;
    }

    /**
     * Emscripten's Module.postMainLoop, after each frame and in the same task: the WebGL drawing
     * buffer still holds the frame there (no preserveDrawingBuffer needed for a PNG).
     */
    framePost() {
      this.inFrame = false;
      this.frames += 1;
      if (this.timing.firstFrame === null) this.timing.firstFrame = performance.now();
      if (this.pendingCaptures.length) this.captureNow(this.pendingCaptures.splice(0));
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

    /** The lesson back to its default; what it replaced goes to the history (asked first in the app). */
    resetLesson() {
      const lesson = this.api.status().lesson;
      const before = this.captureWork();
      this.api.restore({ lesson });
      const after = this.captureWork();
      if (sameJson(before.lessons[lesson], after.lessons[lesson])) {
        this.api.notify(`${this.lessonName(lesson)} is at its default already.`, 5);
        return;
      }
      const kept = this.pushHistory(before, 'reset');
      if (!kept.ok && this.store.readable) {
        // Nothing is lost: without room to keep it, the work stays.
        this.restoreWork(before);
        this.api.notify(`Not reset: your work could not be kept first (storage for this site is full). File > Export scene keeps a copy.`, 10);
        return;
      }
      this.cleanText = null;
      this.refreshHistory();
      this.saveNow();
      this.say(`${this.lessonName(lesson)} is back to its default. "Restore my previous work" undoes this. ` +
               this.droppedText(), 8);
    }

    /** The newest previous work (the top bar's button); pressed twice, it undoes itself. */
    async restorePrevious() {
      const list = this.refreshHistory();
      if (!list.length) {
        this.api.notify('There is no previous work to restore.', 5);
        return false;
      }
      return this.restoreEntry(list[0].id);
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

    // ---- dialog (DOM, over the canvas: real text fields and buttons) ------------------------

    /**
     * A dialog over the lab: a title, paragraphs, read-only text fields with Copy, and buttons
     * ({label, run, primary}). Options: {closeLabel (null: no Close), crash: over a lab that
     * stopped (opaque, no Escape)}.
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
          copy.textContent = (await this.copy(f.value)) ? 'Copied' : 'Select and copy by hand';
        });
        box.appendChild(el('label', { class: 'lab-dialog-field' }, [el('span', { text: f.label }), area]));
        box.appendChild(el('div', { class: 'lab-dialog-row' }, [copy]));
      }
      const row = el('div', { class: 'lab-dialog-row lab-dialog-actions' });
      for (const b of buttons) {
        const button = el('button', { type: 'button', text: b.label, class: b.primary ? 'lab-dialog-primary' : '' });
        if (b.name) button.dataset.action = b.name;
        button.addEventListener('click', () => b.run(button));
        row.appendChild(button);
      }
      let close = null;
      if (closeLabel) {
        close = el('button', { type: 'button', class: 'lab-dialog-close', text: closeLabel });
        close.dataset.action = 'close';
        close.addEventListener('click', () => this.closeDialog());
        row.appendChild(close);
      }
      box.appendChild(row);
      const dialog = el('div', { class: 'lab-dialog' + (crash ? ' lab-crash' : ''), role: 'dialog' }, [box]);
      dialog.setAttribute('aria-modal', 'true');
      dialog.setAttribute('aria-labelledby', titleId);
      dialog.addEventListener('keydown', (e) => {
        if (e.key === 'Escape' && close) this.closeDialog();
        if (e.key === 'Tab') {
          // Keep the keyboard in the dialog: it is modal.
          const items = Array.from(dialog.querySelectorAll('button, textarea')).filter((x) => !x.disabled);
          const i = items.indexOf(document.activeElement);
          if (e.shiftKey && i <= 0) { items[items.length - 1].focus(); e.preventDefault(); }
          else if (!e.shiftKey && i === items.length - 1) { items[0].focus(); e.preventDefault(); }
        }
      });
      if (close) {
        dialog.addEventListener('mousedown', (e) => {
          if (e.target === dialog) this.closeDialog();
        });
      }
      this.root.appendChild(dialog);
      this.dialog = dialog;
      const first = dialog.querySelector('textarea') || dialog.querySelector('.lab-dialog-actions button');
      if (first) first.focus({ preventScroll: true });
      return dialog;
    }

    closeDialog() {
      if (!this.dialog) return;
      const crash = this.dialog.classList.contains('lab-crash');
      this.dialog.remove();
      this.dialog = null;
      if (!crash && !this.dead) this.canvas.focus({ preventScroll: true });
    }

    /**
     * After a clean start: the work that could not be restored, and what to do with it. It is
     * in the history already, so closing the dialog loses nothing.
     */
    showRecovery(offer) {
      if (this.dead) return;
      // A history entry, or (when there was no room to keep it aside) the work slot itself.
      const entry = offer.id ? this.store.entry(offer.id) : offer.slot ? this.subjectOf({ source: { kind: 'work' } }) : null;
      if (!entry) return;
      const m = offer.marker || {};
      const cause = m.trapped ? `the lab stopped (${offer.error || 'the app failed'})` : 'the page stopped responding';
      const what = offer.what === 'your work' ? 'while you worked' : `while restoring ${offer.what}`;
      const paragraphs = [
        `Last time ${cause} ${what}. So that this cannot happen again at every start, the lab opened with the lessons' defaults.`,
        offer.id ? `That work is kept: File > "${this.entryLabel(entry)}".`
                 : 'That work is still the saved work: there is no room to keep it aside, so changes here are not saved until you decide.',
      ];
      const buttons = [
        { name: 'retry', label: 'Try to restore it again', primary: true, run: async () => {
          this.closeDialog();
          if (!offer.id) {
            m.choice = 'retry';
            this.store.setMarker(m);
            global.location.reload();
            return;
          }
          try {
            await this.restoreEntry(entry.id);
          } catch (e) {
            if (!this.dead) this.api.notify(`Not restored: ${describeError(e)}`, 8);
          }
        } },
        { name: 'export', label: 'Export it (JSON file)', run: (b) => {
          this.exportEntry((offer.id && this.store.entry(offer.id)) || entry);
          b.textContent = 'Exported';
        } },
        { name: 'discard', label: 'Discard it', run: () => {
          if (offer.id) this.store.removeEntry(offer.id);
          else {
            this.discardSubject(m);
            this.protectWork = false;
            this.saveNow();
          }
          this.closeDialog();
          this.refreshHistory();
          this.api.notify('Discarded the work that could not be restored.', 5);
        } },
      ];
      this.showDialog('Your work could not be restored', paragraphs, [], buttons, { closeLabel: 'Decide later' });
    }

    /**
     * The lab failed: a message in its place with the same choices as showRecovery. Export and
     * discard only touch storage and download a file; "try again" reloads the page, whose start
     * restores the work (and opens clean if it fails once more).
     */
    showCrashPanel() {
      const store = this.store;
      const m = this.marker;
      const status = this.root.querySelector('.lab-status');
      if (status) status.hidden = true;
      const subject = m ? this.subjectOf(m) : null;
      const paragraphs = [`The lab's engine failed: ${this.deathText}.`];
      const buttons = [];
      if (subject) {
        paragraphs.push(m.what === 'your work'
          ? `Your work saved in this browser at ${timeText(subject.savedAt)} is kept.`
          : `It stopped while restoring ${m.what}, which is kept in this browser.`);
        buttons.push(
          { name: 'retry', label: 'Try to restore it again', primary: true, run: () => {
            m.choice = 'retry';
            store.setMarker(m);
            global.location.reload();
          } },
          { name: 'export', label: 'Export it (JSON file)', run: (b) => {
            this.exportEntry(subject);
            b.textContent = 'Exported';
          } },
          { name: 'discard', label: 'Discard it', run: () => {
            this.discardSubject(m);
            global.location.reload();
          } });
        paragraphs.push('"Try to restore it again" reloads the page; if it fails again, the lab opens with the defaults and offers it once more.');
      } else {
        paragraphs.push(store.readable ? 'Nothing of yours was saved in this browser before it stopped.' : 'This page may not use the browser\'s storage, so nothing was saved.');
        buttons.push({ name: 'reload', label: 'Reload the lab', primary: true, run: () => global.location.reload() });
      }
      this.showDialog('C-Space Lab stopped', paragraphs, [], buttons, { closeLabel: null, crash: true });
    }

    /** What a marker's restore was about, as a history entry (to export), or null. */
    subjectOf(m) {
      const source = m.source || { kind: 'work' };
      if (source.kind === 'history' && source.id) {
        const e = this.store.entry(source.id);
        if (e) return e;
      }
      if (source.kind === 'link' && typeof source.query === 'string')
        return { savedAt: m.startedAt || Date.now(), link: { query: source.query }, lesson: this.linkLesson(source.query) };
      const work = this.store.getJson('work');
      if (validWork(work)) return { savedAt: work.savedAt || Date.now(), work, lesson: work.current };
      return null;
    }

    /** Drops what the failed restore was about, so that the next start does not meet it again. */
    discardSubject(m) {
      const store = this.store;
      const source = m.source || { kind: 'work' };
      if (source.kind === 'history' && source.id) {
        store.removeEntry(source.id);
      } else if (source.kind === 'link') {
        // The link is dropped, not the work it would have replaced: that work remembers the link
        // as seen, so the same address does not apply it again.
        const work = store.getJson('work');
        const record = validWork(work) ? work : { format: WORK_FORMAT, version: 1, current: '', lessons: {} };
        record.config = source.config || null;
        store.set('work', JSON.stringify(record));
      } else {
        // Emptied, not removed: the work remembers which link it came from, so that the same
        // address does not bring the failing state back.
        const work = store.getJson('work');
        store.set('work', JSON.stringify({ format: WORK_FORMAT, version: 1, config: validWork(work) ? work.config : null,
                                           current: '', lessons: {} }));
      }
      store.clearMarker(m.tab);
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
