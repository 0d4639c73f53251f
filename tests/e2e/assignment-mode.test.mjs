// The assignment mode as a student meets it: docs/assignment-example.json opened through the API
// with a learner id (as the LMS layer opens it), exercises answered in the card by keyboard and
// mouse (right and wrong, the right numbers computed here from the CLI's given numbers), the
// task done by really running the PRM and "Check my lab", the explore item visited, Submit with
// its confirmation, and the grade compared with `cspacelab assignment grade` for the same
// answers. A reload resumes exactly from the suspend object; the DOM event carries the state; the
// card works in the phone's compact layout and under an instructor's lock.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { withPage, withBrowser, collectErrors, openLab, click, keys, waitFrames, api, pageButton, screenshot,
         inspectPng, cli, tempJson, DIST, launchBrowser } from './lib/harness.mjs';
import { serve } from '../../scripts/static-server.mjs';
import { s1, minGrid } from '../lib/homework-answers.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const FILE = path.resolve(here, '../../docs/assignment-example.json');
const ASSIGNMENT = JSON.parse(fs.readFileSync(FILE, 'utf8'));
const LEARNER = 'student-4711';

// The learner's exercises as the CLI makes them (seeds, given numbers; never an answer).
function exercises(learner) {
  return cli('assignment', 'exercises', FILE, '--learner', learner).items;
}

async function press(page, name) {
  const at = await pageButton(page, name);
  assert.ok(at, `the control "${name}" is on screen`);
  await click(page, at);
}

// Clears the card's answer field, types `text` and presses Enter, as a student does.
async function typeAnswer(page, text, { enter = true } = {}) {
  await press(page, 'assignment-answer');
  await page.keyboard.press('Control+A');
  await page.keyboard.press('Backspace');
  await waitFrames(page, 1);
  await page.keyboard.type(text, { delay: 20 });
  await waitFrames(page, 2);
  if (enter) await keys(page, 'Enter');
  await waitFrames(page, 2);
}

const state = (page) => api(page, 'assignment_state');
// The state without its note (why the lab could not show an item: not part of the work).
const work = ({ note, ...rest }) => rest;

// Records every cspacelab:assignment event's detail on the lab's root element.
async function listen(page) {
  await page.evaluate(() => {
    window.__assignmentEvents = [];
    const root = window.cspacelab.module.canvas.closest('[data-lab]');
    root.addEventListener('cspacelab:assignment', (e) => window.__assignmentEvents.push(e.detail));
  });
}
const events = (page) => page.evaluate(() => window.__assignmentEvents);

// Runs the PRM in step-prm with at most 50 samples until it finds a path (seeds tried in
// turn); the last run by the mouse (Run all). Returns the lesson's state.
async function solveWithFewSamples(page) {
  for (let seed = 1; seed <= 60; ++seed) {
    await page.evaluate((s) => {
      window.cspacelab.setParams({ samples: 50, neighbors: 'k:10', seed: s });
      window.cspacelab.reset();
    }, seed);
    await press(page, 'run-all');
    await page.waitForFunction(() => !window.cspacelab.status().busy && window.cspacelab.status().stepping.finished,
                               null, { timeout: 30000 });
    const s = await api(page, 'state');
    if (s.solved) return s;
  }
  throw new Error('no seed in 1..60 solves the scene with 50 samples');
}

