// WCAG 2.1 AA as axe-core checks it in the browser: no serious or critical violation on the full
// lab, the embed and the course page, in every lesson, with the Share and Embed dialogs open and
// on the panel that takes a stopped lab's place, in assignment mode (the card's page copy, asking
// and after Submit) and in the Author view. axe sees the page's DOM: the canvas's label and
// the dialogs now, any HTML the page grows for screen readers later (it runs over all of it).
// A failure lists every state with its violations' ids and the elements they were found on.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, collectErrors, openLab, openLabs, waitFrames, screenshot } from './lib/harness.mjs';
import { newAxeContext, runAxe } from './lib/axe.mjs';

/**
 * Checks `target` in each lesson of the lab `lab` (a CSS selector of its [data-lab] element, or
 * null: window.cspacelab), then goes back to the first; pushes "state: violation" onto `found`.
 */
async function everyLesson(target, where, found, lab = null) {
  const call = (fn, ...args) => target.evaluate(([sel, f, a]) => {
    const api = sel ? document.querySelector(sel).cspacelab : window.cspacelab;
    return api[f](...a);
  }, [lab, fn, args]);
  const lessons = await call('lessons');
  assert.ok(lessons.length >= 5, `${where}: the lessons are listed`);
  for (const { id } of lessons) {
    await call('selectLesson', id);
    await target.waitForFunction(([sel, want]) => {
      const api = sel ? document.querySelector(sel).cspacelab : window.cspacelab;
      return api.status().lesson === want;
    }, [lab, id]);
    await waitFrames(target, 2);
    await check(target, `${where}, lesson ${id}`, found);
  }
  await call('selectLesson', lessons[0].id);
}

async function check(target, state, found) {
  const { blocking, other } = await runAxe(target);
  for (const v of blocking) found.push(`${state}: ${v}`);
  // Moderate and minor findings do not fail the test; they are shown for the record.
  for (const v of other) console.log(`# axe, not blocking: ${state}: ${v}`);
}

function expectNone(found) {
  assert.deepEqual(found, [], `axe found ${found.length} serious or critical violation(s):\n  ${found.join('\n  ')}`);
}

test('index.html and embed.html: no serious or critical axe violation in any lesson, nor in their dialogs',
  () => withBrowser(async ({ browser, url }) => {
  const context = await newAxeContext(browser);
  await context.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
  const found = [];
  // (The embed with a task: the task's section above the canvas is checked with it.)
  for (const file of ['index.html', 'embed.html?lesson=collision&scene=p12&task=Find%20the%20smallest%20N.%0AWhy%20that%20one%3F']) {
    const page = await context.newPage();
    const errors = collectErrors(page);
    await openLab(page, url + file);
    await check(page, file, found);
    await everyLesson(page, file, found);
    // Share and Embed: the page's dialogs, opened as the app's buttons open them.
    for (const action of ['share', 'embed']) {
      await page.evaluate((a) => window.cspacelab.module.cslPageAction(a), action);
      await page.waitForSelector('.lab-dialog[role=dialog]');
      await check(page, `${file}, ${action} dialog`, found);
      await page.keyboard.press('Escape');
      await page.waitForSelector('.lab-dialog', { state: 'detached' });
    }
    assert.deepEqual(errors, [], `${file}: no console errors`);
    await page.close();
  }
  // The first visit's welcome (drawn in the app, but it changes what the panel holds).
  const fresh = await browser.newContext({ bypassCSP: true, viewport: { width: 1280, height: 800 } });
  const first = await fresh.newPage();
  await openLab(first, url);
  assert.equal((await first.evaluate(() => window.cspacelab.pageState())).welcome, true);
  await check(first, 'index.html, first visit', found);
  await fresh.close();
  expectNone(found);
}));

test('a lab that stopped: the panel in its place passes axe', () => withBrowser(async ({ browser, url }) => {
  const context = await newAxeContext(browser);
  const page = await context.newPage();
  await openLab(page, url);
  // What Emscripten calls when the wasm aborts (lab.js routes it to the page shell).
  await page.evaluate(() => window.cspacelab.module.onAbort('an abort injected by the accessibility test'));
  await page.waitForSelector('.lab-crash[role=dialog]');
  await screenshot(page, 'accessibility-crash-panel.png');
  const found = [];
  await check(page, 'index.html, the crash panel', found);
  expectNone(found);
}));

test('the course page: no serious or critical axe violation, each lesson in its first lab',
  () => withBrowser(async ({ browser, url }) => {
  const context = await newAxeContext(browser, { viewport: { width: 1100, height: 800 } });
  const page = await context.newPage();
  const errors = collectErrors(page);
  await openLabs(page, url + 'examples/course-page.html', ['#lab-collision', '#lab-prm']);
  const found = [];
  await check(page, 'course page', found);
  await everyLesson(page, 'course page', found, '#lab-collision');
  assert.deepEqual(errors, [], 'no console errors');
  expectNone(found);
}));

