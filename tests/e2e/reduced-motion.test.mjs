// prefers-reduced-motion (WCAG 2.1 2.3.3): when the browser asks for it, nothing in the lab
// moves by itself. The page passes the preference to the app (page_state reduced_motion, also
// when it changes); the torus lesson's loop exercise then draws its loop whole instead of
// walking the arm around it, and the notation lesson's sphere shows three loops shrinking
// instead of one sliding. Each lesson's picture must stay the same over time; the same check
// without the preference sees the motion (so it can fail).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, collectErrors, openLab, waitFrames, api, pageButton, click } from './lib/harness.mjs';

/** Two pictures of the canvas 1.2 s apart, compared byte for byte. */
async function still(page) {
  await page.mouse.move(1, 1);
  await waitFrames(page, 3);
  const clip = await page.locator('canvas').boundingBox();
  const a = await page.screenshot({ clip });
  await page.waitForTimeout(1200);
  await waitFrames(page, 3);
  const b = await page.screenshot({ clip });
  return a.equals(b);
}

async function open(browser, url, reducedMotion, link = '') {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, reducedMotion });
  await context.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
  const page = await context.newPage();
  const errors = collectErrors(page);
  await openLab(page, url + link);
  return { page, errors, context };
}

test('reduced motion: the app knows, and no lesson moves by itself', () => withBrowser(async ({ browser, url }) => {
  const { page, errors, context } = await open(browser, url, 'reduce');
  assert.equal((await api(page, 'page_state')).reduced_motion, true, 'the page told the app');
  const moving = [];
  for (const { id } of await api(page, 'lessons')) {
    await api(page, 'select_lesson', { id });
    if (!(await still(page))) moving.push(id);
  }
  assert.deepEqual(moving, [], 'lessons whose picture changed by itself');
  // A preference changed while the lab is open reaches the app too.
  await page.emulateMedia({ reducedMotion: 'no-preference' });
  await page.waitForFunction(() => window.cspacelab.pageState().reduced_motion === false);
  await page.emulateMedia({ reducedMotion: 'reduce' });
  await page.waitForFunction(() => window.cspacelab.pageState().reduced_motion === true);
  assert.deepEqual(errors, []);
  await context.close();
}));

/** Presses the torus lesson's "a loop around the torus" (the exercise that walks the arm). */
async function startLoop(page) {
  await click(page, await pageButton(page, 'torus-loop-around'));
  await page.mouse.move(1, 1);
  await waitFrames(page, 3);
}

test('reduced motion: the torus loop exercise shows its loop whole and still', () => withBrowser(async ({ browser, url }) => {
  const { page, errors, context } = await open(browser, url, 'reduce', '?lesson=torus');
  await startLoop(page);
  const s = await api(page, 'state');
  assert.equal(s.exercise, 'around');
  assert.equal(s.animate, false, 'the arm does not walk by itself');
  assert.ok(s.trail >= 200, `the loop drawn whole (${s.trail} points)`);
  assert.match(s.workspace_caption, /not a (planned )?path/, 'and still explained');
  assert.ok(await still(page), 'the picture stays');
  assert.deepEqual((await api(page, 'state')).q, s.q);
  assert.deepEqual(errors, []);
  await context.close();
}));

test('without the preference the same checks see the motion', () => withBrowser(async ({ browser, url }) => {
  const { page, errors, context } = await open(browser, url, 'no-preference', '?lesson=torus');
  assert.equal((await api(page, 'page_state')).reduced_motion, false);
  await startLoop(page);
  const q = (await api(page, 'state')).q;
  assert.equal((await api(page, 'state')).animate, true);
  assert.equal(await still(page), false, 'the torus loop walks');
  assert.notDeepEqual((await api(page, 'state')).q, q);
  await api(page, 'select_lesson', { id: 'notation' });
  assert.equal(await still(page), false, 'the sphere\'s loop slides');
  assert.deepEqual(errors, []);
  await context.close();
}));