test('an assignment done in the card: exercises by keyboard and mouse, the task by running the PRM, submitted, graded as the CLI grades',
  () => withPage(async ({ page, browser }) => {
  await listen(page);
  let st = await api(page, 'assignment_open', { assignment: ASSIGNMENT, learner: LEARNER });
  assert.equal(st.title, ASSIGNMENT.title);
  assert.equal(st.learner, LEARNER);
  assert.equal(st.items.length, 5);
  assert.deepEqual(st.items.map((i) => i.status), ['open', 'open', 'open', 'open', 'open']);
  assert.deepEqual(st.items.map((i) => i.id), ['item-1', 'item-2', 'item-3', 'item-4', 'item-5']);
  assert.deepEqual(st.grade, { raw: 0, min: 0, max: 8, scaled: 0, completed: false, passed: false });
  await page.waitForFunction(() => window.__assignmentEvents.length === 1);
  assert.deepEqual((await events(page))[0], st, 'the event carries the state');

  // The learner's own numbers, as the CLI gives them for the same id (and not another's).
  const mine = exercises(LEARNER);
  for (const i of [0, 1, 2]) {
    assert.equal(st.items[i].seed, mine[i].seed, `item ${i}: the CLI's seed`);
    assert.equal(st.items[i].prompt, mine[i].prompt);
  }
  assert.notEqual(exercises('someone-else')[1].seed, mine[1].seed, 'a neighbour gets other numbers');

  // Item 1 (P3): a wrong answer, typed and sent with Enter.
  await press(page, 'assignment-item-0');
  assert.equal((await state(page)).current, 0);
  assert.equal((await api(page, 'status')).lesson, 'notation', 'P3 opens its tool');
  await typeAnswer(page, 'R^9');
  st = await state(page);
  assert.equal(st.items[0].status, 'incorrect');
  assert.equal(st.items[0].answer, 'R^9');
  assert.equal(st.items[0].feedback, 'Not right yet.');
  assert.ok(!('expected' in st.items[0]), 'no answer shown before submission');

  // Item 2 (P10), by keyboard: Next, then a wrong answer, then the right one (Enter each time).
  await press(page, 'assignment-next');
  assert.equal((await state(page)).current, 1);
  const { q1, q2 } = mine[1].given;
  const d = s1(q1, q2);
  const wrong = Math.abs(Math.abs(q1 - q2) - d) > 0.05 ? Math.abs(q1 - q2) : d + 1;
  await typeAnswer(page, wrong.toFixed(3));
  assert.equal((await state(page)).items[1].status, 'incorrect');
  const p10 = d.toFixed(4);
  await typeAnswer(page, p10);
  st = await state(page);
  assert.equal(st.items[1].status, 'correct', st.items[1].feedback);
  assert.equal(st.items[1].score, 2);
  await screenshot(page, 'assignment-exercise.png');

  // Item 3 (P12, a fixed seed), by mouse: the item's row, a wrong count, then the right one with Check.
  await press(page, 'assignment-item-2');
  assert.equal((await api(page, 'status')).lesson, 'collision');
  const n = minGrid(mine[2].given.center, mine[2].given.radius);
  await typeAnswer(page, String(n + 3), { enter: false });
  await press(page, 'assignment-check');
  assert.equal((await state(page)).items[2].status, 'incorrect');
  await typeAnswer(page, String(n), { enter: false });
  await press(page, 'assignment-check');
  st = await state(page);
  assert.equal(st.items[2].status, 'correct');
  assert.equal(st.grade.raw, 4);

  // Item 4 (explore): Next opens the wall with a gap in Step PRM, and that is the visit.
  await press(page, 'assignment-next');
  st = await state(page);
  assert.equal(st.current, 3);
  assert.equal(st.items[3].status, 'viewed');
  assert.equal((await api(page, 'status')).lesson, 'step-prm');
  assert.equal((await api(page, 'state')).scene_name, 'A wall with a gap');
  assert.equal((await api(page, 'state')).params.samples, 200);

  // Item 5 (task): "Check my lab" before a path is found fails, after one is found passes.
  await press(page, 'assignment-next');
  assert.equal((await api(page, 'state')).params.samples, 50, 'the task\'s parameters');
  // No gift: as it opens (a narrow passage, 50 samples, seed 5) the roadmap does not get through.
  assert.equal((await api(page, 'state')).scene_name, 'A passage through a thick wall');
  await press(page, 'run-all');
  await page.waitForFunction(() => !window.cspacelab.status().busy && window.cspacelab.status().stepping.finished,
                             null, { timeout: 30000 });
  assert.equal((await api(page, 'state')).solved, false, 'the task is not solved as it opens');
  await press(page, 'assignment-check-lab');
  assert.match((await state(page)).items[4].feedback, /^Not yet: no: solved is false/);
  await page.evaluate(() => window.cspacelab.setParams({ samples: 60 }));
  await press(page, 'assignment-check-lab');
  st = await state(page);
  assert.equal(st.items[4].status, 'incorrect');
  assert.match(st.items[4].feedback, /samples is 60/);
  const solved = await solveWithFewSamples(page);
  assert.equal(solved.params.samples, 50);
  await press(page, 'assignment-check-lab');
  st = await state(page);
  assert.equal(st.items[4].status, 'correct', st.items[4].feedback);
  assert.deepEqual(st.items[4].answer, { solved: true, params: { samples: 50 }, scene_name: 'A passage through a thick wall' },
                   'what the check read, kept');
  const card = await screenshot(page, 'assignment-task.png');
  assert.ok((await inspectPng(browser, card.png)).colours > 25);

  // Submit asks first: Cancel keeps it open, Submit makes it final.
  await press(page, 'assignment-submit');
  await waitFrames(page, 2);
  await screenshot(page, 'assignment-confirm.png');
  await press(page, 'assignment-submit-cancel');
  assert.equal((await state(page)).submitted, false);
  await press(page, 'assignment-submit');
  await waitFrames(page, 2);
  await press(page, 'assignment-submit-confirm');
  st = await state(page);
  assert.equal(st.submitted, true);
  assert.deepEqual(st.items.map((i) => i.status), ['incorrect', 'correct', 'correct', 'viewed', 'correct']);
  // The review: right answers and worked solutions now, and in the interactions.
  assert.ok(Math.abs(st.items[1].expected - d) < 1e-9, `expected ${st.items[1].expected} = ${d}`);
  assert.equal(st.items[2].expected, n);
  assert.ok(st.items[1].explanation.length > 20);
  assert.equal(st.interactions[1].type, 'numeric');
  assert.equal(st.interactions[0].type, 'fill-in');
  assert.equal(st.interactions[1].learner_response, p10);
  assert.equal(st.interactions[0].result, 'incorrect');
  assert.ok('correct_response' in st.interactions[2]);
  assert.deepEqual(st.interactions.map((i) => i.weighting), [1, 2, 2, 0, 3]);
  await screenshot(page, 'assignment-review.png');
  assert.match(await page.evaluate(() => {
    try { window.cspacelab.call('assignment_answer', { index: 0, answer: 'R^2' }); } catch (e) { return e.message; }
    return 'taken';
  }), /submitted/, 'answers are final');

  // The grade is the CLI's for the same answers (typed here, the state read here before the check).
  const answers = { learner: LEARNER, answers: [
    { item: 0, answer: 'R^9' }, { item: 1, answer: p10 }, { item: 2, answer: String(n) }, { item: 3, visited: true },
    { item: 4, state: solved }] };
  const graded = cli('assignment', 'grade', FILE, '--answers', tempJson(answers));
  assert.deepEqual(st.grade, { ...graded.score, completed: graded.completed, passed: graded.passed });
  assert.deepEqual(st.grade, { raw: 7, min: 0, max: 8, scaled: 7 / 8, completed: true, passed: true });
  // ... and the answers the state reports grade the same.
  assert.deepEqual(cli('assignment', 'grade', FILE, '--answers', tempJson(st.answers)).score, graded.score);

  // Every change was announced: the last event is the state now.
  const all = await events(page);
  assert.ok(all.length >= 12, `${all.length} events`);
  assert.deepEqual(all[all.length - 1], st);
}));