test('the dark look and high contrast: the page\'s dialogs and the parallel DOM pass axe in each',
  () => withBrowser(async ({ browser, url }) => {
  // The browser's own preferences (what a student's system sets), not the app's menu: the
  // page must pick them up by itself.
  const found = [];
  for (const [name, media] of [['dark', { colorScheme: 'dark' }], ['high contrast', { contrast: 'more' }],
                               ['dark, high contrast', { colorScheme: 'dark', contrast: 'more' }]]) {
    const context = await newAxeContext(browser);
    await context.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
    const page = await context.newPage();
    await page.emulateMedia(media);
    const errors = collectErrors(page);
    await openLab(page, url + '?lesson=step-prm&task=Find+a+path+with+at+most+100+samples.');  // the task section too
    const look = await page.evaluate(() => window.cspacelab.pageState().look);
    assert.deepEqual(look, { dark: !!media.colorScheme, high_contrast: !!media.contrast }, `${name}: the app follows the browser`);
    assert.equal(await page.evaluate(() => document.querySelector('.lab').dataset.look),
                 (media.colorScheme ? 'dark' : 'light') + (media.contrast ? ' high' : ''));
    await check(page, name, found);
    // The parallel DOM shown (keyboard inside it), then a dialog.
    await page.focus('.lab-access button');
    await check(page, `${name}, the parallel DOM shown`, found);
    await page.evaluate(() => window.cspacelab.module.cslPageAction('share'));
    await page.waitForSelector('.lab-dialog[role=dialog]');
    await screenshot(page, `accessibility-${name.replace(/[ ,]+/g, '-')}-share.png`);
    await check(page, `${name}, share dialog`, found);
    assert.deepEqual(errors, [], `${name}: no console errors`);
    await context.close();
  }
  expectNone(found);
}));

test('the homework card\'s and an assignment\'s page copies (before and after Submit) and the Author view pass axe',
  () => withBrowser(async ({ browser, url }) => {
  // The parts of the page that only a problem or an assignment brings, which the tests above
  // never open: lab-homework-access.js's card answered, lab-assignment-access.js's group (shown,
  // the keyboard inside it) and lab-author.js's dialog.
  const found = [];
  const context = await newAxeContext(browser);
  await context.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
  const page = await context.newPage();
  const errors = collectErrors(page);
  await openLab(page, url + 'index.html?problem=P10&seed=7');
  await page.waitForSelector('.lab-access-homework-card:not([hidden])', { state: 'attached' });
  await page.locator('.lab-access-homework input').fill('2');
  await page.locator('.lab-access-homework-card').getByRole('button', { name: 'Check' }).click();
  await page.waitForFunction(() => /^Not quite/.test(document.querySelector('.lab-access-homework [aria-live]').textContent));
  await page.focus('.lab-access-homework input');
  await check(page, 'the homework card\'s copy, answered', found);
  await openLab(page, url + 'index.html?assignment=examples/assignment-example.json');
  await page.waitForFunction(() => {
    const g = document.querySelector('.lab-access-assignment');
    return g && !g.hidden;
  }, null, { timeout: 30000 });
  await page.focus('.lab-access-assignment input');
  await check(page, 'assignment, the card\'s copy shown', found);
  await page.locator('.lab-access-assignment').getByRole('button', { name: 'Submit...' }).click();
  await check(page, 'assignment, Submit asking', found);
  await page.locator('.lab-access-assignment').getByRole('button', { name: /Yes, submit/ }).click();
  await page.waitForFunction(() => window.cspacelab.call('assignment_state').submitted);
  await check(page, 'assignment, the review', found);
  // The Author view with a draft of each kind of item (the dialog reads a stored draft).
  await page.evaluate(() => localStorage.setItem('cspacelab:v1:author:' + location.pathname, JSON.stringify({
    title: 'Week 3', description: 'Roadmaps', pass: '0.6', seed_key: '', items: [
      { kind: 'exercise', title: '', problem: 'P10', seedMode: 'fixed', seed: '4', points: '2', tolerance: '0.01' },
      { kind: 'explore', title: 'Look', prompt: 'Step PRM once', lesson: 'step-prm', scene: null, params: {}, points: '0' },
      { kind: 'task', title: 'Solve', prompt: 'Find a path', lesson: 'step-prm', scene: null, params: {}, points: '1',
        check: '{"pointer": "/solved", "equals": true}' }],
  })));
  await openLab(page, url + 'index.html?author=1');
  await page.locator('.lab-author').waitFor({ state: 'visible' });
  assert.equal(await page.locator('.lab-author [data-item]').count(), 3, 'axe sees the three items');
  await check(page, 'the Author view', found);
  await screenshot(page, 'accessibility-author.png');
  assert.deepEqual(errors, [], 'no console errors');
  await context.close();
  expectNone(found);
}));
