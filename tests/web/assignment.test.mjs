// web/lab-assignment.js under node, against a real SCORM runtime (npm scorm-again, both versions)
// in a fake parent frame and a small fake of the app's assignment commands: what reaches the LMS
// (each element read back from the runtime), resume from suspend data, one Initialize and one
// Terminate per load, a plain page's localStorage, refusals shown as a notice.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';

const require = createRequire(import.meta.url);
const Assignment = require('../../web/lab-assignment.js');
const { Scorm12API, Scorm2004API } = await import('scorm-again');
const EXAMPLE = fs.readFileSync(fileURLToPath(new URL('../../docs/assignment-example.json', import.meta.url)), 'utf8');

// What core answers for learner stu-17 (`cspacelab assignment grade docs/assignment-example.json
// --answers ANSWERS --learner stu-17`, ANSWERS = GRADED below): the fake's right answers and the
// grade the fake is checked against.
const GRADE = JSON.parse(fs.readFileSync(fileURLToPath(new URL('./fixtures/assignment-grade-stu-17.json', import.meta.url)), 'utf8'));
const SOLVED = { solved: true, params: { samples: 40 }, scene_name: 'A passage through a thick wall' };
const GRADED = [[0, 'T^2'], [1, '3.05'], [2, '7'], [4, SOLVED]];

/**
 * A fake of the app's assignment commands following core's rules (assignment_grade.cpp,
 * assignment_session.cpp): an item is attempted when answered readably (an explore item when
 * visited); completed = every item attempted; raw = the points of the right ones; scaled =
 * raw / max (1 when max is 0 and completed); passed = scaled >= pass, whether submitted or not;
 * an interaction's result is neutral until attempted; suspend = {v: 1, c, s, a: [[item, answer, tries]]}.
 * Right answers are core's for stu-17 (GRADE); a task is answered here with a state ({index,
 * state}) where the app reads its lesson's.
 */