test('a reload resumes exactly from the suspend object; a bad file or resume is refused whole',
  () => withPage(async ({ page }) => {
  await api(page, 'assignment_open', { assignment: JSON.stringify(ASSIGNMENT), learner: LEARNER });
  const mine = exercises(LEARNER);
  await api(page, 'assignment_go', { index: 1 });
  const d = s1(mine[1].given.q1, mine[1].given.q2);
  let item = await api(page, 'assignment_answer', { index: 1, answer: d.toFixed(4) });
  assert.equal(item.status, 'correct');
  assert.equal(item.score, 2);
  await api(page, 'assignment_answer', { index: 0, answer: 'nonsense ((' });
  await api(page, 'assignment_answer', { index: 3 });
  await api(page, 'assignment_go', { index: 4 });
  const before = await state(page);
  assert.equal(before.items[0].status, 'answered', 'an unreadable answer is recorded, not an attempt');
  assert.equal(before.items[3].status, 'viewed');
  assert.equal(before.current, 4);
  const suspend = before.suspend;
  assert.ok(JSON.stringify(suspend).length < 4000);

  await page.reload();
  await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2);
  await listen(page);
  const after = await api(page, 'assignment_open', { assignment: ASSIGNMENT, learner: LEARNER, resume: suspend });
  assert.deepEqual(work(after), work(before), 'the same answers, item, grade and interactions');
  await page.waitForFunction(() => window.__assignmentEvents.length === 1);
  assert.deepEqual((await events(page))[0], after);
  await waitFrames(page, 3);
  await screenshot(page, 'assignment-resumed.png');
  // The card shows the resumed item: its "Check my lab" is on screen.
  assert.ok(await pageButton(page, 'assignment-check-lab'));

  // Every problem of a bad file in one error, naming item and field; nothing changes.
  const bad = structuredClone(ASSIGNMENT);
  bad.items[1].points = -1;
  bad.items[4].check = { pointer: 'solved', equals: true };
  bad.items[2].problem = 'P99';
  const message = await page.evaluate((a) => {
    try { window.cspacelab.call('assignment_open', { assignment: a }); } catch (e) { return e.message; }
    return null;
  }, bad);
  assert.match(message, /^assignment: 3 problems: /);
  assert.match(message, /items\[1\] \(P10\): points: /);
  assert.match(message, /items\[2\] \(P99\): problem: /);
  assert.match(message, /items\[4\] \("Find a path with at most 50 samples"\): check/);
  const resumeError = await page.evaluate(([a, s]) => {
    try { window.cspacelab.call('assignment_open', { assignment: a, resume: s }); } catch (e) { return e.message; }
    return null;
  }, [ASSIGNMENT, { ...suspend, c: 9 }]);
  assert.match(resumeError, /resume: c: the current item, 0 to 4/);
  assert.deepEqual(work(await state(page)), work(before), 'the open assignment is untouched');

  await api(page, 'assignment_close');
  await page.waitForFunction(() => window.__assignmentEvents.at(-1) === null);
  assert.equal(await pageButton(page, 'assignment-progress'), null, 'the card is gone');
}));

