// The SCORM packages in a stand-in LMS: each version's zip (scripts/scorm-package.mjs) unpacked
// and served, its launch page in an iframe of a parent page that provides the LMS's API object
// with a real SCORM runtime (npm scorm-again) under a strict Content-Security-Policy. The example
// assignment is worked through with the mouse on the app's assignment card (an answer typed,
// an item opened, Submit) and the app's assignment commands, answers computed here
// independently (as tests/cli/assignment.test.mjs does); then what the lab reported is read back
// from the runtime: score, completion and success, each interaction. A reload of the iframe is
// a new launch (the stand-in LMS hands the suspend data back): the same answers and item come
// back, and each launch initialised and terminated exactly once.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { DIST, CLI, launchBrowser, collectErrors, cli, screenshot } from './lib/harness.mjs';
import { serve } from '../../scripts/static-server.mjs';
import { readZip } from '../../scripts/zip.mjs';
import { s1, minGrid } from '../lib/homework-answers.mjs';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const EXAMPLE = path.join(ROOT, 'docs/assignment-example.json');
const LEARNER = 'ann@example.edu';
const SCORM_AGAIN = path.join(ROOT, 'node_modules/scorm-again/dist/scorm-again.min.js');

// The stand-in LMS: a page with scorm-again and an iframe. Every launch gets a fresh API object
// holding the learner and the last session's suspend data (entry=resume after exit=suspend), as
// an LMS does; each counts its Initialize/Terminate/Commit.
const LMS_HTML = `<!doctype html>
<html lang="en"><head><meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="default-src 'self'; script-src 'self'; frame-src 'self'; style-src 'self'; img-src data:">
<link rel="icon" href="data:,">
<title>Stand-in LMS</title>
<script src="scorm-again.min.js"></script>
<script src="lms.js"></script>
</head><body><iframe id="sco" title="course" width="1280" height="760"></iframe></body></html>
`;
const LMS_JS = `'use strict';
(function () {
  const version = new URLSearchParams(location.search).get('v');
  const names = version === '1.2' ? ['LMSInitialize', 'LMSFinish', 'LMSCommit'] : ['Initialize', 'Terminate', 'Commit'];
  window.lms = { version, launches: [] };
  function launch(previous) {
    const api = version === '1.2' ? new Scorm12API({ logLevel: 5 }) : new Scorm2004API({ logLevel: 5 });
    const cmi = version === '1.2' ? { core: { student_id: ${JSON.stringify(LEARNER)}, student_name: 'Ann' } }
                                  : { learner_id: ${JSON.stringify(LEARNER)}, learner_name: 'Ann' };
    if (previous) {
      // An LMS keeps the attempt's interactions as well (the journal goes on after them).
      cmi.suspend_data = previous.suspend_data;
      cmi.interactions = previous.interactions;
      const resume = (version === '1.2' ? previous.core.exit : previous.exit) === 'suspend' ? 'resume' : '';
      if (version === '1.2') cmi.core.entry = resume; else cmi.entry = resume;
    }
    api.loadFromJSON(cmi);
    const record = { calls: { [names[0]]: 0, [names[1]]: 0, [names[2]]: 0 }, cmi: null };
    for (const m of names) {
      const f = api[m].bind(api);
      api[m] = (...args) => {
        record.calls[m] += 1;
        const result = f(...args);
        if (m === names[1]) {
          record.cmi = api.renderCMIToJSONObject().cmi;
          launch(record.cmi);
        }
        return result;
      };
    }
    window.lms.launches.push(record);
    window.lms.api = api;
    window[version === '1.2' ? 'API' : 'API_1484_11'] = api;
  }
  launch(null);
  document.addEventListener('DOMContentLoaded', () => { document.getElementById('sco').src = 'course/launch.html'; });
})();
`;