function fakeApp() {
  const calls = [];
  const notices = [];
  let a = null;
  let learner = '';
  let current = 0;
  let submitted = false;
  let answers = [];
  let tries = [];  // every answer but a visit counts one (core spares a typo or a repeat: not needed here)
  const notation = (item) => /^P[1-7]$/.test(item.problem);
  function judge(item, index, answer) {
    if (answer === undefined) return { attempted: false, correct: false };
    if (item.kind === 'explore') return { attempted: true, correct: true };
    if (item.kind === 'task') {
      return { attempted: true,
               correct: answer.solved === true && answer.params.samples <= 50 && answer.scene_name === item.check.all[2].equals };
    }
    const expected = GRADE.items[index].expected;
    if (notation(item)) return { attempted: answer.trim() !== '', correct: answer.trim() === expected };
    const x = Number(answer);
    return { attempted: Number.isFinite(x), correct: Math.abs(x - expected) <= (item.tolerance ?? 0.005) };
  }
  function state() {
    const graded = a.items.map((item, i) => judge(item, i, answers[i]));
    const items = a.items.map((item, index) => {
      const g = graded[index];
      const points = item.points ?? (item.kind === 'explore' ? 0 : 1);
      return { index, id: `item-${index + 1}`, kind: item.kind, title: item.title || item.problem, points,
               status: answers[index] === undefined ? 'open' : item.kind === 'explore' ? 'viewed' : !g.attempted ? 'answered' : g.correct ? 'correct' : 'incorrect',
               score: g.correct ? points : 0, max: points, tries: tries[index] || 0 };
    });
    const max = items.reduce((s, i) => s + i.max, 0);
    const raw = items.reduce((s, i) => s + i.score, 0);
    const completed = graded.every((g) => g.attempted);
    const scaled = max > 0 ? raw / max : completed ? 1 : 0;
    const pass = a.pass ?? 0.6;
    const response = (item, x) => (x === undefined ? '' : item.kind === 'explore' ? 'visited' : item.kind === 'task' ? `solved: ${x.solved}` : x);
    return {
      title: a.title, description: a.description, learner, pass, current, submitted, items,
      grade: { raw, min: 0, max, scaled, completed, passed: scaled >= pass },
      interactions: items.map((it, i) => ({
        id: it.id, description: it.title, weighting: it.max,
        type: it.kind !== 'exercise' ? 'other' : notation(a.items[i]) ? 'fill-in' : 'numeric',
        learner_response: response(a.items[i], answers[i]),
        result: !graded[i].attempted ? 'neutral' : graded[i].correct ? 'correct' : 'incorrect' })),
      suspend: { v: 1, c: current, s: submitted ? 1 : 0,
                 a: answers.flatMap((x, i) => (x === undefined ? [] : [[i, a.items[i].kind === 'explore' ? 1 : x].concat(tries[i] || [])])) },
    };
  }
  const api = {
    calls, notices,
    notify(text) { notices.push(text); },
    call(cmd, args = {}) {
      calls.push([cmd, args]);
      if (cmd === 'assignment_open') {
        const file = typeof args.assignment === 'string' ? JSON.parse(args.assignment) : args.assignment;
        if (!Array.isArray(file.items)) throw new Error('items: missing');
        const r = args.resume;
        if (r && r.v !== 1) throw new Error('resume: v: 1, the version of the suspend object');
        if (r && !Array.isArray(r.a)) throw new Error('resume: a: a list of [item, answer]');
        a = file;
        learner = args.learner || '';
        current = r ? r.c : 0;
        submitted = r ? r.s === 1 : false;
        answers = [];
        tries = [];
        for (const [i, x, t] of r ? r.a : []) answers[i] = x, tries[i] = t ?? 0;
        return state();
      }
      if (cmd === 'assignment_state') return state();
      if (submitted && cmd === 'assignment_answer') throw new Error('assignment_answer: submitted');
      if (cmd === 'assignment_go') current = args.index;
      else if (cmd === 'assignment_answer') {
        answers[args.index] = a.items[args.index].kind === 'explore' ? 1 : args.answer ?? args.state;
        if (a.items[args.index].kind !== 'explore') tries[args.index] = (tries[args.index] || 0) + 1;
      }
      else if (cmd === 'assignment_submit') submitted = true;
      else throw new Error('unknown command ' + cmd);
      const s = state();
      root.dispatchEvent(new CustomEvent('cspacelab:assignment', { detail: s }));
      return s;
    },
  };
  const root = new EventTarget();
  root.getAttribute = (name) => root.attrs[name] ?? null;
  root.attrs = {};
  return { api, root };
}

/** Answers item `index` in the fake: a task with a lesson state, anything else with text. */
function answer(app, index, x) {
  return app.api.call('assignment_answer', typeof x === 'object' ? { index, state: x } : { index, answer: x });
}

test('the fake grades as core does (the recorded cspacelab assignment grade)', async () => {
  const app = fakeApp();
  await run(fakeWindow(null), app, 'http://lab.test/a.json');
  for (const [i, x] of GRADED) answer(app, i, x);
  const g = app.api.call('assignment_state').grade;
  assert.deepEqual(g, { ...GRADE.score, completed: GRADE.completed, passed: GRADE.passed });
  assert.deepEqual(app.api.call('assignment_state').items.map((it) => it.score), GRADE.items.map((it) => it.points));
  assert.equal(GRADE.completed, false, 'the explore item is not visited');
  assert.equal(GRADE.passed, true, 'core passes what is not complete: the adapter must wait for submission');
});

/** A window in a frame under `parent`, fetching the assignment text `file`. */
function fakeWindow(parent, file = EXAMPLE, storage = new Map()) {
  const win = new EventTarget();
  win.parent = parent || win;
  win.opener = null;
  win.fetch = async () => ({ ok: true, status: 200, text: async () => file });
  win.localStorage = { getItem: (k) => (storage.has(k) ? storage.get(k) : null), setItem: (k, v) => storage.set(k, String(v)) };
  return win;
}