test('on a phone: the card in the Controls tab, answered by touch, submitted',
  () => withBrowser(async ({ browser, url }) => {
  const ctx = await browser.newContext({ viewport: { width: 390, height: 844 }, deviceScaleFactor: 3, hasTouch: true, isMobile: true });
  const page = await ctx.newPage();
  await page.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
  const errors = collectErrors(page);
  await openLab(page, url);
  const cdp = await ctx.newCDPSession(page);
  const tap = async (name) => {
    const at = await pageButton(page, name);
    assert.ok(at, `the control "${name}" is on screen`);
    for (const type of ['touchStart', 'touchEnd']) {
      await cdp.send('Input.dispatchTouchEvent', { type, touchPoints: type === 'touchStart' ? [{ x: at.x, y: at.y, id: 0 }] : [] });
      await waitFrames(page, 2);
    }
  };
  await api(page, 'assignment_open', { assignment: ASSIGNMENT, learner: LEARNER });
  await tap('tab:controls');
  assert.equal((await api(page, 'status')).layout.tab, 'controls');
  // The card opens at its top, its title in view, and no field has taken the keyboard: that
  // would open the phone's on-screen keyboard over half the screen, unasked.
  assert.equal((await api(page, 'status')).panel.scroll, 0);
  const focusedProxy = () => page.evaluate(() => document.activeElement === window.cspacelab.module.canvas.cslText);
  assert.equal(await focusedProxy(), false, 'no text field has the keyboard');
  // Every control of the card is a finger's target: 24 px high at least (WCAG 2.5.8).
  const buttons = await page.evaluate(() => window.cspacelab.pageState().buttons);
  for (const [name, r] of Object.entries(buttons).filter(([n]) => n.startsWith('assignment-') && n !== 'assignment-progress'))
    assert.ok(r[3] - r[1] >= 24, `${name} is ${r[3] - r[1]} px high`);
  const mine = exercises(LEARNER);
  await tap('assignment-item-1');
  await tap('assignment-answer');
  assert.equal(await focusedProxy(), true, 'a tap on the field gives it the keyboard');
  await page.keyboard.type(s1(mine[1].given.q1, mine[1].given.q2).toFixed(4), { delay: 20 });
  await waitFrames(page, 2);
  await tap('assignment-check');
  assert.equal((await state(page)).items[1].status, 'correct');
  await screenshot(page, 'assignment-phone.png');
  // An explore item opens the View tab: the student looks at the lab.
  await tap('assignment-item-3');
  assert.equal((await api(page, 'status')).layout.tab, 'view');
  assert.equal((await state(page)).items[3].status, 'viewed');
  await tap('tab:controls');
  await tap('assignment-submit');
  await tap('assignment-submit-confirm');
  const st = await state(page);
  assert.equal(st.submitted, true);
  assert.equal(st.grade.raw, 2);
  await screenshot(page, 'assignment-phone-review.png');
  assert.deepEqual(errors, []);
  await ctx.close();
}));

