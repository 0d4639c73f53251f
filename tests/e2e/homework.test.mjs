// The homework companion as a student meets it: the first-visit welcome, the Homework map with
// every problem P1-P13 opened by the mouse (its tool drawn, no console error), exercises
// answered by typing (one right, one wrong, checked against numbers computed here), the same
// exercise in the CLI, ?problem= links, and a problem in a 900 px embed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, withBrowser, collectErrors, openLab, click, keys, waitFrames, api, pageButton, screenshot,
         inspectPng, cli, expectView } from './lib/harness.mjs';
import { lessonProbes } from './lib/probes.mjs';
import { s1, minGrid } from '../lib/homework-answers.mjs';

const LESSON = { P1: 'notation', P2: 'notation', P3: 'notation', P4: 'notation', P5: 'notation', P6: 'notation',
                 P7: 'notation', P8: 'analysis', P9: 'analysis', P10: 'distances', P11: 'distances',
                 P12: 'collision', P13: 'potential' };

async function press(page, name) {
  const at = await pageButton(page, name);
  assert.ok(at, `the control "${name}" is on screen`);
  await click(page, at);
}

// Clears the answer field and types `text`, then Enter, as a student does.
async function answer(page, text) {
  await press(page, 'answer');
  await page.keyboard.press('Control+A');
  await page.keyboard.press('Backspace');
  await waitFrames(page, 1);
  await page.keyboard.type(text, { delay: 20 });
  await waitFrames(page, 2);
  await keys(page, 'Enter');
  await waitFrames(page, 2);
  return (await api(page, 'homework_state')).check;
}

test('first visit: the welcome leads to the homework map, and is not shown again',
  () => withPage({ welcome: true }, async ({ page, browser }) => {
  let hw = await api(page, 'homework_state');
  assert.equal(hw.welcome, true);
  const look = await lessonProbes(page);  // the lesson under the welcome, drawn as its state says
  await expectView(page, browser, 'homework-welcome.png', look.probes, look.view, { misses: look.misses || 0 });
  await press(page, 'welcome-map');
  await waitFrames(page, 3);
  hw = await api(page, 'homework_state');
  assert.equal(hw.welcome, false);
  assert.equal(hw.map_open, true, 'the map opened');
  await screenshot(page, 'homework-map.png');
  await press(page, 'problem-P10');
  hw = await api(page, 'homework_state');
  assert.equal(hw.problem, 'P10');
  assert.equal((await api(page, 'status')).lesson, 'distances');
  // Remembered: a reload shows no welcome.
  await page.reload();
  await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2);
  assert.equal((await api(page, 'homework_state')).welcome, false);
}));

test('the Homework map opens each of P1-P13 with the mouse: its lesson drawn, its exercise shown',
  () => withPage(async ({ page, browser }) => {
  const list = await api(page, 'homework');
  assert.deepEqual(list.map((p) => p.id), Object.keys(LESSON));
  assert.deepEqual(list, cli('homework'), 'the same list as the CLI');
  for (const { id } of list) {
    await press(page, 'homework');
    await waitFrames(page, 2);
    await press(page, 'problem-' + id);
    await waitFrames(page, 3);
    const hw = await api(page, 'homework_state');
    assert.equal(hw.problem, id);
    assert.equal((await api(page, 'status')).lesson, LESSON[id], `${id} opens ${LESSON[id]}`);
    assert.equal(hw.exercise.id, id);
    assert.ok(hw.exercise.prompt.length > 20);
    // Its exercise is the CLI's for the same seed.
    const e = cli('exercise', id, '--seed', String(hw.exercise.seed));
    assert.deepEqual(hw.exercise, e, `${id}: the same exercise in the CLI`);
    // The tool is drawn as its state says (the notation picture, which varies with the exercise,
    // is compared with references in notation.test.mjs; here it need only be drawn).
    const look = await lessonProbes(page);
    if (look) {
      await expectView(page, browser, `homework-${id}.png`, look.probes, look.view, { misses: look.misses || 0 });
    } else {
      const shot = await screenshot(page, `homework-${id}.png`);
      const info = await inspectPng(browser, shot.png);
      assert.ok(info.colours > 25, `${id}: drawn (${info.colours} colours)`);
    }
  }
  assert.ok(!(await api(page, 'homework_state')).welcome);
}));