/** A parent frame playing the LMS with scorm-again, counting each method's calls. */
function lmsParent(version, cmi) {
  const api = version === '1.2' ? new Scorm12API({ logLevel: 5 }) : new Scorm2004API({ logLevel: 5 });
  if (cmi) api.loadFromJSON(cmi);
  const count = {};
  for (const m of ['LMSInitialize', 'LMSFinish', 'LMSCommit', 'Initialize', 'Terminate', 'Commit']) {
    if (typeof api[m] !== 'function') continue;
    const f = api[m].bind(api);
    api[m] = (...args) => { count[m] = (count[m] || 0) + 1; return f(...args); };
  }
  const parent = { count, lms: api };
  parent.parent = parent;
  parent[version === '1.2' ? 'API' : 'API_1484_11'] = api;
  return parent;
}

async function run(win, app, url = 'http://lab.test/assignment.json') {
  const a = new Assignment(app.root, app.api, url, win);
  await a.start();
  return a;
}

for (const version of ['1.2', '2004']) {
  const v12 = version === '1.2';
  const get = (lms, el) => (v12 ? lms.LMSGetValue(el) : lms.GetValue(el));
  // The runtime's whole record (write-only elements such as a 1.2 response or cmi.exit included).
  const record = (lms) => lms.renderCMIToJSONObject().cmi;
  const interactions = (lms) => Object.values(record(lms).interactions);
  const interaction = (lms, n) => interactions(lms)[n];

  test(`SCORM ${version}: score, status and interactions reach the runtime; Terminate once`, async () => {
    const parent = lmsParent(version, v12 ? { core: { student_id: 'stu-17' } } : { learner_id: 'stu-17' });
    const middle = { parent };  // the LMS's page nests the SCO two frames down
    const win = fakeWindow(middle);
    const app = fakeApp();
    const a = await run(win, app);
    const lms = parent.lms;
    assert.equal(parent.count[v12 ? 'LMSInitialize' : 'Initialize'], 1);
    assert.equal(app.api.calls[0][0], 'assignment_open');
    assert.equal(app.api.calls[0][1].learner, 'stu-17', 'the LMS learner id goes to the app');
    assert.equal(app.api.calls[0][1].resume, undefined, 'nothing to resume on a first launch');
    if (v12) assert.equal(get(lms, 'cmi.core.lesson_status'), 'incomplete');
    else assert.deepEqual([get(lms, 'cmi.completion_status'), get(lms, 'cmi.success_status')], ['incomplete', 'unknown']);
    assert.equal(interactions(lms).length, 5);

    const status = () => (v12 ? [get(lms, 'cmi.core.lesson_status')] : [get(lms, 'cmi.completion_status'), get(lms, 'cmi.success_status')]);
    // Items 1, 2 and 5 right (1 + 2 + 3 of 8 points), item 3 wrong, 4 (explore, 0 points) not visited.
    for (const [i, x] of GRADED) answer(app, i, x);
    app.api.call('assignment_go', { index: 4 });
    assert.equal(interaction(lms, 2)[v12 ? 'student_response' : 'learner_response'], '7');
    assert.equal(interaction(lms, 2).result, v12 ? 'wrong' : 'incorrect', 'core judges an attempt before submission');
    assert.deepEqual(status(), v12 ? ['incomplete'] : ['incomplete', 'unknown'], 'core says passed; not submitted');
    // All answered, not submitted: core's grade is completed and passed; the LMS hears neither.
    answer(app, 3);
    const g = app.api.call('assignment_state').grade;
    assert.deepEqual([g.completed, g.passed], [true, true]);
    assert.deepEqual(status(), v12 ? ['incomplete'] : ['incomplete', 'unknown'], 'answers may still change');
    app.api.call('assignment_submit', {});

    const pts = 6 / 8;
    if (v12) {
      assert.deepEqual(['raw', 'min', 'max'].map((k) => Number(get(lms, 'cmi.core.score.' + k))), [pts * 100, 0, 100]);
      assert.equal(get(lms, 'cmi.core.lesson_status'), 'passed');
    } else {
      assert.deepEqual(['raw', 'min', 'max', 'scaled'].map((k) => Number(get(lms, 'cmi.score.' + k))), [6, 0, 8, pts]);
      assert.equal(get(lms, 'cmi.completion_status'), 'completed');
      assert.equal(get(lms, 'cmi.success_status'), 'passed');
    }
    const rows = interactions(lms).map((it) => [it.id, it.type, it[v12 ? 'student_response' : 'learner_response'], it.result]);
    const other = v12 ? 'performance' : 'other';
    assert.deepEqual(rows, [
      ['item-1', 'fill-in', 'T^2', 'correct'],
      ['item-2', 'numeric', '3.05', 'correct'],
      ['item-3', 'numeric', '7', v12 ? 'wrong' : 'incorrect'],
      ['item-4', other, 'visited', 'correct'],
      ['item-5', other, 'solved: true', 'correct'],
      // The journal: a check each (a visit is none), in the order made.
      ['item-1-try-1', 'fill-in', 'T^2', 'correct'],
      ['item-2-try-1', 'numeric', '3.05', 'correct'],
      ['item-3-try-1', 'numeric', '7', v12 ? 'wrong' : 'incorrect'],
      ['item-5-try-1', other, 'solved: true', 'correct'],
    ]);
    assert.deepEqual(interactions(lms).slice(0, 5).map((it) => Number(it.weighting)), [1, 2, 2, 0, 3]);
    assert.ok(interactions(lms).slice(5).every((it) => !it.weighting), 'a try has no weighting: the LMS must not count it again');
    for (const it of interactions(lms).slice(5)) {
      if (v12) assert.match(it.time, /^\d\d:\d\d:\d\d$/);
      else assert.ok(Math.abs(Date.parse(it.timestamp) - Date.now()) < 60000, it.timestamp);
    }
    if (!v12) assert.match(interaction(lms, 7).description, /^\(try 1\) .+$/);
    assert.deepEqual(JSON.parse(record(lms).suspend_data),
                     { v: 1, c: 4, s: 1, a: [[0, 'T^2', 1], [1, '3.05', 1], [2, '7', 1], [3, 1], [4, SOLVED, 1]] });

    win.dispatchEvent(new Event('pagehide'));
    win.dispatchEvent(new Event('pagehide'));
    a.finish();
    assert.equal(parent.count[v12 ? 'LMSFinish' : 'Terminate'], 1, 'terminated exactly once');
    assert.ok(parent.count[v12 ? 'LMSCommit' : 'Commit'] >= 1, 'committed before terminating');
    assert.equal(v12 ? record(lms).core.exit : record(lms).exit, 'suspend', 'the next launch resumes');
    assert.match(v12 ? record(lms).core.session_time : record(lms).session_time, v12 ? /^\d{2,4}:\d\d:\d\d(\.\d{1,2})?$/ : /^PT\d+H\d+M[\d.]+S$/);
    assert.deepEqual(app.api.notices, [], 'the LMS took every value');
  });

  test(`SCORM ${version}: the journal keeps every check, across sessions`, async () => {
    const parent = lmsParent(version);
    const app = fakeApp();
    const a = await run(fakeWindow(parent), app);
    answer(app, 2, '9');
    answer(app, 2, '7');
    const lms = parent.lms;
    const row = (it) => [it.id, it[v12 ? 'student_response' : 'learner_response'], it.result];
    const wrong = v12 ? 'wrong' : 'incorrect';
    assert.deepEqual(interactions(lms).slice(2).map(row), [['item-3', '7', wrong], ['item-4', '', 'neutral'], ['item-5', '', 'neutral'],
                                                            ['item-3-try-1', '9', wrong], ['item-3-try-2', '7', wrong]]);
    a.finish();
    // The next launch: the LMS holds 7 interactions and the suspend data; the journal goes on after them.
    const parent2 = lmsParent(version, { ...record(lms), ...(v12 ? { core: { entry: 'resume' } } : { entry: 'resume' }) });
    const app2 = fakeApp();
    await run(fakeWindow(parent2), app2);
    const right = String(GRADE.items[2].expected);
    answer(app2, 2, right);
    const rows = interactions(parent2.lms).map(row);
    assert.equal(rows.length, 8, 'resumed tries are not journaled again');
    assert.deepEqual(rows.slice(2), [['item-3', right, 'correct'], ['item-4', '', 'neutral'], ['item-5', '', 'neutral'],
                                     ['item-3-try-1', '9', wrong], ['item-3-try-2', '7', wrong], ['item-3-try-3', right, 'correct']]);
    assert.deepEqual(app2.api.notices, []);
  });

  test(`SCORM ${version}: where the LMS does not say how many interactions it holds, no journal`, async () => {
    // Written from a guessed index, a journal would overwrite an earlier session's entries.
    const parent = lmsParent(version);
    const getValue = v12 ? 'LMSGetValue' : 'GetValue';
    const real = parent.lms[getValue].bind(parent.lms);
    parent.lms[getValue] = (el) => (el === 'cmi.interactions._count' ? '' : real(el));
    const app = fakeApp();
    await run(fakeWindow(parent), app);
    answer(app, 2, '9');
    answer(app, 2, '7');
    assert.deepEqual(interactions(parent.lms).map((it) => it.id), ['item-1', 'item-2', 'item-3', 'item-4', 'item-5']);
    assert.equal(interaction(parent.lms, 2)[v12 ? 'student_response' : 'learner_response'], '7', 'the item itself is reported');
    assert.deepEqual(app.api.notices, []);
  });

  test(`SCORM ${version}: a relaunch resumes from the suspend data`, async () => {
    const suspend = JSON.stringify({ v: 1, c: 2, s: 0, a: [[0, 'T^2'], [1, '7']] });
    const parent = lmsParent(version, v12 ? { suspend_data: suspend, core: { entry: 'resume' } } : { suspend_data: suspend, entry: 'resume' });
    const app = fakeApp();
    await run(fakeWindow(parent), app);
    assert.deepEqual(app.api.calls[0][1].resume, JSON.parse(suspend));
    const lms = parent.lms;
    assert.deepEqual(interactions(lms).slice(0, 2).map((it) => it[v12 ? 'student_response' : 'learner_response']), ['T^2', '7']);
    // Saved work the file no longer takes: a fresh start, said in the notice.
    const broken = lmsParent(version, { suspend_data: '{"v":1,"c":1}' });
    const app2 = fakeApp();
    const a2 = await run(fakeWindow(broken), app2);
    assert.equal(a2.state.current, 0);
    assert.match(app2.api.notices.join('\n'), /saved answers do not fit this assignment any more \(resume: a: a list of \[item, answer\]\)/);
  });
}