test('with the lesson locked by the instructor (lock=lesson) the assignment still works',
  () => withPage({ open: '?lesson=distances&lock=lesson' }, async ({ page }) => {
  await api(page, 'assignment_open', { assignment: ASSIGNMENT, learner: LEARNER });
  // P3's tool is another lesson: the lab stays, the card says why, the exercise is answered.
  let st = await api(page, 'assignment_go', { index: 0 });
  assert.equal((await api(page, 'status')).lesson, 'distances');
  assert.match(st.note, /instructor/);
  // P10's tool is this one.
  st = await api(page, 'assignment_go', { index: 1 });
  assert.equal(st.note, '');
  const mine = exercises(LEARNER);
  await waitFrames(page, 2);
  await typeAnswer(page, s1(mine[1].given.q1, mine[1].given.q2).toFixed(4));
  assert.equal((await state(page)).items[1].status, 'correct');
  // The task's lesson is not open (locked away): Check my lab says so, nothing is recorded.
  await api(page, 'assignment_go', { index: 4 });
  await waitFrames(page, 2);
  await press(page, 'assignment-check-lab');
  st = await state(page);
  assert.equal(st.items[4].status, 'open');
  assert.match(st.note, /not open/);
}));

// Presses Tab (Shift+Tab with `back`) until `is(activeElement)` holds, at most `max` times;
// returns how many presses it took. Only key presses move the focus here, as for a student
// without a pointer.
async function tabTo(page, is, max, { back = false, what = 'the control' } = {}) {
  for (let n = 1; n <= max; ++n) {
    await page.keyboard.press(back ? 'Shift+Tab' : 'Tab');
    await waitFrames(page, 1);
    if (await page.evaluate(is)) return n;
  }
  const at = await page.evaluate(() => document.activeElement.outerHTML.slice(0, 120));
  throw new Error(`${what} not reached in ${max} presses of Tab; the focus is on ${at}`);
}
const focusedText = (page) => page.evaluate(() => document.activeElement.textContent);