/** The packages, built once from the site under test. */
function buildPackages() {
  const out = fs.mkdtempSync(path.join(os.tmpdir(), 'csl-scorm-e2e-'));
  const r = spawnSync(process.execPath, [path.join(ROOT, 'scripts/scorm-package.mjs'), EXAMPLE, '--dist', DIST, '--out', out],
                      { encoding: 'utf8', env: { ...process.env, CSPACELAB_CLI: CLI } });
  assert.equal(r.status, 0, r.stderr);
  return Object.fromEntries(JSON.parse(r.stdout).packages.map((p) => [p.version, p.file]));
}

/** A site with the stand-in LMS at / and the package unzipped (in node) under /course/. */
function lmsSite(zipFile) {
  const site = fs.mkdtempSync(path.join(os.tmpdir(), 'csl-lms-'));
  for (const { name, data } of readZip(fs.readFileSync(zipFile))) {
    const file = path.join(site, 'course', name);
    fs.mkdirSync(path.dirname(file), { recursive: true });
    fs.writeFileSync(file, data);
  }
  fs.writeFileSync(path.join(site, 'lms.html'), LMS_HTML);
  fs.writeFileSync(path.join(site, 'lms.js'), LMS_JS);
  fs.copyFileSync(SCORM_AGAIN, path.join(site, 'scorm-again.min.js'));
  return site;
}

/** The lab's frame once its assignment is open; resolves to [frame, its assignment state]. */
async function openedFrame(page) {
  const handle = await page.waitForSelector('#sco');
  let frame = null;
  await page.waitForFunction(() => true);  // the iframe's document may be replaced: ask again below
  for (let i = 0; i < 600 && !frame; ++i) {
    const f = await handle.contentFrame();
    if (f && /launch\.html$/.test(f.url())) {
      try {
        const ready = await f.evaluate(async () => {
          const p = document.getElementById('assignment') && document.getElementById('assignment').cspacelabAssignment;
          if (!p) return false;
          const a = await p;
          return !!(a && a.state);
        });
        if (ready) frame = f;
      } catch {
        // navigating: try again
      }
    }
    if (!frame) await page.waitForTimeout(100);
  }
  assert.ok(frame, 'the launch page opened its assignment');
  return [frame, await call(frame, 'assignment_state')];
}

/** Waits until the lab in `frame` has drawn `count` more frames (ImGui reads input once a frame). */
async function labFrames(frame, count = 2) {
  const start = await frame.evaluate(() => window.cspacelab.status().frames);
  await frame.waitForFunction((n) => window.cspacelab.status().frames >= n, start + count);
}

/** A real click on one of the assignment card's controls (page_state().buttons) in the LMS's frame. */
async function clickControl(page, frame, name) {
  await labFrames(frame, 2);
  const inner = await frame.evaluate((n) => {
    const a = window.cspacelab;
    const r = a.pageState().buttons[n];
    const box = a.module.canvas.getBoundingClientRect();
    return r ? { x: box.left + (r[0] + r[2]) / 2, y: box.top + (r[1] + r[3]) / 2 } : null;
  }, name);
  assert.ok(inner, `the card shows ${name}`);
  const offset = await page.evaluate(() => {
    const f = document.getElementById('sco');
    const r = f.getBoundingClientRect();
    return { x: r.left + f.clientLeft, y: r.top + f.clientTop };
  });
  await page.mouse.move(offset.x + inner.x, offset.y + inner.y);
  await labFrames(frame, 2);
  await page.mouse.down();
  await labFrames(frame, 1);
  await page.mouse.up();
  await labFrames(frame, 2);
}

const call = (frame, cmd, args = {}) =>
  frame.evaluate(([c, a]) => document.getElementById('assignment').cspacelab.call(c, a), [cmd, args]);
const lmsGet = (page, element) =>
  page.evaluate((el) => (window.lms.version === '1.2' ? window.lms.api.LMSGetValue(el) : window.lms.api.GetValue(el)), element);
const lmsRecord = (page) => page.evaluate(() => window.lms.api.renderCMIToJSONObject().cmi);
const launches = (page) => page.evaluate(() => window.lms.launches.map((l) => l.calls));

