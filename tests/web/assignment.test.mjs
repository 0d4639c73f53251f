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

/**
 * A fake of the app's assignment commands (the contract in docs/web.md, Assignments): an
 * exercise's answer is right when it is 42, a task's when it is "done"; the grade counts points.
 */
function fakeApp() {
  const calls = [];
  const notices = [];
  let a = null;
  let learner = '';
  let current = 0;
  let submitted = false;
  let answers = [];
  const right = (item, answer) => (item.kind === 'exercise' ? answer === 42 : answer === 'done');
  function state() {
    const items = a.items.map((item, index) => {
      const answered = answers[index] !== undefined;
      const ok = answered && right(item, answers[index]);
      return { index, id: `item-${index + 1}`, kind: item.kind, title: item.title || item.problem, prompt: '', points: item.points,
               status: submitted ? (ok ? 'correct' : 'incorrect') : answered ? 'answered' : 'open',
               score: submitted && ok ? item.points : 0, max: item.points };
    });
    const max = items.reduce((s, i) => s + i.max, 0);
    const raw = items.reduce((s, i) => s + i.score, 0);
    return {
      title: a.title, description: a.description, learner, pass: a.pass, current, submitted, items,
      grade: { raw, min: 0, max, scaled: max ? raw / max : 0, completed: submitted, passed: submitted ? raw / max >= a.pass : null },
      interactions: items.map((it) => ({
        id: `${it.id} ${a.items[it.index].problem || it.kind}`, type: it.kind === 'exercise' ? 'numeric' : 'other',
        description: it.title, learner_response: answers[it.index] === undefined ? '' : String(answers[it.index]),
        result: !submitted ? 'neutral' : it.status === 'correct' ? 'correct' : 'incorrect', weighting: it.max })),
      suspend: { current, answers, submitted },
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
        if (args.resume && !Array.isArray(args.resume.answers)) throw new Error('resume: answers missing');
        a = file;
        learner = args.learner || '';
        ({ current = 0, answers = [], submitted = false } = args.resume || {});
        answers = [...answers];
        return state();
      }
      if (cmd === 'assignment_state') return state();
      if (cmd === 'assignment_go') current = args.index;
      else if (cmd === 'assignment_answer') answers[args.index] = args.answer;
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

async function run(win, app) {
  const a = new Assignment(app.root, app.api, 'http://lab.test/assignment.json', win);
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

    // Items 1, 2 and 5 right (1 + 2 + 3 of 8 points), item 3 wrong, 4 unanswered.
    app.api.call('assignment_answer', { index: 0, answer: 42 });
    app.api.call('assignment_answer', { index: 1, answer: 42 });
    app.api.call('assignment_answer', { index: 2, answer: 41.5 });
    app.api.call('assignment_answer', { index: 4, answer: 'done' });
    app.api.call('assignment_go', { index: 4 });
    assert.equal(interaction(lms, 2)[v12 ? 'student_response' : 'learner_response'], '41.5');
    assert.equal(interaction(lms, 2).result, 'neutral', 'no result before submission');
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
      ['item-1_P3', 'numeric', '42', 'correct'],
      ['item-2_P10', 'numeric', '42', 'correct'],
      ['item-3_P12', 'numeric', '41.5', v12 ? 'wrong' : 'incorrect'],
      ['item-4_explore', other, '', v12 ? 'wrong' : 'incorrect'],
      ['item-5_task', other, 'done', 'correct'],
    ]);
    assert.deepEqual(interactions(lms).map((it) => Number(it.weighting)), [1, 2, 2, 0, 3]);
    assert.deepEqual(JSON.parse(record(lms).suspend_data), { current: 4, answers: [42, 42, 41.5, null, 'done'], submitted: true });

    win.dispatchEvent(new Event('pagehide'));
    win.dispatchEvent(new Event('pagehide'));
    a.finish();
    assert.equal(parent.count[v12 ? 'LMSFinish' : 'Terminate'], 1, 'terminated exactly once');
    assert.ok(parent.count[v12 ? 'LMSCommit' : 'Commit'] >= 1, 'committed before terminating');
    assert.equal(v12 ? record(lms).core.exit : record(lms).exit, 'suspend', 'the next launch resumes');
    assert.match(v12 ? record(lms).core.session_time : record(lms).session_time, v12 ? /^\d{2,4}:\d\d:\d\d(\.\d{1,2})?$/ : /^PT\d+H\d+M[\d.]+S$/);
    assert.deepEqual(app.api.notices, [], 'the LMS took every value');
  });

  test(`SCORM ${version}: a relaunch resumes from the suspend data`, async () => {
    const suspend = JSON.stringify({ current: 2, answers: [42, 7], submitted: false });
    const parent = lmsParent(version, v12 ? { suspend_data: suspend, core: { entry: 'resume' } } : { suspend_data: suspend, entry: 'resume' });
    const app = fakeApp();
    await run(fakeWindow(parent), app);
    assert.deepEqual(app.api.calls[0][1].resume, JSON.parse(suspend));
    const lms = parent.lms;
    assert.deepEqual(interactions(lms).slice(0, 2).map((it) => it[v12 ? 'student_response' : 'learner_response']), ['42', '7']);
    // Saved work the file no longer takes: a fresh start, said in the notice.
    const broken = lmsParent(version, { suspend_data: '{"current":1}' });
    const app2 = fakeApp();
    const a2 = await run(fakeWindow(broken), app2);
    assert.equal(a2.state.current, 0);
    assert.match(app2.api.notices.join('\n'), /saved answers do not fit this assignment any more \(resume: answers missing\)/);
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
  app.api.call('assignment_answer', { index: 1, answer: 42 });
  app.api.call('assignment_go', { index: 1 });
  const key = 'cspacelab:v1:assignment:motion-planning-week3';
  assert.deepEqual(JSON.parse(storage.get(key)), { current: 1, answers: [null, 42], submitted: false });
  const again = fakeApp();
  const a = await run(fakeWindow(null, EXAMPLE, storage), again);
  assert.equal(again.api.calls[0][1].learner, undefined);
  assert.deepEqual(again.api.calls[0][1].resume, { current: 1, answers: [null, 42], submitted: false });
  assert.equal(a.state.current, 1);
});

test('what the LMS refuses is one notice per element; a bad file is named and the session ends', async () => {
  const parent = lmsParent('2004');
  const set = parent.lms.SetValue.bind(parent.lms);
  parent.lms.SetValue = (el, value) => (el === 'cmi.score.raw' ? 'false' : set(el, value));
  const app = fakeApp();
  await run(fakeWindow(parent), app);
  app.api.call('assignment_answer', { index: 0, answer: 42 });
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