test('by keyboard alone in the accessible DOM: from the lab to the answer, Cancel, Submit, the review',
  { timeout: 180000 }, async () => {
  // The site with the assignment file beside the page, as a course's site or the SCORM package
  // holds it: the mirror (lab-assignment-access.js) comes only with assignment=.
  const site = fs.mkdtempSync(path.join(os.tmpdir(), 'cspacelab-assign-'));
  for (const f of fs.readdirSync(DIST)) fs.symlinkSync(path.join(DIST, f), path.join(site, f));
  fs.copyFileSync(FILE, path.join(site, 'week3.json'));
  const { server, url } = await serve(site, 0);
  const browser = await launchBrowser();
  try {
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    await page.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
    const errors = collectErrors(page);
    await openLab(page, url + 'index.html?assignment=week3.json');
    const group = page.locator('.lab-access-assignment');
    await group.waitFor({ state: 'attached' });
    await page.waitForFunction(() => !document.querySelector('.lab-access-assignment').hidden);
    assert.match(await group.locator('h3').textContent(), /^Assignment: Week 3/);
    const items = group.locator('ol').first().locator('button');
    assert.equal(await items.count(), ASSIGNMENT.items.length);
    assert.equal(await items.nth(0).getAttribute('aria-current'), 'true');

    // The lab has the keyboard when it opens (its canvas, or the text field's proxy). The page's
    // answer field is one Tab on (it took 27 presses when the card sat after every lesson and parameter).
    assert.ok(await page.evaluate(() => {
      const c = window.cspacelab.module.canvas;
      return document.activeElement === c || document.activeElement === c.cslText;
    }), 'the lab has the focus');
    // The card on the canvas says how: Esc leaves its answer field (Tab there steps between the
    // app's own fields), and then Tab goes on to the page.
    await page.keyboard.press('Escape');
    await waitFrames(page, 3);
    const toAnswer = await tabTo(page, () => document.activeElement.id.endsWith('-answer'), 3, { what: 'the answer field' });
    assert.equal(toAnswer, 1, 'the answer field is the first Tab after the canvas');
    assert.equal(await page.evaluate(() => !!document.activeElement.closest('.lab-access:focus-within')), true,
                 'the section shows while the keyboard is in it');
    const panel = await page.evaluate(() => document.querySelector('.lab-access').getBoundingClientRect().height);
    assert.ok(panel > 100, `the section is on screen while the focus is in it (${panel} px high)`);

    // On to item 2 (P10): Tab to Next, Enter. The focus stays on Next; Shift+Tab back to the field.
    const toNext = await tabTo(page, () => document.activeElement.textContent === 'Next', 5, { what: 'Next' });
    await page.keyboard.press('Enter');
    await page.waitForFunction(() => window.cspacelab.call('assignment_state').current === 1);
    assert.equal(await focusedText(page), 'Next');
    assert.match(await group.locator('p').nth(1).textContent(), /^2\. /);
    await tabTo(page, () => document.activeElement.id.endsWith('-answer'), toNext, { back: true, what: 'the answer field' });
    const learner = (await api(page, 'assignment_state')).learner;
    const given = cli('assignment', 'exercises', FILE, ...(learner ? ['--learner', learner] : [])).items[1].given;
    const right = s1(given.q1, given.q2);
    const answerWith = async (text) => {
      await page.keyboard.press('Control+A');
      await page.keyboard.press('Backspace');
      await page.keyboard.type(text);
      await page.keyboard.press('Enter');
      await waitFrames(page, 2);
    };
    await answerWith((right + 0.5).toFixed(4));
    assert.equal((await api(page, 'assignment_state')).items[1].status, 'incorrect');
    assert.match(await items.nth(1).textContent(), /^P10.*\(2 points\): not right$/);
    await answerWith(right.toFixed(4));
    assert.equal((await api(page, 'assignment_state')).items[1].status, 'correct');
    assert.match(await items.nth(1).textContent(), /: right$/);
    assert.match(await group.locator('p[aria-live]').textContent(), /right/i, 'the feedback is in the live region');
    assert.match(await group.locator('p').first().textContent(), /^1 of 5 answered, score 2 of 8$/);

    // Submit asks first and says what is still open; Cancel gives the focus back to Submit.
    await tabTo(page, () => document.activeElement.textContent === 'Submit...', 8, { what: 'Submit...' });
    await page.keyboard.press('Enter');
    const sure = group.getByRole('button', { name: /Yes, submit/ });
    assert.equal(await sure.isVisible(), true);
    assert.equal(await focusedText(page), await sure.textContent());
    const open = (await api(page, 'assignment_state')).items.filter((it) => it.status === 'open').length;
    assert.equal(open, ASSIGNMENT.items.length - 1);
    assert.match(await group.getByRole('group', { name: 'Submit the assignment?' }).textContent(),
                 new RegExp(`^${open} of ${ASSIGNMENT.items.length} items have no answer yet\\.`));
    // Escape is Cancel too; then Enter on Submit... again, and Tab, Enter on Cancel.
    await page.keyboard.press('Escape');
    assert.equal(await sure.isVisible(), false);
    assert.equal(await focusedText(page), 'Submit...');
    await page.keyboard.press('Enter');
    assert.equal(await page.evaluate(() => document.getElementById(document.activeElement.getAttribute('aria-describedby')).textContent),
                 `${open} of ${ASSIGNMENT.items.length} items have no answer yet. Your answers become final, and the review shows the right ones.`,
                 'Yes is read with the warning');
    await tabTo(page, () => document.activeElement.textContent === 'Cancel', 1, { what: 'Cancel' });
    await page.keyboard.press('Enter');
    assert.equal(await sure.isVisible(), false);
    assert.equal(await focusedText(page), 'Submit...');
    assert.equal((await api(page, 'assignment_state')).submitted, false, 'Cancel submits nothing');

    // Enter on Submit..., Enter on Yes: submitted, and the focus is on the review's heading.
    await page.keyboard.press('Enter');
    assert.equal(await focusedText(page), await sure.textContent());
    await page.keyboard.press('Enter');
    await page.waitForFunction(() => window.cspacelab.call('assignment_state').submitted);
    assert.equal(await focusedText(page), 'Review: your answers and the right ones', 'the focus did not fall to the body');
    assert.equal(await group.locator('p').first().textContent(), 'submitted: score 2 of 8, not passed');
    const review = group.locator('ol').nth(1).locator('li');
    assert.equal(await review.count(), ASSIGNMENT.items.length);
    // The right answer as a person writes it: six significant digits (as C's %.6g, computed
    // here from the given angles), and the tolerance this assignment accepts.
    const six = String(Number(right.toPrecision(6)));
    assert.match(await review.nth(1).textContent(),
                 new RegExp(`Your answer: ${right.toFixed(4)}\\. The right answer: ${six.replace('.', '\\.')} \\(within 0\\.01\\)\\.`));
    assert.deepEqual(errors, []);
  } finally {
    await browser.close();
    server.close();
    fs.rmSync(site, { recursive: true, force: true });
  }
});