const packages = buildPackages();
const view = cli('assignment', 'exercises', EXAMPLE, '--learner', LEARNER);
const p10 = view.items[1].given;
const p12 = view.items[2].given;
const ANSWERS = { 0: 'R^3', 1: s1(p10.q1, p10.q2).toFixed(4), 2: String(minGrid(p12.center, p12.radius)) };

for (const version of ['1.2', '2004']) {
  const v12 = version === '1.2';
  test(`SCORM ${version}: the package in an LMS frame reports score, status and interactions, and resumes`, { timeout: 240000 }, async () => {
    const site = lmsSite(packages[version]);
    const { server, url } = await serve(site, 0);
    const browser = await launchBrowser();
    try {
      const page = await browser.newPage({ viewport: { width: 1300, height: 800 } });
      await page.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
      const errors = collectErrors(page);
      const csp = [];
      page.on('console', (m) => { if (/Content Security Policy|Refused to/i.test(m.text())) csp.push(m.text()); });
      await page.goto(url + 'lms.html?v=' + version);
      let [frame, state] = await openedFrame(page);

      // The LMS's learner id reached the app; the session started once; nothing reported as done.
      assert.equal(state.learner, LEARNER);
      assert.equal(state.items.length, 5);
      const first = (await launches(page))[0];
      assert.deepEqual(Object.values(first).slice(0, 2), [1, 0], 'initialised once, not terminated');
      if (v12) assert.equal(await lmsGet(page, 'cmi.core.lesson_status'), 'incomplete');
      else assert.deepEqual([await lmsGet(page, 'cmi.completion_status'), await lmsGet(page, 'cmi.success_status')], ['incomplete', 'unknown']);

      // P3 and P10 answered through the app's commands (P3 wrong on purpose), P12 typed into the
      // card's answer field with the mouse and keys, the explore item opened from the card.
      for (const index of [0, 1]) {
        await call(frame, 'assignment_go', { index });
        await call(frame, 'assignment_answer', { index, answer: ANSWERS[index] });
      }
      await clickControl(page, frame, 'assignment-item-2');
      assert.equal((await call(frame, 'assignment_state')).current, 2, 'the list\'s item opened');
      await clickControl(page, frame, 'assignment-answer');
      for (const key of [...ANSWERS[2], 'Enter']) {
        await page.keyboard.press(key);
        await labFrames(frame, 1);
      }
      await frame.waitForFunction(() => window.cspacelab.call('assignment_state').items[2].status !== 'open');
      await clickControl(page, frame, 'assignment-item-3');
      await clickControl(page, frame, 'assignment-open-item');
      state = await call(frame, 'assignment_state');
      assert.deepEqual(state.items.map((i) => i.status), ['incorrect', 'correct', 'correct', 'viewed', 'open']);
      assert.equal(state.current, 3);
      // An interaction per item, then one per check made (P3, P10, P12; the visit is none).
      await page.waitForFunction(() => Object.keys(window.lms.api.renderCMIToJSONObject().cmi.interactions).length === 8);
      const before = await call(frame, 'assignment_state');
      const rec = await lmsRecord(page);
      const responses = Object.values(rec.interactions).map((i) => i[v12 ? 'student_response' : 'learner_response']);
      assert.deepEqual(responses.slice(0, 3), [ANSWERS[0], ANSWERS[1], ANSWERS[2]].map((a) => a.slice(0, 255)));
      // SCORM has no count of tries: 2004's description carries it (1.2 has no description).
      if (!v12) assert.match(Object.values(rec.interactions)[2].description, /^P12: .* \(1 try\)$/);
      assert.ok(rec.suspend_data.length > 2 && rec.suspend_data.length < 4096, `suspend data: ${rec.suspend_data.length} characters`);

      // A reload is a new launch: the first terminated once, the second resumes where it was.
      await frame.evaluate(() => location.reload());
      [frame, state] = await openedFrame(page);
      assert.equal(state.current, 3, 'the same item');
      assert.deepEqual(state.interactions.map((i) => i.learner_response), before.interactions.map((i) => i.learner_response), 'the same answers');
      assert.deepEqual(state.items.map((i) => i.status), before.items.map((i) => i.status));
      const [init, term, commit] = v12 ? ['LMSInitialize', 'LMSFinish', 'LMSCommit'] : ['Initialize', 'Terminate', 'Commit'];
      const two = await launches(page);
      assert.deepEqual(two.map((c) => [c[init], c[term]]), [[1, 1], [1, 0]], 'one Initialize and one Terminate per launch');
      assert.ok(two[0][commit] >= 1, 'the first launch committed before it terminated');

      // The task: at most 50 samples and a path. The seed that solves it is searched here.
      await call(frame, 'assignment_go', { index: 4 });
      let solved = false;
      for (let seed = 1; seed <= 40 && !solved; ++seed) {
        await frame.evaluate((s) => { const api = document.getElementById('assignment').cspacelab; api.setParams({ samples: 45, seed: s }); api.run(); }, seed);
        await frame.waitForFunction(() => { const s = document.getElementById('assignment').cspacelab.status(); return !s.busy && s.stepping.finished; });
        solved = (await frame.evaluate(() => document.getElementById('assignment').cspacelab.state())).solved;
      }
      assert.ok(solved, 'a seed with 45 samples joins start and goal');
      await call(frame, 'assignment_answer', { index: 4 });
      // Every item answered, not submitted: the app's grade is completed and passed, but the
      // answers may still change, so the LMS hears neither (read back from the runtime).
      const open = await call(frame, 'assignment_state');
      assert.deepEqual([open.submitted, open.grade.completed, open.grade.passed], [false, true, true]);
      await page.waitForFunction((el) => Object.values(window.lms.api.renderCMIToJSONObject().cmi.interactions)[4][el] !== '',
                                 v12 ? 'student_response' : 'learner_response');
      if (v12) assert.equal(await lmsGet(page, 'cmi.core.lesson_status'), 'incomplete');
      else assert.deepEqual([await lmsGet(page, 'cmi.completion_status'), await lmsGet(page, 'cmi.success_status')], ['incomplete', 'unknown']);
      // Submit with the mouse, through the card's confirmation.
      await clickControl(page, frame, 'assignment-submit');
      await clickControl(page, frame, 'assignment-submit-confirm');
      state = await call(frame, 'assignment_state');
      assert.equal(state.submitted, true);
      const notice = JSON.stringify(await frame.evaluate(() => window.cspacelab.status().notice) || '');
      assert.doesNotMatch(notice, /LMS.*refused/, 'the LMS took every value');
      await page.waitForTimeout(1500);  // the lab commits at most once a second

      // What the runtime holds: 7 of 8 points (P3 wrong), passed (pass 0.6).
      if (v12) {
        assert.deepEqual(await Promise.all(['raw', 'min', 'max'].map((k) => lmsGet(page, 'cmi.core.score.' + k).then(Number))), [87.5, 0, 100]);
        assert.equal(await lmsGet(page, 'cmi.core.lesson_status'), 'passed');
      } else {
        assert.deepEqual(await Promise.all(['raw', 'min', 'max', 'scaled'].map((k) => lmsGet(page, 'cmi.score.' + k).then(Number))), [7, 0, 8, 0.875]);
        assert.equal(await lmsGet(page, 'cmi.completion_status'), 'completed');
        assert.equal(await lmsGet(page, 'cmi.success_status'), 'passed');
      }
      const all = Object.values((await lmsRecord(page)).interactions);
      assert.equal(all.length, 9, 'five items, and the journal of four checks across two launches');
      const done = all.slice(0, 5);
      const journal = all.slice(5);
      assert.deepEqual(journal.map((i) => [i.id, i.result, i[v12 ? 'student_response' : 'learner_response']]),
                       [['item-1-try-1', v12 ? 'wrong' : 'incorrect', ANSWERS[0]], ['item-2-try-1', 'correct', ANSWERS[1]],
                        ['item-3-try-1', 'correct', ANSWERS[2]], ['item-5-try-1', 'correct', done[4][v12 ? 'student_response' : 'learner_response']]]);
      for (const it of journal) assert.match(v12 ? it.time : it.timestamp, v12 ? /^\d\d:\d\d:\d\d$/ : /^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d\dZ$/);
      const wrong = v12 ? 'wrong' : 'incorrect';
      assert.deepEqual([0, 1, 2, 4].map((i) => done[i].result), [wrong, 'correct', 'correct', 'correct']);
      assert.deepEqual(done.slice(0, 3).map((i) => i[v12 ? 'student_response' : 'learner_response']), [ANSWERS[0], ANSWERS[1], ANSWERS[2]]);
      assert.deepEqual(done.slice(1, 3).map((i) => i.type), ['numeric', 'numeric'], 'P10 and P12 ask for a number');
      assert.deepEqual(done.slice(3).map((i) => i.type), v12 ? ['performance', 'performance'] : ['other', 'other']);
      assert.deepEqual(done.map((i) => Number(i.weighting)), [1, 2, 2, 0, 3]);
      for (const [n, it] of done.entries()) {
        assert.equal(it.id, state.interactions[n].id.replace(/[^A-Za-z0-9_.:-]/g, '_'), 'the app\'s interaction id');
        assert.equal(it.result, { correct: 'correct', incorrect: wrong, neutral: 'neutral' }[state.interactions[n].result]);
      }
      await screenshot(page, `scorm-${version}-submitted.png`);

      // A last launch: the submitted assignment comes back for review; then the LMS closes it.
      await frame.evaluate(() => location.reload());
      [frame, state] = await openedFrame(page);
      assert.equal(state.submitted, true);
      assert.equal(state.current, 4);
      assert.equal(state.grade.raw, 7);
      await page.evaluate(() => { document.getElementById('sco').src = 'about:blank'; });
      await page.waitForFunction(() => window.lms.launches.length === 4);
      const counts = await launches(page);
      for (const c of counts.slice(0, 3)) assert.deepEqual([c[init], c[term]], [1, 1], 'each launch: one Initialize, one Terminate');
      assert.deepEqual([counts[3][init], counts[3][term]], [0, 0], 'the LMS\'s next launch object, unused');
      assert.deepEqual(csp, [], 'no Content-Security-Policy refusals (scorm-again in the parent, lab-assignment.js in the frame)');
      assert.deepEqual(errors, []);
    } finally {
      await browser.close();
      server.close();
    }
  });
}