test('exercises answered by typing: right and wrong, checked against numbers computed here',
  () => withPage({ open: '?problem=P10&seed=7' }, async ({ page }) => {
  let hw = await api(page, 'homework_state');
  assert.equal(hw.problem, 'P10');
  assert.equal(hw.exercise.seed, 7);
  const { q1, q2 } = hw.exercise.given;
  const d = s1(q1, q2);
  // A wrong answer first: the raw difference when it differs, else something far off.
  const wrong = Math.abs(Math.abs(q1 - q2) - d) > 0.05 ? Math.abs(q1 - q2) : d + 1;
  let c = await answer(page, wrong.toFixed(3));
  assert.equal(c.correct, false);
  assert.ok(Math.abs(c.expected - d) < 1e-9, `expected ${c.expected} = ${d}`);
  assert.match(c.explanation, /mod 2 pi/);
  c = await answer(page, d.toFixed(3));
  assert.equal(c.correct, true, c.explanation);
  await screenshot(page, 'homework-P10-checked.png');
  hw = await api(page, 'homework_state');
  assert.deepEqual(hw.scores.P10, { tried: 2, right: 1 });
  // Then the reveal: the exercise's own numbers in the tool, by the mouse.
  await press(page, 'show-in-tool');
  const tool = await api(page, 'state');
  assert.equal(tool.q1, q1);
  assert.equal(tool.q2, q2);

  // P12, an integer, through the API as a page script would.
  await page.evaluate(() => window.cspacelab.openProblem('P12', 11));
  const e12 = (await api(page, 'homework_state')).exercise;
  const n = minGrid(e12.given.center, e12.given.radius);
  c = await answer(page, String(n - 2));
  assert.equal(c.correct, false);
  assert.match(c.explanation, /both ends/);
  c = await answer(page, String(n));
  assert.equal(c.correct, true);
  await press(page, 'show-in-tool');
  assert.equal((await api(page, 'state')).min_grid, n, 'the collision lesson finds the same N in the exercise\'s scene');
  assert.equal(await page.evaluate(() => window.cspacelab.undo()), true, 'the student\'s scene comes back with Undo');

  // P1, in the course's notation (a mobile robot in the plane: SE(2)), typed as R^2 x S^1; the
  // same with superscripts and a times sign through the API (a test's keyboard cannot type
  // them into the canvas: it sends such characters as composed text, which SDL does not read).
  await page.evaluate(() => window.cspacelab.openProblem('P1', 3));
  await waitFrames(page, 2);
  assert.equal(await pageButton(page, 'see-in-3d'), null, 'the 3-D picture, whose title says SE(2), waits for an answer');
  assert.equal(await page.evaluate(() => window.cspacelab.checkAnswer('R^2').correct), false);
  assert.equal(await page.evaluate(() => window.cspacelab.checkAnswer('R² × S¹').correct), true);
  c = await answer(page, 'R^2 x S^1');
  assert.equal(c.correct, true, c.explanation);
  assert.equal(c.expected, 'SE(2)');
  await answer(page, 'R^2 x S^1');
  await answer(page, '');
  // Four readable answers (R^2, R² × S¹, and R^2 x S^1 twice), one exercise right.
  assert.deepEqual((await api(page, 'homework_state')).scores.P1, { tried: 4, right: 1 },
                   'a right answer counts once, an empty one not at all');

  // Answered: the C-space itself, SE(2) as a stack of theta slices in the 3-D lesson.
  await press(page, 'see-in-3d');
  assert.equal((await api(page, 'status')).lesson, 'cspace-3d');
  assert.equal((await api(page, 'state')).robot, 'polygon');

  // P5's arm varies with the seed (the joints from `cspacelab exercise P5 --seed S`): the button
  // opens the space the student just named, and is absent where the lesson has no picture of it.
  const p5 = [[1, 'R^2 x S^1', 'prismatic, then prismatic, then revolute', 'polygon'],  // like SE(2)
              [2, 'T^3', 'revolute, then revolute, then revolute', 'arm3'],
              [3, 'T^2 x R', 'revolute, then revolute, then prismatic', null]];            // not drawn
  for (const [seed, typed, joints, robot] of p5) {
    await page.evaluate((s) => window.cspacelab.openProblem('P5', s), seed);
    await waitFrames(page, 2);
    assert.ok((await api(page, 'homework_state')).exercise.prompt.includes(joints), `P5 seed ${seed}: ${joints}`);
    c = await answer(page, typed);
    assert.equal(c.correct, true, `P5 seed ${seed}: ${typed}: ${c.explanation}`);
    if (robot === null) {
      assert.equal(await pageButton(page, 'see-in-3d'), null, `P5 seed ${seed}: no 3-D picture of T^2 x R`);
      continue;
    }
    await press(page, 'see-in-3d');
    assert.equal((await api(page, 'status')).lesson, 'cspace-3d');
    assert.equal((await api(page, 'state')).robot, robot, `P5 seed ${seed}`);
  }

  // A reload of the problem link: the saved work stands and the problem's card comes back.
  await page.evaluate(() => window.cspacelab.shell.saveNow && window.cspacelab.shell.saveNow());
  await page.reload();
  await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2);
  hw = await api(page, 'homework_state');
  assert.equal(hw.problem, 'P10');
  assert.equal(hw.exercise.seed, 7);
  assert.equal((await api(page, 'status')).lesson, 'distances');
}));