test('the LMS object: frames up, the opener, the package version first, other origins skipped', () => {
  const api12 = { LMSInitialize() {} };
  const api04 = { Initialize() {} };
  const top = { API: api12, API_1484_11: api04 };
  top.parent = top;
  const child = { parent: { parent: top } };
  assert.equal(Assignment.findLms(child, '1.2').api, api12);
  assert.equal(Assignment.findLms(child, '2004').api, api04);
  assert.equal(Assignment.findLms(child, null).api, api04, 'without a hint, 2004 first (as ADL\'s wrappers do)');
  const foreign = {};
  Object.defineProperty(foreign, 'API', { get() { throw new Error('SecurityError'); } });
  foreign.parent = foreign;
  assert.equal(Assignment.findLms({ parent: foreign }, '1.2'), null);
  const popup = { parent: null, opener: child };
  popup.parent = popup;
  assert.equal(Assignment.findLms(popup, '1.2').api, api12, 'a SCO in a window the LMS opened');
  let deep = top;
  for (let i = 0; i < 12; ++i) deep = { parent: deep };
  assert.equal(Assignment.findLms(deep, '1.2'), null, 'the search stops after 10 frames');
});

test('without an LMS: a plain page that resumes from localStorage', async () => {
  const storage = new Map();
  const app = fakeApp();
  await run(fakeWindow(null, EXAMPLE, storage), app);
  answer(app, 1, '3.05');
  app.api.call('assignment_go', { index: 1 });
  const key = 'cspacelab:v1:assignment:http://lab.test/assignment.json#motion-planning-week3';
  assert.deepEqual([...storage.keys()], [key], 'by the file\'s URL and its seed_key');
  assert.deepEqual(JSON.parse(storage.get(key)), { v: 1, c: 1, s: 0, a: [[1, '3.05', 1]] });
  const again = fakeApp();
  const a = await run(fakeWindow(null, EXAMPLE, storage), again);
  assert.equal(again.api.calls[0][1].learner, undefined);
  assert.deepEqual(again.api.calls[0][1].resume, { v: 1, c: 1, s: 0, a: [[1, '3.05', 1]] });
  assert.equal(a.state.current, 1);
});