test('assignment= only loads lab-assignment.js where it is used, and refuses another site', { timeout: 120000 }, async () => {
  const { server, url } = await serve(DIST, 0);
  const browser = await launchBrowser();
  try {
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    await page.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
    const errors = collectErrors(page);
    const scripts = [];
    page.on('request', (r) => { if (r.resourceType() === 'script') scripts.push(new URL(r.url()).pathname); });
    await page.goto(url + 'index.html?lesson=collision');
    await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2, null, { timeout: 30000 });
    assert.ok(scripts.includes('/lab.js') && !scripts.includes('/lab-assignment.js'), scripts.join(' '));
    assert.equal(await page.evaluate(() => typeof window.CSpaceLabAssignment), 'undefined');

    for (const [raw, why] of [['https://evil.example/a.json', 'is not on this site'], ['//evil.example/a.json', 'is not on this site'],
                              ['missing.json', 'could not be loaded \\(HTTP 404\\)']]) {
      await page.goto(url + 'index.html?assignment=' + encodeURIComponent(raw));
      await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2, null, { timeout: 30000 });
      const made = await page.evaluate(async () => {
        const a = await document.querySelector('[data-lab]').cspacelabAssignment;
        return a ? a.state : 'no assignment';
      });
      assert.ok(made === null || made === 'no assignment', 'nothing opened');
      const notice = (await page.evaluate(() => window.cspacelab.status().notice)) || '';
      const text = typeof notice === 'string' ? notice : JSON.stringify(notice);
      assert.match(text, new RegExp(why), raw);
    }
    // (the 404 of missing.json is the browser's console line for the failed fetch, nothing else)
    assert.deepEqual(errors.filter((e) => !/404/.test(e)), []);
  } finally {
    await browser.close();
    server.close();
  }
});