test('problem links: bad ones are named and change nothing; a problem in a 900 px embed',
  () => withBrowser(async ({ browser, url }) => {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const errors = collectErrors(page);
  await openLab(page, url + '?problem=P99&seed=x');
  await page.waitForFunction(() => window.cspacelab.status().notice !== '');
  const notice = (await api(page, 'status')).notice;
  assert.match(notice, /problem "P99"/);
  assert.match(notice, /seed "x"/);
  assert.equal((await api(page, 'homework_state')).problem, null);

  const host = url + 'hw-host.html';
  await page.route(host, (route) => route.fulfill({
    contentType: 'text/html',
    body: `<!doctype html><html><head><meta charset="utf-8"><title>course</title></head><body style="margin:0">
      <iframe src="embed.html?problem=P11&amp;seed=3" style="border:0;width:900px;height:600px" title="lab"></iframe></body></html>`,
  }));
  await page.goto(host);
  const frame = await (await page.waitForSelector('iframe')).contentFrame();
  await frame.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2, null, { timeout: 30000 });
  const hw = await frame.evaluate(() => window.cspacelab.call('homework_state'));
  assert.equal(hw.problem, 'P11');
  assert.equal(hw.exercise.seed, 3);
  await frame.waitForFunction((n) => window.cspacelab.status().frames >= n,
                              (await frame.evaluate(() => window.cspacelab.status().frames)) + 3);
  const look = await lessonProbes(frame);
  await expectView(page, browser, 'homework-embed-900.png', look.probes, look.view, { misses: look.misses || 0, frame });
  assert.deepEqual(errors, []);
}));

// Typing × and superscripts (issue 21): the card's hint says "x or ×, ^ or superscripts", but a
// character that comes without a key press (a character palette, a compose key, an on-screen
// keyboard; Playwright types such characters with insertText) was dropped: "R² × S¹" arrived as
// "R  S". Typed here character by character into the answer field, as a student does.
test('an answer typed with × and superscripts arrives whole and is checked',
  () => withPage({ open: '?problem=P1&seed=1' }, async ({ page }) => {
  await page.waitForFunction(() => window.cspacelab.call('homework_state', {}).problem === 'P1');
  const exercise = cli('exercise', 'P1', '--seed', '1');
  assert.match(exercise.prompt, /spin/, 'a planar robot that turns: Q = R^2 x S^1');
  for (const typed of ['R² × S¹', 'S¹ × R²', 'R^2×S^1']) {
    const check = await answer(page, typed);
    assert.equal((await api(page, 'homework_state')).answer, typed, 'every character arrived');
    assert.equal(check.correct, true, `${typed}: ${check.explanation}`);
  }
  const wrong = await answer(page, 'R³ × S¹');
  assert.equal((await api(page, 'homework_state')).answer, 'R³ × S¹');
  assert.equal(wrong.correct, false);
}));