test('the built site carries the example assignment: examples/assignment-example.json opens as a student sees it',
  () => withPage({ open: 'index.html?assignment=examples/assignment-example.json' }, async ({ page, url }) => {
  // An instructor who puts the lab on a server tries assignment mode with this link first.
  const served = await page.evaluate(async (u) => (await fetch(u)).text(), url + 'examples/assignment-example.json');
  assert.equal(served, fs.readFileSync(FILE, 'utf8'), 'the file is docs/assignment-example.json as it is');
  await page.waitForFunction(() => {
    try { return typeof window.cspacelab.call('assignment_state', {}).title === 'string'; } catch { return false; }
  }, null, { timeout: 30000 });
  const st = await api(page, 'assignment_state');
  assert.equal(st.title, ASSIGNMENT.title);
  assert.equal(st.items.length, ASSIGNMENT.items.length);
  assert.equal(st.submitted, false);
}));

test('tries: P12 allows 3; every graded check counts, and used up the answer is final in the card and its page copy',
  () => withPage({ open: 'index.html?assignment=examples/assignment-example.json' }, async ({ page }) => {
  await page.waitForFunction(() => {
    try { return !document.querySelector('.lab-access-assignment').hidden; } catch { return false; }
  }, null, { timeout: 30000 });
  assert.equal(ASSIGNMENT.items[2].tries, 3, 'the example limits P12, whose N can be found by counting up');
  const given = exercises('')[2].given;
  const n = minGrid(given.center, given.radius);
  await press(page, 'assignment-item-2');
  let st;
  let it = (await state(page)).items[2];
  assert.deepEqual([it.tries, it.tries_allowed, it.tries_left, it.tries_text], [0, 3, 3, 'Tries: 0 of 3 used.']);

  // A wrong count costs a try; a typo costs none and says why, and leaves the checked answer on
  // the record (it would have taken its grade away); the same answer again costs none.
  await typeAnswer(page, String(n + 1));
  it = (await state(page)).items[2];
  assert.deepEqual([it.status, it.tries, it.feedback], ['incorrect', 1, 'Not right yet. 2 tries left.']);
  await typeAnswer(page, `${n}x`);
  st = await state(page);
  it = st.items[2];
  assert.deepEqual([it.status, it.tries, it.answer], ['incorrect', 1, String(n + 1)], it.feedback);
  assert.match(st.note, new RegExp(`^"${n}x" is not .*Your checked answer "${n + 1}" stands\\.$`));
  assert.match(it.feedback, /2 tries left\.$/);
  await typeAnswer(page, String(n + 2));
  await typeAnswer(page, String(n + 2));
  assert.equal((await state(page)).items[2].tries, 2);
  await typeAnswer(page, String(n - 1));
  it = (await state(page)).items[2];
  assert.deepEqual([it.status, it.tries, it.tries_left, it.feedback],
                   ['incorrect', 3, 0, 'Not right. No tries left: this answer is final.']);

  // Final: typing the right count into the card changes nothing (its field is disabled), the
  // API refuses, and the page's copy says so and makes its field read-only.
  await typeAnswer(page, String(n), { enter: false });
  await press(page, 'assignment-check');
  st = await state(page);
  it = st.items[2];
  assert.deepEqual([it.answer, it.status, it.tries], [String(n - 1), 'incorrect', 3]);
  // Not refused by core either: the disabled field took no keys (the typed count, had it gone
  // in and been sent, would have been refused, and the refusal shown as the card's note).
  assert.equal(st.note, '', 'the disabled field took the typed count');
  assert.match(await page.evaluate(() => {
    try { window.cspacelab.call('assignment_answer', { index: 2, answer: '1' }); } catch (e) { return e.message; }
    return 'taken';
  }), /no tries left: item 3 allows 3 checks/);
  const group = page.locator('.lab-access-assignment');
  assert.equal(await group.locator('input').evaluate((e) => e.readOnly), true);
  assert.equal(await group.getByRole('button', { name: 'Check', exact: true }).getAttribute('aria-disabled'), 'true');
  assert.match(await group.locator('p[aria-live]').textContent(), /No tries left: this answer is final\./);
  assert.match(await group.locator('p').nth(1).textContent(), /Tries: 3 of 3 used\.$/);
  await screenshot(page, 'assignment-tries-final.png');
  // Another item's field is not read-only.
  await press(page, 'assignment-item-1');
  assert.equal(await group.locator('input').evaluate((e) => e.readOnly), false);

  // Counted where an instructor looks: the interaction (SCORM 2004's description), the answers
  // the CLI grades (with their tries), and the review.
  st = await state(page);
  assert.equal(st.interactions[2].description, `${st.items[2].title} (3 tries)`);
  assert.deepEqual(st.answers.answers.find((a) => a.item === 2), { item: 2, answer: String(n - 1), tries: 3 });
  const graded = cli('assignment', 'grade', FILE, '--answers', tempJson(st.answers));
  assert.deepEqual([graded.items[2].tries, graded.items[2].tries_allowed, graded.items[2].correct], [3, 3, false]);
  await api(page, 'assignment_submit');
  st = await state(page);
  assert.equal(st.items[2].tries_text, 'Tries: 3 of 3 used.');
  assert.match(await group.locator('ol').nth(1).locator('li').nth(2).textContent(), /Tries: 3 of 3 used\./);
  await waitFrames(page, 2);
  await screenshot(page, 'assignment-tries-review.png');
}));
