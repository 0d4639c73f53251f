// The homework by keyboard alone, as a student with a screen reader meets it: the page's copy of
// the Homework map and card (web/lab-homework-access.js) in the accessible section. From the
// lab's focus: Tab to the problem list, P10 chosen with the arrow keys and opened, an answer
// wrong (twice, read twice; no answer in the feedback), the solution asked for, and right,
// checked against the S^1 distance computed here; the
// numbers shown in the tool; New numbers; Close. Then P1 answered and its C-space in 3-D, a check
// made on the canvas's card followed by the copy, and a minimal embed with a problem link.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, withBrowser, collectErrors, openLab, api, waitFrames, recordLive, focused, tabTo,
         tabToButton } from './lib/harness.mjs';
import { s1, visibility } from '../lib/homework-answers.mjs';

const G = '.lab-access-homework';

const verdict = (page) => page.locator(`${G} [aria-live]`).textContent();

// Types into the focused answer field (clearing it first) and presses Enter.
async function typeAnswer(page, text) {
  await page.keyboard.press('Control+A');
  await page.keyboard.press('Backspace');
  await page.keyboard.type(text);
  await page.keyboard.press('Enter');
}

test('homework by keyboard alone: P10 from the list, wrong and right, its numbers, New numbers, Close',
  () => withPage({ open: 'index.html?lesson=step-prm' }, async ({ page }) => {
  await page.waitForSelector(`${G} select`, { state: 'attached' });
  await recordLive(page, `${G} [aria-live]`);  // every word it gets, in order
  const list = await api(page, 'homework');
  assert.deepEqual(await page.locator(`${G} option`).allTextContents(), list.map((p) => `${p.id}: ${p.title}`));
  assert.equal(await page.locator(`${G}-card`).isHidden(), true, 'no card before a problem is open');

  // The lab has the keyboard; the list is the first Tab on (before the lessons and parameters).
  await page.locator('canvas').focus();
  assert.equal(await tabTo(page, () => document.activeElement.tagName === 'SELECT', 3, 'the problem list'), 1);
  for (let n = 0; n < 12 && await page.locator(`${G} select`).inputValue() !== 'P10'; ++n) await page.keyboard.press('ArrowDown');
  assert.equal(await page.locator(`${G} select`).inputValue(), 'P10');
  assert.equal((await api(page, 'homework_state')).problem, null, 'choosing in the list opens nothing yet');
  await page.keyboard.press('Tab');
  assert.equal(await focused(page), 'Open the problem');
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => document.activeElement.tagName === 'H4');
  assert.match(await focused(page), /^P10: /, 'the focus is on the problem\'s heading');
  let hw = await api(page, 'homework_state');
  assert.equal(hw.problem, 'P10');
  assert.equal((await api(page, 'status')).lesson, 'distances');
  const card = page.locator(`${G}-card`);
  let text = await card.textContent();
  assert.ok(text.includes(list.find((p) => p.id === 'P10').task), 'the problem\'s task');
  assert.ok(text.includes(`Exercise P10, numbers no. ${hw.exercise.seed}`));
  for (const line of hw.exercise.prompt.split('\n').filter((l) => l.trim())) assert.ok(text.includes(line), line);
  assert.ok(text.includes(hw.exercise.format_hint), 'the answer\'s format');
  // Nothing is given away before an answer, as on the canvas's card.
  assert.doesNotMatch(text, /answer is|Right|Not quite/);
  assert.equal(await card.getByRole('button', { name: 'Show these numbers in the tool' }).isHidden(), true);

  // The answer field is one Tab on (the task and the exercise are text, not stops).
  assert.equal(await tabTo(page, () => document.activeElement.tagName === 'INPUT', 2, 'the answer field'), 1);
  const { q1, q2 } = hw.exercise.given;
  const d = s1(q1, q2);
  // Off, and no typical mistake (whose reason the feedback would give): d + 0.5 unless that is
  // near the longer way round, 2 pi - d.
  const wrong = Math.abs(d + 0.5 - (2 * Math.PI - d)) > 0.1 ? d + 0.5 : d + 0.25;
  await typeAnswer(page, wrong.toFixed(3));
  await page.waitForFunction((g) => /^Not quite: you wrote /.test(document.querySelector(`${g} [aria-live]`).textContent), G);
  // What went wrong, not the answer: another try is still worth something.
  assert.doesNotMatch(await verdict(page), /answer is|mod 2 pi/);
  assert.equal((await api(page, 'homework_state')).check.correct, false);
  // The same wrong answer again is read again (the region is emptied and set).
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => window.cspacelab.call('homework_state').scores.P10.tried === 2);
  await page.waitForFunction(() => window.__said.length >= 2);
  const said = await page.evaluate(() => window.__said);
  assert.equal(said.length, 2, said.join(' | '));
  assert.equal(said[0], said[1]);
  // The solution on request: Check, then Show the solution; the focus goes back to the field.
  await tabToButton(page, 'Show the solution', 3);
  await page.keyboard.press('Enter');
  await page.waitForFunction((g) => /the answer is .*mod 2 pi/s.test(document.querySelector(`${g} [aria-live]`).textContent), G);
  assert.equal(await page.evaluate(() => document.activeElement.tagName), 'INPUT');
  assert.equal((await api(page, 'homework_state')).solution_shown, true);
  await typeAnswer(page, d.toFixed(3));
  await page.waitForFunction((g) => /^Right: /.test(document.querySelector(`${g} [aria-live]`).textContent), G);
  assert.equal(await page.evaluate(() => document.activeElement.tagName), 'INPUT', 'the focus stays in the field');
  assert.deepEqual((await api(page, 'homework_state')).scores.P10, { tried: 3, right: 1 });
  assert.match(await card.textContent(), /This visit: 1 solved in 3 tries\./);
  assert.match(await page.locator(`${G} option[value=P10]`).textContent(), /\(solved\)$/);

  // Answered: the exercise's own numbers go into the tool.
  await tabToButton(page, 'Show these numbers in the tool', 3);
  await page.keyboard.press('Enter');
  await waitFrames(page, 2);
  const tool = await api(page, 'state');
  assert.deepEqual([tool.q1, tool.q2], [q1, q2]);

  // New numbers: another exercise, read out from its start; the field and the verdict empty.
  const seed = hw.exercise.seed;
  await tabToButton(page, 'New numbers', 3);
  await page.keyboard.press('Enter');
  await page.waitForFunction((s) => window.cspacelab.call('homework_state').exercise.seed !== s, seed);
  hw = await api(page, 'homework_state');
  await page.waitForFunction(() => document.activeElement.getAttribute('aria-label') === 'Exercise');
  assert.ok((await focused(page)).startsWith(`Exercise P10, numbers no. ${hw.exercise.seed}`));
  assert.equal(await page.locator(`${G} input`).inputValue(), '');
  assert.equal(await verdict(page), '');
  assert.equal(await card.getByRole('button', { name: 'Show these numbers in the tool' }).isHidden(), true);

  // Close: the card goes, the focus goes back to the list, the lesson stays.
  await tabToButton(page, 'Close', 4);
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => document.activeElement.tagName === 'SELECT');
  assert.equal((await api(page, 'homework_state')).problem, null);
  assert.equal(await card.isHidden(), true);
  assert.equal((await api(page, 'status')).lesson, 'distances');
}));

