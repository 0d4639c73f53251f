// Assignment mode: a lab configured with assignment=URL (lab-url.js) works through that file and,
// inside an LMS, reports to it through SCORM. Loaded by lab.js only for such a lab.
//
// The app grades (assignment_open/_state/_submit, docs/web.md, Assignments); this file carries
// what it says to the LMS: it finds the LMS's API object in a parent frame or the opener (SCORM
// 1.2's window.API, 2004's window.API_1484_11), initialises, opens the assignment for the LMS's
// learner id with the suspend data of the last session, and on every 'cspacelab:assignment'
// event of the lab's root writes score, status, one interaction per item (and one more per
// check: a journal) and the suspend data, then commits. It terminates once, on a pagehide not
// into the back-forward cache. Without an LMS the suspend data goes to localStorage instead.
// Anything the LMS refuses becomes the app's one-line notice: the lab itself goes on. Nothing
// received from the LMS is evaluated.
'use strict';

(function (global) {
  const FIND_LIMIT = 10;  // frames up from this one (ADL's sample searches 500; real LMSs nest 2-4)
  const COMMIT_DELAY_MS = 1000;  // an LMS's commit may be a synchronous request: not on every click
  const STORE_PREFIX = 'cspacelab:v1:assignment:';

  // What differs between the versions: element names and vocabularies.
  const V12 = {
    version: '1.2', init: 'LMSInitialize', finish: 'LMSFinish', get: 'LMSGetValue', set: 'LMSSetValue',
    commit: 'LMSCommit', error: 'LMSGetLastError', errorText: 'LMSGetErrorString',
    learner: 'cmi.core.student_id', score: 'cmi.core.score.', exit: 'cmi.core.exit', time: 'cmi.core.session_time',
    response: 'student_response', types: { numeric: 'numeric', 'fill-in': 'fill-in', other: 'performance' },
    results: { correct: 'correct', incorrect: 'wrong', neutral: 'neutral' },
  };
  const V2004 = {
    version: '2004', init: 'Initialize', finish: 'Terminate', get: 'GetValue', set: 'SetValue',
    commit: 'Commit', error: 'GetLastError', errorText: 'GetErrorString',
    learner: 'cmi.learner_id', score: 'cmi.score.', exit: 'cmi.exit', time: 'cmi.session_time',
    response: 'learner_response', types: { numeric: 'numeric', 'fill-in': 'fill-in', other: 'other' },
    results: { correct: 'correct', incorrect: 'incorrect', neutral: 'neutral' },
  };

  /** The API object named `name` in `win` or a frame above it, or null (other origins are skipped). */
  function search(win, name) {
    for (let i = 0; win && i <= FIND_LIMIT; ++i) {
      try {
        if (win[name] && typeof win[name] === 'object') return win[name];
      } catch {
        // a frame of another origin: its API is not ours to use
      }
      if (win.parent === win) break;
      win = win.parent;
    }
    return null;
  }

  /**
   * The LMS: {api, v} or null. ADL's search: up the parents, then the opener's. `prefer` ('1.2' or
   * '2004', the package's version) is tried first: an LMS may offer both objects.
   */
  function findLms(win, prefer) {
    const order = prefer === '1.2' ? [V12, V2004] : [V2004, V12];
    for (const v of order) {
      const name = v === V12 ? 'API' : 'API_1484_11';
      let api = search(win, name);
      if (!api) {
        try {
          if (win.opener) api = search(win.opener, name);
        } catch {
          // an opener of another origin
        }
      }
      if (api && typeof api[v.init] === 'function') return { api, v };
    }
    return null;
  }

  /**
   * The URL of a configuration's assignment file: `raw` resolved against the page's address
   * `pageHref`. Only a relative URL of the page's own origin is taken (the file decides what a
   * student is graded on, so a link must not point it at another site). Throws an Error saying why.
   */
  function assignmentUrl(raw, pageHref) {
    const text = String(raw);
    if (text === '' || /[\u0000-\u001f\\]/.test(text)) throw new Error(`${quote(text)} is not a relative URL of this site`);
    if (/^[a-z][a-z0-9+.-]*:/i.test(text) || text.startsWith('//'))
      throw new Error(`${quote(text)} is not on this site: an assignment is a relative URL such as assignment.json`);
    let url;
    try {
      url = new URL(text, pageHref);
    } catch {
      throw new Error(`${quote(text)} is not a relative URL of this site`);
    }
    if (url.origin !== new URL(pageHref).origin)
      throw new Error(`${quote(text)} is not on this site: an assignment is a relative URL such as assignment.json`);
    return url.href;
  }

  /** A short printable excerpt of untrusted text for a message. */
  function quote(text) {
    const s = String(text);
    return JSON.stringify(s.length > 40 ? s.slice(0, 40) + '…' : s);
  }

  /** A number as a decimal the LMS takes (no exponent, at most 4 decimals). */
  function decimal(x) {
    return String(Math.round(Number(x) * 10000) / 10000);
  }

  const DECIMAL = /^-?\d{1,10}(\.\d{1,18})?$/;  // what both versions take as a number

  /** A value as the LMS's text: strings as they are, anything else as JSON, none as ''. */
  function text(x) {
    return x === undefined || x === null ? '' : typeof x === 'string' ? x : JSON.stringify(x);
  }

  /** An identifier both versions take: letters, digits and - _ . : only, at most 250 characters. */
  function identifier(text, index) {
    const s = String(text || '').replace(/[^A-Za-z0-9_.:-]/g, '_').slice(0, 250);
    return /[A-Za-z0-9]/.test(s) ? s : 'item-' + (index + 1);
  }

  /** SCORM's elapsed time: 1.2 HHHH:MM:SS.SS, 2004 PTnHnMnS. */
  function elapsed(ms, v) {
    const s = Math.max(0, ms) / 1000;
    const h = Math.floor(s / 3600);
    const m = Math.floor((s % 3600) / 60);
    const sec = (s % 60).toFixed(2);
    if (v === V2004) return `PT${h}H${m}M${sec}S`;
    return `${String(h).padStart(4, '0')}:${String(m).padStart(2, '0')}:${sec.padStart(5, '0')}`;
  }

  /** A 2004 fill-in response is CMILangString250 per [,] node; a leading { opens {lang=}: so [;], (. */
  function fillIn(s) {
    return s.replace(/\[,\]/g, '[;]').replace(/^\{/, '(').slice(0, 250);
  }

  /**
   * The values one state writes, in order ([element, value]): score, status, interactions (the
   * items', then `journal`'s from index `base`: see report), suspend data. SCORM 1.2's raw score
   * is compared with the manifest's masteryscore (0-100) and kept within 0-100 by runtimes, so
   * 1.2 reports core's scaled as a percentage; 2004 reports points and scaled. Passed/failed
   * only once submitted (core's `completed`: all attempted).
   */
  function valuesOf(state, v, journal = [], base = 0) {
    const g = state.grade || {};
    const out = [];
    const result = state.submitted === true ? (g.passed ? 'passed' : 'failed') : null;
    if (v === V12) {
      const pct = Math.round(10000 * Math.max(0, Math.min(1, Number(g.scaled) || 0))) / 100;
      out.push([v.score + 'raw', decimal(pct)], [v.score + 'min', '0'], [v.score + 'max', '100']);
      out.push(['cmi.core.lesson_status', result || 'incomplete']);
    } else {
      out.push([v.score + 'raw', decimal(g.raw)], [v.score + 'min', decimal(g.min)], [v.score + 'max', decimal(g.max)]);
      out.push([v.score + 'scaled', decimal(Math.max(-1, Math.min(1, g.scaled)))]);
      out.push(['cmi.completion_status', result ? 'completed' : 'incomplete']);
      out.push(['cmi.success_status', result || 'unknown']);
    }
    const its = state.interactions || [];
    its.concat(journal).forEach((it, n) => {
      const p = `cmi.interactions.${n < its.length ? n : base + n - its.length}.`;
      const response = text(it.learner_response);
      const correct = text(it.correct_response);
      // A numeric item answered with text ("pi/2") is reported as fill-in: the runtime refuses
      // text as a numeric response.
      const numeric = it.type === 'numeric' && [response, correct].every((x) => x === '' || DECIMAL.test(x));
      const type = numeric ? v.types.numeric : it.type === 'numeric' ? v.types['fill-in'] : v.types[it.type] || v.types.other;
      out.push([p + 'id', identifier(it.id, n)], [p + 'type', type]);
      if (v === V2004 && it.description) out.push([p + 'description', String(it.description).slice(0, 250)]);
      // An unanswered item has no response (an empty one is not a number); 1.2 holds 255 characters.
      if (response !== '')
        out.push([p + v.response, v === V12 ? response.slice(0, 255) : type === 'fill-in' ? fillIn(response) : response.slice(0, 4000)]);
      // The right answer where its pattern is plain: a number, or text without 2004's {…} and [,]
      // syntax. (A task's condition is not a pattern: runtimes refuse some as type mismatches.)
      if (correct !== '' && (type === 'numeric' || (type === 'fill-in' && !/[{}[\]]/.test(correct))))
        out.push([p + 'correct_responses.0.pattern', correct.slice(0, 250)]);
      if (v.results[it.result]) out.push([p + 'result', v.results[it.result]]);
      if (typeof it.weighting === 'number') out.push([p + 'weighting', decimal(it.weighting)]);
      // 2004's time(second,10,0) puts a zone only after hundredths: 2026-11-27T20:10:05.12Z.
      if (it.at) out.push(v === V12 ? [p + 'time', it.at.toTimeString().slice(0, 8)] : [p + 'timestamp', it.at.toISOString().slice(0, 22) + 'Z']);
    });
    if (state.suspend !== undefined) out.push(['cmi.suspend_data', JSON.stringify(state.suspend)]);
    return out;
  }

  class LabAssignment {
    /**
     * root: the lab's element; api: its CSpaceLabApi; url: the assignment's (assignmentUrl);
     * win: the window it runs in (the unit tests pass a fake).
     */
    constructor(root, api, url, win = global) {
      this.win = win;
      this.root = root;
      this.api = api;
      this.url = url;
      this.lms = null;
      this.written = new Map();  // element -> the value last set (each is written when it changes)
      this.refused = new Set();  // elements whose refusal was shown (once each)
      this.state = null;
      this.tries = null;   // each item's tries when last reported
      this.journal = [];   // an interaction per try (report)
      this.base = 0;       // where the journal starts: after what the LMS holds (null: unknown)
      this.started = Date.now();
      this.finished = false;
      this.commitTimer = null;
      this.onState = (event) => this.report(event.detail);
      this.onHide = (event) => (event && event.persisted ? this.commit() : this.finish());
      // Back from the bfcache after Terminate: SCORM allows no second Initialize.
      this.onShow = (event) => {
        if (event && event.persisted && this.finished)
          this.notify('This page has stopped reporting to your course: reload the page to keep reporting to your course.');
      };
    }

    notify(text) {
      try {
        this.api.notify(text);
      } catch {
        console.warn('C-Space Lab:', text);  // the app has stopped: its crash panel says so
      }
    }

    /** Calls the LMS; a failure (false, an exception) is shown once per element and returns null. */
    lmsCall(method, ...args) {
      const { api, v } = this.lms;
      let result;
      let why = '';
      try {
        result = api[method](...args);
      } catch (e) {
        why = e && e.message ? e.message : String(e);
      }
      if (!why && result !== false && result !== 'false') return result;
      const what = method === v.set || method === v.get ? args[0] : method;
      if (!why) {
        try {
          const code = api[v.error]();
          why = `${code}: ${api[v.errorText](code)}`;
        } catch {
          why = 'no reason given';
        }
      }
      if (!this.refused.has(what)) {
        this.refused.add(what);
        this.notify(`The LMS (SCORM ${v.version}) refused ${what}${method === v.set ? ' = ' + String(args[1]).slice(0, 40) : ''} (${why}).`);
      }
      return null;
    }

    /** By the file's URL (two courses' "Week 3" differ) and seed_key. */
    get storeKey() {
      const a = this.assignment || {};
      return STORE_PREFIX + this.url + (a.seed_key ? '#' + a.seed_key : '');
    }

    async start() {
      let text;
      try {
        // A redirect must not lead the file off this site (assignmentUrl's rule); one within it may.
        const response = await this.win.fetch(this.url, { credentials: 'same-origin' });
        if (!response.ok) throw new Error(`HTTP ${response.status}`);
        if (response.url && new URL(response.url).origin !== new URL(this.url).origin) throw new Error('redirected off this site');
        text = await response.text();
        this.assignment = JSON.parse(text);
      } catch (e) {
        this.notify(`The assignment ${this.url.split('/').pop()} could not be loaded (${e.message}).`);
        return null;
      }
      this.lms = findLms(this.win, this.root.getAttribute('data-lab-scorm'));
      let learner;
      let resume = null;
      if (this.lms) {
        const { v } = this.lms;
        if (this.lmsCall(v.init, '') === null) {
          this.lms = null;  // the LMS would not start a session: run as a plain page
        } else {
          this.win.addEventListener('pagehide', this.onHide);
          this.win.addEventListener('pageshow', this.onShow);
          learner = this.lmsCall(v.get, v.learner) || undefined;
          resume = this.lmsCall(v.get, 'cmi.suspend_data') || null;
          // Unread, a journal would overwrite an earlier session's entries: then none is kept.
          const count = String(this.lmsCall(v.get, 'cmi.interactions._count'));
          this.base = /^\d+$/.test(count) ? +count : null;
        }
      }
      if (!this.lms) {
        try {
          resume = this.win.localStorage.getItem(this.storeKey);
        } catch {
          resume = null;  // no storage (privacy mode): the work lasts as long as the page
        }
      }
      let parsed;
      try {
        parsed = resume ? JSON.parse(resume) : undefined;
      } catch {
        parsed = undefined;
      }
      let state;
      try {
        state = this.open(text, learner, parsed);
      } catch (e) {
        if (parsed === undefined) {
          this.notify('The assignment cannot be used: ' + e.message);
          this.finish();
          return null;
        }
        // Saved work the assignment no longer takes (the file changed): start afresh, and say so.
        try {
          state = this.open(text, learner, undefined);
          this.notify('Your saved answers do not fit this assignment any more (' + e.message + '); it starts afresh.');
        } catch (e2) {
          this.notify('The assignment cannot be used: ' + e2.message);
          this.finish();
          return null;
        }
      }
      this.root.addEventListener('cspacelab:assignment', this.onState);
      this.report(state);
      return state;
    }

    open(text, learner, resume) {
      const args = { assignment: text };
      if (learner !== undefined) args.learner = String(learner);
      if (resume !== undefined) args.resume = resume;
      return this.api.call('assignment_open', args);
    }

    /** Writes what changed in `state` to the LMS (or storage) and commits soon. */
    report(state) {
      if (!state || typeof state !== 'object' || this.finished) return;
      this.state = state;
      if (!this.lms) {
        try {
          if (state.suspend !== undefined) this.win.localStorage.setItem(this.storeKey, JSON.stringify(state.suspend));
        } catch {
          // storage full or off: the page keeps the work while it is open
        }
        return;
      }
      const { v } = this.lms;
      // Each item's interaction shows its latest answer; a try also adds one of its own after
      // them, which later tries leave as it was: the LMS keeps every check and when it was made
      // (SCORM allows 250). Tries from an earlier session were written then.
      const its = state.interactions || [];
      const base = Math.max(this.base, its.length);
      (state.items || []).forEach((item, i) => {
        const first = this.tries && this.base !== null ? this.tries[i] + 1 : Infinity;
        for (let t = first; t <= item.tries && base + this.journal.length < 250; t++) {
          // No weighting: a log of tries, not items an LMS would count again.
          this.journal.push({ ...its[i], id: `${its[i].id}-try-${t}`, description: `(try ${t}) ${item.title}`,
                              at: new Date(), weighting: undefined });
        }
      });
      this.tries = (state.items || []).map((item) => item.tries);
      let changed = false;
      for (const [element, value] of valuesOf(state, v, this.journal, base)) {
        if (this.written.get(element) === value) continue;
        if (this.lmsCall(v.set, element, value) !== null) this.written.set(element, value);
        changed = true;
      }
      if (changed && this.commitTimer === null)
        this.commitTimer = setTimeout(() => this.commit(), COMMIT_DELAY_MS);
    }

    commit() {
      clearTimeout(this.commitTimer);
      this.commitTimer = null;
      if (this.lms && !this.finished) this.lmsCall(this.lms.v.commit, '');
    }

    /** Ends the LMS session, once: the time spent, suspend (so the next launch resumes), commit, finish. */
    finish() {
      if (this.finished || !this.lms) return;  // a plain page keeps saving (it may come back from the back-forward cache)
      this.root.removeEventListener('cspacelab:assignment', this.onState);
      const { v } = this.lms;
      // A finished assignment is kept for review: the next launch shows the answers again.
      this.lmsCall(v.set, v.exit, 'suspend');
      this.lmsCall(v.set, v.time, elapsed(Date.now() - this.started, v));
      this.commit();
      this.finished = true;
      this.lmsCall(v.finish, '');
      this.win.removeEventListener('pagehide', this.onHide);
    }
  }

  LabAssignment.assignmentUrl = assignmentUrl;
  LabAssignment.findLms = findLms;
  LabAssignment.valuesOf = valuesOf;
  LabAssignment.elapsed = elapsed;
  LabAssignment.V12 = V12;
  LabAssignment.V2004 = V2004;
  global.CSpaceLabAssignment = LabAssignment;
  if (typeof module !== 'undefined' && module.exports) module.exports = LabAssignment;
})(typeof window !== 'undefined' ? window : globalThis);