test('what the LMS refuses is one notice per element; a bad file is named and the session ends', async () => {
  const parent = lmsParent('2004');
  const set = parent.lms.SetValue.bind(parent.lms);
  parent.lms.SetValue = (el, value) => (el === 'cmi.score.raw' ? 'false' : set(el, value));
  const app = fakeApp();
  await run(fakeWindow(parent), app);
  answer(app, 0, 'T^2');
  app.api.call('assignment_submit', {});
  assert.equal(app.api.notices.length, 1, app.api.notices.join('\n'));
  assert.match(app.api.notices[0], /^The LMS \(SCORM 2004\) refused cmi\.score\.raw = 0 \(\d+: /);
  assert.equal(parent.lms.GetValue('cmi.completion_status'), 'completed', 'the rest still reached the LMS');

  const bad = lmsParent('1.2');
  const app2 = fakeApp();
  const a = await run(fakeWindow(bad, '{"title": "x"}'), app2);
  assert.equal(a.state, null);
  assert.deepEqual(app2.api.notices, ['The assignment cannot be used: items: missing']);
  assert.equal(bad.count.LMSFinish, 1);

  const app3 = fakeApp();
  const win = fakeWindow(null);
  win.fetch = async () => ({ ok: false, status: 404 });
  await run(win, app3);
  assert.deepEqual(app3.api.notices, ['The assignment assignment.json could not be loaded (HTTP 404).']);
});

test('elapsed time in each version\'s syntax', () => {
  assert.equal(Assignment.elapsed(3723450, Assignment.V12), '0001:02:03.45');
  assert.equal(Assignment.elapsed(3723450, Assignment.V2004), 'PT1H2M3.45S');
});

test('assignment=: a relative URL of the page\'s own site only', () => {
  const page = 'https://lab.example.edu/course/launch.html?x=1';
  assert.equal(Assignment.assignmentUrl('assignment.json', page), 'https://lab.example.edu/course/assignment.json');
  assert.equal(Assignment.assignmentUrl('week3/a%20b.json', page), 'https://lab.example.edu/course/week3/a%20b.json');
  assert.equal(Assignment.assignmentUrl('../a.json', page), 'https://lab.example.edu/a.json');
  for (const raw of ['https://evil.example/a.json', '//evil.example/a.json', 'javascript:alert(1)', 'data:,{}',
                     'HTTPS://lab.example.edu/a.json'])
    assert.throws(() => Assignment.assignmentUrl(raw, page), /is not on this site: an assignment is a relative URL such as assignment\.json/, raw);
  for (const raw of ['', 'a\\b', 'a\nb'])
    assert.throws(() => Assignment.assignmentUrl(raw, page), /is not a relative URL of this site/, JSON.stringify(raw));
});

test('a numeric item answered with text is reported as fill-in; plain right answers only; every value is one the runtimes take', () => {
  const state = {
    grade: { raw: 3, min: 0, max: 8, scaled: 0.375, completed: true, passed: false },
    interactions: [
      { id: 'item-1', type: 'numeric', description: 'P10', learner_response: 'pi/2', result: 'incorrect', weighting: 2, correct_response: '1.5708' },
      { id: 'item-2', type: 'numeric', description: 'P12', learner_response: '7', result: 'correct', weighting: 2, correct_response: '7' },
      { id: 'item-3', type: 'fill-in', description: 'P3', learner_response: 'T^2', result: 'correct', weighting: 1, correct_response: 'T^2' },
      { id: 'item 4', type: 'other', description: '', learner_response: '', result: 'neutral', weighting: 0 },
      { id: 'item-5', type: 'other', description: 'task', learner_response: 'solved: true', result: 'incorrect', weighting: 3,
        correct_response: { solved: true, samples: { max: 50 } } },
    ],
    suspend: { v: 1 },
  };
  for (const [V, Api] of [[Assignment.V12, Scorm12API], [Assignment.V2004, Scorm2004API]]) {
    const values = new Map(Assignment.valuesOf(state, V));
    const fillIn = 'fill-in';
    assert.equal(values.get('cmi.interactions.0.type'), fillIn, 'text in a numeric item');
    assert.equal(values.get('cmi.interactions.1.type'), 'numeric');
    assert.equal(values.get('cmi.interactions.3.id'), 'item_4');
    assert.ok(!values.has(`cmi.interactions.3.${V.response}`), 'no response for an unanswered item');
    assert.equal(values.get('cmi.interactions.1.correct_responses.0.pattern'), '7');
    assert.equal(values.get('cmi.interactions.2.correct_responses.0.pattern'), 'T^2');
    assert.ok(!values.has('cmi.interactions.4.correct_responses.0.pattern'), 'a task\'s condition is no pattern');
    const lms = new Api({ logLevel: 5 });
    assert.equal(lms[V.init](''), 'true');
    for (const [element, value] of values)
      assert.equal(lms[V.set](element, value), 'true', `SCORM ${V.version} takes ${element} = ${value} (${lms[V.error]()})`);
  }
});

test('1.2 score: core\'s scaled as a percentage (1 for an assignment of 0 points, once completed)', () => {
  const score = (grade, submitted = true) => new Map(Assignment.valuesOf({ submitted, grade }, Assignment.V12));
  const zero = score({ raw: 0, min: 0, max: 0, scaled: 1, completed: true, passed: true });
  assert.deepEqual(['raw', 'min', 'max'].map((k) => zero.get('cmi.core.score.' + k)), ['100', '0', '100']);
  assert.equal(zero.get('cmi.core.lesson_status'), 'passed');
  assert.equal(score({ raw: 2, min: 0, max: 3, scaled: 2 / 3, completed: true, passed: true }).get('cmi.core.score.raw'), '66.67');
  const blank = score({ raw: 0, min: 0, max: 3, scaled: 0, completed: false, passed: false });
  assert.equal(blank.get('cmi.core.lesson_status'), 'failed', 'submitted with a blank item: failed, not incomplete');
});

test('2004 fill-in responses: at most 250 characters, no leading { or [,] (CMILangString250 per node)', () => {
  const long = 'Q = ' + 'S^1 x '.repeat(60) + 'R^2';
  const state = { submitted: false, grade: { raw: 0, min: 0, max: 3, scaled: 0, completed: true, passed: false }, interactions: [
    { id: 'item-1', type: 'fill-in', learner_response: '{x | x in R^2 [,] |x| < 1}' },
    { id: 'item-2', type: 'fill-in', learner_response: long },
    { id: 'item-3', type: 'numeric', learner_response: '{1}' },
  ] };
  const values = new Map(Assignment.valuesOf(state, Assignment.V2004));
  assert.equal(values.get('cmi.interactions.0.learner_response'), '(x | x in R^2 [;] |x| < 1}');
  assert.equal(values.get('cmi.interactions.1.learner_response'), long.slice(0, 250));
  assert.equal(values.get('cmi.interactions.2.type'), 'fill-in');
  const lms = new Scorm2004API({ logLevel: 5 });
  lms.Initialize('');
  for (const [element, value] of values)
    assert.equal(lms.SetValue(element, value), 'true', `SCORM 2004 takes ${element} = ${value} (${lms.GetLastError()})`);
  assert.equal(lms.GetValue('cmi.interactions.1.learner_response').length, 250);
  const v12 = new Map(Assignment.valuesOf(state, Assignment.V12));
  assert.equal(v12.get('cmi.interactions.0.student_response'), '{x | x in R^2 [,] |x| < 1}', '1.2 keeps the text');
});

test('back-forward cache: a persisted pagehide commits only; back after Terminate, a notice', async () => {
  for (const version of ['1.2', '2004']) {
    const [fin, com] = version === '1.2' ? ['LMSFinish', 'LMSCommit'] : ['Terminate', 'Commit'];
    const parent = lmsParent(version);
    const win = fakeWindow(parent);
    const app = fakeApp();
    const a = await run(win, app);
    answer(app, 0, 'T^2');
    const hide = (persisted) => win.dispatchEvent(Object.assign(new Event('pagehide'), { persisted }));
    const show = (persisted) => win.dispatchEvent(Object.assign(new Event('pageshow'), { persisted }));
    hide(true);
    assert.equal(parent.count[fin], undefined, `${version}: not terminated into the cache`);
    assert.equal(parent.count[com], 1, `${version}: committed`);
    show(true);
    answer(app, 1, '3.05');
    a.commit();
    assert.equal(parent.count[com], 2, `${version}: still reporting after coming back`);
    assert.deepEqual(app.api.notices, []);
    hide(false);
    assert.equal(parent.count[fin], 1);
    show(true);
    assert.deepEqual(app.api.notices, ['This page has stopped reporting to your course: reload the page to keep reporting to your course.']);
    assert.equal(parent.count[version === '1.2' ? 'LMSInitialize' : 'Initialize'], 1, 'no second Initialize');
  }
});

test('assignment=: a redirect off this site is refused', async () => {
  const http = await import('node:http');
  // Another origin (another port) that serves a file, as a site a link would point it at would.
  const other = http.createServer((req, res) => res.writeHead(200, { 'access-control-allow-origin': '*' }).end(EXAMPLE));
  await new Promise((ok) => other.listen(0, '127.0.0.1', ok));
  const server = http.createServer((req, res) => {
    if (req.url === '/away.json') res.writeHead(302, { location: `http://127.0.0.1:${other.address().port}/a.json` }).end();
    else if (req.url === '/here.json') res.writeHead(302, { location: '/assignment.json' }).end();
    else res.writeHead(200, { 'content-type': 'application/json' }).end(EXAMPLE);
  });
  await new Promise((ok) => server.listen(0, '127.0.0.1', ok));
  const base = `http://127.0.0.1:${server.address().port}`;
  try {
    const away = fakeApp();
    const a = await run(Object.assign(fakeWindow(null), { fetch: (url, init) => fetch(url, init) }), away, base + '/away.json');
    assert.equal(a.state, null);
    assert.deepEqual(away.api.notices, ['The assignment away.json could not be loaded (redirected off this site).']);
    const here = fakeApp();
    await run(Object.assign(fakeWindow(null), { fetch: (url, init) => fetch(url, init) }), here, base + '/here.json');
    assert.deepEqual(here.api.notices, [], 'a redirect within the site is followed');
    assert.equal(here.api.calls[0][0], 'assignment_open');
    // What a fetch that follows a redirect reports (response.url) is checked too.
    const win = fakeWindow(null);
    win.fetch = async () => ({ ok: true, status: 200, url: 'http://evil.example/a.json', text: async () => EXAMPLE });
    const app = fakeApp();
    await run(win, app);
    assert.deepEqual(app.api.notices, ['The assignment assignment.json could not be loaded (redirected off this site).']);
    const plain = fakeApp();
    await run(Object.assign(fakeWindow(null), { fetch: (url, init) => fetch(url, init) }), plain, base + '/assignment.json');
    assert.deepEqual(plain.api.notices, [], 'no redirect: loaded');
  } finally {
    server.close();
    other.close();
  }
});

test('without an LMS: two courses\' files of one title keep their work apart', async () => {
  const storage = new Map();
  const file = JSON.stringify({ ...JSON.parse(EXAMPLE), seed_key: undefined });
  for (const course of ['robotics', 'planning']) {
    const app = fakeApp();
    await run(fakeWindow(null, file, storage), app, `http://lab.test/${course}/week3.json`);
    answer(app, 1, course === 'robotics' ? '3.05' : '1');
  }
  assert.deepEqual([...storage.keys()], ['cspacelab:v1:assignment:http://lab.test/robotics/week3.json',
                                         'cspacelab:v1:assignment:http://lab.test/planning/week3.json']);
  const again = fakeApp();
  await run(fakeWindow(null, file, storage), again, 'http://lab.test/robotics/week3.json');
  assert.deepEqual(again.api.calls[0][1].resume.a, [[1, '3.05', 1]]);
});