test('homework by keyboard: P1 answered opens SE(2) in 3-D; a check on the canvas\'s card is followed; a minimal embed',
  () => withBrowser(async ({ browser, url }) => {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  await page.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
  const errors = collectErrors(page);
  await openLab(page, url + 'index.html?problem=P1&seed=3');
  const card = page.locator(`${G}-card`);
  await page.waitForFunction((g) => {
    const c = document.querySelector(`${g}-card`);
    return c && !c.hidden && c.textContent.includes('P1: ');
  }, G);
  assert.equal(await page.locator(`${G} select`).inputValue(), 'P1', 'the list shows the open problem');
  const button3d = card.getByRole('button', { name: 'See SE(2) in 3-D' });
  assert.equal(await button3d.count(), 0, 'the 3-D picture, whose title names the answer, waits for an answer');
  await page.locator(`${G} input`).focus();
  await typeAnswer(page, 'R^2 x S^1');
  await page.waitForFunction((g) => /^Right: /.test(document.querySelector(`${g} [aria-live]`).textContent), G);
  await tabToButton(page, 'See SE(2) in 3-D', 3);
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => window.cspacelab.status().lesson === 'cspace-3d');
  assert.equal((await api(page, 'state')).robot, 'polygon');
  await page.waitForFunction(() => document.activeElement.classList.contains('lab-access-description'));
  assert.equal(await card.isHidden(), true, 'the card stays with its lesson, as on the canvas');

  // A check made elsewhere (the canvas's card, a page script) shows in the copy.
  await page.evaluate(() => window.cspacelab.openProblem('P12', 11));
  await page.waitForFunction((g) => document.querySelector(`${g} h4`).textContent.startsWith('P12: '), G);
  await page.evaluate(() => window.cspacelab.checkAnswer('1'));
  await page.waitForFunction((g) => /^Not quite: /.test(document.querySelector(`${g} [aria-live]`).textContent), G);
  assert.deepEqual(errors, [], 'no console errors');
  await page.close();

  // A minimal embed has no Homework button, so no list; a problem link's card is there.
  const embed = await browser.newPage({ viewport: { width: 900, height: 600 } });
  await openLab(embed, url + 'embed.html?problem=P10&seed=7');
  await embed.waitForFunction((g) => {
    const c = document.querySelector(`${g}-card`);
    return c && !c.hidden;
  }, G);
  assert.equal(await embed.locator(`${G} select`).count(), 0);
  await embed.locator(`${G} input`).focus();
  const { q1, q2 } = (await api(embed, 'homework_state')).exercise.given;
  await typeAnswer(embed, s1(q1, q2).toFixed(3));
  await embed.waitForFunction((g) => /^Right: /.test(document.querySelector(`${g} [aria-live]`).textContent), G);
  await tabToButton(embed, 'Close', 5);
  await embed.keyboard.press('Enter');
  await embed.waitForFunction(() => document.activeElement.classList.contains('lab-access-description'));
  await embed.close();
}));

