// The side panel at 1280 x 800, as a student meets it: every lesson's first state fits without
// scrolling; what grows (a run's numbers, an exercise's text) either fits or shows the cue under
// the panel, which scrolls when pressed; sections fold and unfold under the mouse.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, api, click, waitFrames, pageButton, screenshot, inspectPng } from './lib/harness.mjs';

const panel = async (page) => (await api(page, 'status')).panel;

// Presses one of the app's controls (by the name page_state gives it) with the mouse.
async function press(page, name) {
  const at = await pageButton(page, name);
  assert.ok(at, `the control "${name}" is on screen`);
  await click(page, at);
}

test('every lesson\'s first state fits the panel at 1280 x 800', () => withPage(async ({ page }) => {
  const lessons = await api(page, 'lessons');
  assert.ok(lessons.length >= 7);
  for (const { id } of lessons) {
    await api(page, 'select_lesson', { id });
    await page.mouse.move(2, 2);
    await waitFrames(page, 4);
    const p = await panel(page);
    assert.ok(p.height > 600, `${id}: the panel is ${p.height} px tall`);
    assert.ok(p.scroll_max <= 0.5 && !p.cue, `${id}: ${p.content} px of content in ${p.height} (more below: ${p.more_below})`);
  }
}));

// A student's very first visit: the welcome above the lesson's panel, and still everything in view.
test('a first visit, with its welcome, fits the panel too', () => withPage({ welcome: true }, async ({ page }) => {
  await page.mouse.move(2, 2);
  await waitFrames(page, 4);
  assert.equal((await api(page, 'homework_state')).welcome, true, 'the welcome is shown');
  const p = await panel(page);
  assert.ok(p.scroll_max <= 0.5 && !p.cue, `${p.content} px of content in ${p.height}`);
}));

test('what grows past the panel shows the cue, and the cue scrolls to it',
  () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'torus' });
  await waitFrames(page, 3);
  // Run all, then the loop around the torus, both with the mouse.
  await press(page, 'run-all');
  await page.waitForFunction(() => !window.cspacelab.status().busy && window.cspacelab.call('state', {}).prm.phase === 'done',
                             null, { timeout: 60000 });
  await press(page, 'torus-loop-around');
  await waitFrames(page, 6);
  let p = await panel(page);
  assert.equal((await api(page, 'state')).exercise, 'around');
  assert.ok(p.content > p.height, `the exercise's text makes the panel taller (${p.content} in ${p.height})`);
  assert.equal(p.cue, true, 'the cue shows under the panel');
  const { png } = await screenshot(page, 'panel-cue-torus-loop.png');
  // The cue is drawn where page_state says: a button of the lab's blue tint across the panel.
  let buttons = (await api(page, 'page_state')).buttons;
  const cue = buttons['panel-more'];
  assert.ok(cue && cue[2] - cue[0] > 250, `the cue spans the panel: ${cue}`);
  const [[r, g, b]] = (await inspectPng(browser, png, [[cue[0] + 6, (cue[1] + cue[3]) / 2]])).at;
  assert.ok(b > r + 20 && b > 150, `the cue's colour at its left end: ${[r, g, b]}`);
  // The exercise's text, just added, was scrolled into view: its last control is above the cue.
  const stop = buttons['torus-loop-stop'];
  assert.ok(stop && stop[3] <= cue[1] && stop[1] > 80, `the exercise's end is in view: ${stop}, cue at ${cue[1]}`);

  // The cue goes down a page at a time to the end, then back to the top.
  for (let i = 0; p.more_below && i < 4; ++i) {
    const before = p.scroll;
    await press(page, 'panel-more');
    await waitFrames(page, 3);
    p = await panel(page);
    assert.ok(p.scroll > before + 20, `down: ${before} -> ${p.scroll}`);
  }
  assert.equal(p.more_below, false, 'at the end');
  assert.ok(p.scroll >= p.scroll_max - 4);
  await press(page, 'panel-more');
  await waitFrames(page, 3);
  p = await panel(page);
  assert.ok(p.scroll < 1 && p.more_below, `back at the top: ${p.scroll}`);

  // A section folds under the mouse and the panel fits again.
  await press(page, 'section:PRM on the torus');
  await waitFrames(page, 4);
  p = await panel(page);
  const prm = p.sections.find((s) => s.title === 'PRM on the torus');
  assert.equal(prm.open, false, 'folded');
  assert.ok(p.content <= p.height + 0.5 && !p.cue, `fits folded: ${p.content} in ${p.height}`);
  await press(page, 'section:PRM on the torus');
  await waitFrames(page, 3);
  assert.equal((await panel(page)).sections.find((s) => s.title === 'PRM on the torus').open, true, 'open again');
}));

test('the collision lesson keeps its obstacle tools and its whole trace in view',
  () => withPage(async ({ page }) => {
  await api(page, 'select_lesson', { id: 'collision' });
  await api(page, 'set_params', { params: { q: [1, -0.3] } });
  await waitFrames(page, 2);
  await press(page, 'finish-phase');
  await waitFrames(page, 3);
  const s = await api(page, 'state');
  assert.equal(s.shown, s.bisection.trace.length + s.bisection.pieces.length, 'the bisection ran to its end');
  const p = await panel(page);
  assert.ok(!p.cue && p.scroll_max <= 0.5, `fits: ${p.content} in ${p.height}`);
  // The obstacle tools are a section of the panel, open.
  const tools = p.sections.find((x) => x.title.startsWith('Obstacles'));
  assert.ok(tools && tools.open, 'the obstacle tools are open in the panel');
  const header = await pageButton(page, `section:${tools.title}`);
  assert.ok(header.y < 780, 'and on screen');
}));