test('P9 by keyboard: its numbers in the tool, and "What the view shows" describes the square, not the scene',
  () => withPage({ open: 'index.html?problem=P9&seed=5' }, async ({ page }) => {
  await page.waitForSelector(`${G}-card:not([hidden])`, { state: 'attached' });
  const { x, y, d } = (await api(page, 'homework_state')).exercise.given;
  const p = visibility(x, y, d);
  await page.locator(`${G} input`).focus();
  await typeAnswer(page, p.toFixed(3));
  await page.waitForFunction((g) => /^Right: /.test(document.querySelector(`${g} [aria-live]`).textContent), G);
  await tabToButton(page, 'Show these numbers in the tool', 3);
  await page.keyboard.press('Enter');
  const sig = (v) => Number(v.toPrecision(4)).toString();
  await page.waitForFunction(([g]) => document.querySelector('.lab-access-description').textContent.includes(`gap d = ${g})`),
                             [sig(d)]);
  const text = await page.locator('.lab-access-description').textContent();
  assert.ok(text.includes(`open from y = ${sig(0.5 - d / 2)} to ${sig(0.5 + d / 2)}`), text);
  assert.ok(text.includes(`(x1, y1) = (${sig(x)}, ${sig(y)})`), text);
  const exact = Number(/= ([0-9.]+) exact/.exec(text)[1]);
  assert.ok(Math.abs(exact - p) < 1e-4, `the description's p ${exact}, computed here ${p}`);
  assert.doesNotMatch(text, /No experiment|wall 1 from/, 'the square, not the scene of tab Bound');
}));
