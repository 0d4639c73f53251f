// A restore that crashes or freezes the lab must not brick it (issue 27, finding 1). The wasm
// side of the real crash (a scene 1e-15 wide) is fixed elsewhere, so these tests inject one: the
// first restore of a tab throws the wasm's RuntimeError, traps in the next frame, or never
// returns. Then: the lab's place says what happened and offers the work (export and discard
// work without the wasm); the next start opens clean and offers the work in a dialog whose
// "Try to restore it again", "Export it (JSON file)" and "Discard it" do what they say.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import zlib from 'node:zlib';
import { withBrowser, collectErrors, openLab, api, screenshot, waitFrames, click, pageButton } from './lib/harness.mjs';
import { sceneWith, setWork, waitSavedScene, failFirstRestore, downloadFrom, sceneOf, historyLabels, savedWork,
         deepSceneText, startedOrStopped, importByPicker, backgroundTab, markers, recursiveStringify } from './lib/saves.mjs';

const WORK = sceneWith(3, 'my three disks');

/** A context whose lab has saved WORK (Step PRM, seed 9, step 40). */
async function contextWithWork(browser, url, viewport = { width: 1280, height: 800 }) {
  const ctx = await browser.newContext({ viewport });
  const page = await ctx.newPage();
  const errors = collectErrors(page);
  await openLab(page, url);
  await setWork(page, WORK);
  await api(page, 'set_params', { params: { seed: 9, samples: 80 } });
  await api(page, 'run_to', { steps: 40 });
  await waitSavedScene(page, WORK.name);
  await page.close();
  assert.deepEqual(errors, []);
  return ctx;
}

const dialog = '.lab-dialog[role=dialog]';
const button = (action) => `${dialog} button[data-action=${action}]`;

/** Opens the lab in a new page that must start clean and offer the work; returns the page. */
async function cleanStartOffering(ctx, url, shot) {
  const page = await ctx.newPage();
  const errors = collectErrors(page);
  await openLab(page, url);
  await page.waitForSelector(dialog);
  const text = await page.textContent(dialog);
  assert.match(text, /Your work could not be restored/);
  assert.match(text, /opened with the lessons' defaults/);
  assert.match(text, /could not be restored · Step PRM/, 'it names where the work is kept');
  const labels = await page.$$eval(`${dialog} .lab-dialog-actions button`, (bs) => bs.map((b) => b.textContent));
  assert.deepEqual(labels.slice(0, 3), ['Try to restore it again', 'Export it (JSON file)', 'Discard it']);
  // Clean: the first lesson only, with its defaults; nothing of the failed work was restored.
  const lessons = await api(page, 'lessons');
  assert.deepEqual(lessons.filter((l) => l.open).map((l) => l.id), [lessons[0].id], 'only the first lesson, fresh');
  assert.match((await api(page, 'status')).notice, /Opened with the lessons' defaults/);
  assert.match((await historyLabels(page))[0], /could not be restored · Step PRM/, 'the work is in the history');
  if (shot) await screenshot(page, shot);
  // The keyboard reaches every choice: focus starts on the first, Tab goes on.
  assert.equal(await page.evaluate(() => document.activeElement.textContent), 'Try to restore it again');
  await page.keyboard.press('Tab');
  assert.equal(await page.evaluate(() => document.activeElement.textContent), 'Export it (JSON file)');
  return { page, errors };
}

test('a restore that traps: the lab says so in its place; the next start opens clean and offers the work',
  () => withBrowser(async ({ browser, url }) => {
  const ctx = await contextWithWork(browser, url);

  // The restore of the saved work throws the wasm's RuntimeError.
  const crashed = await ctx.newPage();
  await failFirstRestore(crashed, 'trap');
  await crashed.goto(url);
  await crashed.waitForSelector('.lab-crash[role=dialog]', { timeout: 30000 });
  const panel = await crashed.textContent('.lab-crash');
  assert.match(panel, /C-Space Lab stopped/);
  assert.match(panel, /memory access out of bounds/);
  assert.equal(await crashed.isVisible('.lab-status'), false, 'no endless "Loading C-Space Lab…"');
  await screenshot(crashed, 'restore-crash-panel.png');
  // Export works without the wasm: the saved work, read from storage.
  const exported = await downloadFrom(crashed, '.lab-crash button[data-action=export]');
  assert.deepEqual(sceneOf(exported.value), WORK);
  assert.equal(exported.value.lessons['step-prm'].steps, 40);
  await crashed.close();

  // The next start: clean, the work offered. Export it, then try again.
  const { page, errors } = await cleanStartOffering(ctx, url, 'restore-crash-dialog.png');
  const file = await downloadFrom(page, button('export'));
  assert.match(file.name, /^cspacelab-work-.*\.json$/);
  assert.deepEqual(sceneOf(file.value), WORK, 'the exported file holds the work');
  assert.equal(file.value.lessons['step-prm'].params.seed, 9, 'with its parameters');
  assert.equal(file.value.lessons['step-prm'].steps, 40, 'and its step');
  await page.click(button('retry'));
  await page.waitForFunction(() => window.cspacelab.status().lesson === 'step-prm');
  assert.equal(await page.isVisible(dialog), false);
  assert.deepEqual(await api(page, 'get_scene'), WORK, 'try again restores it');
  const state = await api(page, 'state');
  assert.equal(state.steps, 40);
  assert.equal(state.params.seed, 9);
  assert.deepEqual(await historyLabels(page), [], 'it left the history; the clean start was not worth keeping');
  await waitSavedScene(page, WORK.name);
  await page.reload();
  await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2);
  await waitFrames(page, 3);
  assert.deepEqual(await api(page, 'get_scene'), WORK, 'and it is the saved work again');
  assert.equal(await page.isVisible(dialog), false, 'no dialog once it restored');
  assert.deepEqual(errors, []);
}));

test('a trap in the first frames after a restore; "Discard it" in the dialog and on the panel',
  () => withBrowser(async ({ browser, url }) => {
  const ctx = await contextWithWork(browser, url);

  // The restore works, the next frame traps inside the wasm (as the real 1e-15 scene did).
  const crashed = await ctx.newPage();
  await failFirstRestore(crashed, 'frame');
  await crashed.goto(url);
  await crashed.waitForSelector('.lab-crash', { timeout: 30000 });
  assert.match(await crashed.textContent('.lab-crash'), /table index is out of bounds/);
  await crashed.close();

  const { page, errors } = await cleanStartOffering(ctx, url);
  await page.click(button('discard'));
  assert.equal(await page.isVisible(dialog), false);
  assert.deepEqual(await historyLabels(page), [], 'discarded: gone from the history');
  await page.waitForFunction(() => window.cspacelab.status().notice.startsWith('Discarded'));
  await page.reload();
  await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2);
  await waitFrames(page, 3);
  assert.equal(await page.isVisible(dialog), false, 'nothing is offered any more');
  await api(page, 'select_lesson', { id: 'step-prm' });
  assert.equal((await api(page, 'get_scene')).obstacles.length, 5, 'the default scene');
  assert.deepEqual(errors, []);

  // The panel's own "Discard it": drops the work and reloads into a clean lab, no dialog.
  await setWork(page, WORK);
  await waitSavedScene(page, WORK.name);
  await page.close();
  const again = await ctx.newPage();
  await failFirstRestore(again, 'trap');
  await again.goto(url);
  await again.waitForSelector('.lab-crash button[data-action=discard]', { timeout: 30000 });
  await Promise.all([again.waitForNavigation(), again.click('.lab-crash button[data-action=discard]')]);
  await again.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2, null, { timeout: 30000 });
  await waitFrames(again, 3);
  assert.equal(await again.isVisible(dialog), false);
  assert.deepEqual(await historyLabels(again), []);
  const lessons = await api(again, 'lessons');
  assert.deepEqual(lessons.filter((l) => l.open).map((l) => l.id), [lessons[0].id], 'a clean lab');
}));

test('"Try to restore it again" on the panel reloads and restores', () => withBrowser(async ({ browser, url }) => {
  const ctx = await contextWithWork(browser, url, { width: 390, height: 844 });
  const crashed = await ctx.newPage();
  await failFirstRestore(crashed, 'trap');
  await crashed.goto(url);
  await crashed.waitForSelector('.lab-crash button[data-action=retry]', { timeout: 30000 });
  await screenshot(crashed, 'restore-crash-panel-390.png');
  await Promise.all([crashed.waitForNavigation(), crashed.click('.lab-crash button[data-action=retry]')]);
  await crashed.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2, null, { timeout: 30000 });
  await waitFrames(crashed, 3);
  assert.deepEqual(await api(crashed, 'get_scene'), WORK);
  assert.equal(await crashed.isVisible(dialog), false);
  assert.deepEqual(await crashed.evaluate(() => Object.keys(localStorage).filter((k) => k.includes(':restoring:'))), [],
                   'the restore finished: no marker left');
}));

test('a restore that freezes the page: a new page opens clean and offers the work',
  () => withBrowser(async ({ browser, url }) => {
  const ctx = await contextWithWork(browser, url, { width: 390, height: 844 });
  const frozen = await ctx.newPage();
  await failFirstRestore(frozen, 'hang');
  await frozen.goto(url, { waitUntil: 'commit' });
  // It froze once its restore started (the marker was written first).
  await new Promise((r) => setTimeout(r, 4000));

  const t0 = Date.now();
  const { page, errors } = await cleanStartOffering(ctx, url, 'restore-hang-dialog-390.png');
  assert.ok(Date.now() - t0 < 25000, 'it waited for the frozen tab no longer than its marker stays fresh');
  assert.match(await page.textContent(dialog), /the page stopped responding/);
  await page.click(button('retry'));
  await page.waitForFunction(() => window.cspacelab.status().lesson === 'step-prm');
  assert.deepEqual(await api(page, 'get_scene'), WORK);
  assert.equal((await api(page, 'state')).steps, 40);
  assert.deepEqual(errors, []);
  await frozen.close({ runBeforeUnload: false });
}));

// Review findings on the page shell: nesting that the app's own parser refuses must not look
// like a trap; a page script's error is not the wasm's; a stopped tab's Discard, a second tab's
// marker and a hidden tab's marker must not cost work that another tab holds.

const ready = (page) => page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2, null, { timeout: 30000 });

test('a link whose scene nests 30000 levels: a notice, no crash panel; the saved work stays whole',
  () => withBrowser(async ({ browser, url }) => {
  const ctx = await contextWithWork(browser, url);
  const page = await ctx.newPage();
  const errors = collectErrors(page);
  await recursiveStringify(page);
  const deep = zlib.deflateRawSync(Buffer.from(deepSceneText(30000))).toString('base64url');
  await page.goto(`${url}?lesson=step-prm&scene=z.${deep}&seed=4`);
  await startedOrStopped(page);
  assert.equal(await page.isVisible('.lab-crash'), false, 'the lab did not stop');
  const notice = (await api(page, 'status')).notice;
  assert.match(notice, /Not used from the link: scene: is nested more than 64 levels deep\./);
  assert.match(notice, /Your previous work is kept/);
  assert.equal((await api(page, 'state')).params.seed, 4, 'the rest of the link applies');
  const labels = await historyLabels(page);
  assert.match(labels[0], /before a link · Step PRM$/);
  // The same address again: no clean start, nothing "could not be restored".
  await page.reload();
  await ready(page);
  await waitFrames(page, 3);
  assert.equal(await page.isVisible(dialog), false, 'no "could not be restored" dialog');
  assert.deepEqual(await historyLabels(page), labels);
  // The work the link replaced comes back whole.
  await click(page, await pageButton(page, 'restore-previous'));
  await page.waitForFunction((n) => window.cspacelab.getScene().name === n, WORK.name);
  assert.deepEqual(await api(page, 'get_scene'), WORK);
  await page.waitForFunction(() => window.cspacelab.state().steps === 40);
  assert.deepEqual(errors, []);
}));

test('File > Import of a file nesting 30000 levels: a notice, no crash panel, nothing changes',
  () => withBrowser(async ({ browser, url }) => {
  const ctx = await contextWithWork(browser, url);
  const page = await ctx.newPage();
  const errors = collectErrors(page);
  await recursiveStringify(page);
  await openLab(page, url);
  await importByPicker(page, 'deep.json', deepSceneText(30000));
  await page.waitForFunction(() => document.querySelector('.lab-crash') || /^Import/.test(window.cspacelab.status().notice));
  assert.equal(await page.isVisible('.lab-crash'), false, 'the lab did not stop');
  assert.equal((await api(page, 'status')).notice, 'Import: "deep.json" is nested more than 64 levels deep. Nothing changed.');
  assert.deepEqual(await api(page, 'get_scene'), WORK);
  assert.equal((await api(page, 'state')).steps, 40);
  assert.deepEqual(await markers(page), [], 'no restore was begun');
  await page.reload();
  await ready(page);
  await waitFrames(page, 3);
  assert.equal(await page.isVisible(dialog), false);
  assert.deepEqual(await api(page, 'get_scene'), WORK, 'the saved work is untouched');
  assert.deepEqual(errors, []);
}));

test('a page script\'s RangeError or SyntaxError does not stop the lab', () => withBrowser(async ({ browser, url }) => {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const errors = collectErrors(page);
  await recursiveStringify(page);
  await openLab(page, url);
  // A value too deep for JSON.stringify, passed to the API: the caller gets the error.
  const thrown = await page.evaluate(() => {
    let v = 0;
    for (let i = 0; i < 30000; ++i) v = [v];
    try {
      window.cspacelab.setScene({ deep: v });
    } catch (e) {
      return e.name;
    }
    return null;
  });
  assert.equal(thrown, 'RangeError');
  assert.equal(await page.isVisible('.lab-crash'), false, 'the lab did not stop');
  // Uncaught errors of a course page's own scripts reach window's error event.
  await page.evaluate(() => {
    setTimeout(() => { throw new RangeError('a course page: Maximum call stack size exceeded'); }, 0);
    setTimeout(() => JSON.parse('{a course page'), 0);
  });
  await waitFrames(page, 5);
  assert.equal(await page.isVisible('.lab-crash'), false, 'the lab did not stop');
  await setWork(page, WORK);
  assert.deepEqual(await api(page, 'get_scene'), WORK, 'it still works');
  await waitSavedScene(page, WORK.name);
  assert.equal(errors.length, 2, errors.join('\n'));
  assert.match(errors.join('\n'), /RangeError: a course page/);
  assert.match(errors.join('\n'), /SyntaxError/);
}));

test('"Discard it" on a stopped tab\'s panel leaves the work another tab has saved since',
  () => withBrowser(async ({ browser, url }) => {
  const ctx = await contextWithWork(browser, url);
  const crashed = await ctx.newPage();
  await failFirstRestore(crashed, 'trap');
  await crashed.goto(url);
  await crashed.waitForSelector('.lab-crash button[data-action=discard]', { timeout: 30000 });
  // Another tab starts clean (the work goes aside) and the student works on there.
  const { page, errors } = await cleanStartOffering(ctx, url);
  const live = sceneWith(6, 'the live tab\'s work');
  await setWork(page, live);
  await waitSavedScene(page, live.name);
  // The stopped tab's Discard: its marker is gone and another tab holds the lease.
  await Promise.all([crashed.waitForNavigation(), crashed.click('.lab-crash button[data-action=discard]')]);
  assert.equal((await savedWork(page)).lessons['step-prm']?.scene.name, live.name, 'the live tab\'s save stays');
  await ready(crashed);
  await crashed.close();
  await page.waitForTimeout(1500);
  assert.equal((await savedWork(page)).lessons['step-prm']?.scene.name, live.name);
  await page.close();
  const next = await ctx.newPage();
  await openLab(next, url);
  assert.equal((await api(next, 'get_scene')).name, live.name, 'and it is what the next start restores');
  assert.deepEqual(errors, []);
}));

test('a second tab whose link traps after its start: the link is kept, the other tab\'s work is not "could not be restored"',
  () => withBrowser(async ({ browser, url }) => {
  const ctx = await contextWithWork(browser, url);
  const owner = await ctx.newPage();
  const errors = collectErrors(owner);
  await openLab(owner, url);
  await waitFrames(owner, 4);
  const second = await ctx.newPage();
  await failFirstRestore(second, 'frame');  // the next frame after its start traps
  await second.goto(`${url}?lesson=step-prm&scene=p12&seed=3`);
  await second.waitForSelector('.lab-crash', { timeout: 30000 });
  const [m] = (await markers(second)).filter((x) => x.trapped);
  assert.ok(m, 'the stopped tab left its marker');
  if (m.source.kind === 'history')
    assert.ok(await second.evaluate((id) => Object.keys(localStorage).some((k) => k.endsWith(':history:' + id)), m.source.id),
              `the marker points to an entry that exists (${m.source.id})`);
  // The panel's export is the link that failed.
  const exported = await downloadFrom(second, '.lab-crash button[data-action=export]');
  assert.equal(exported.value.format, 'cspacelab-link');
  assert.match(exported.value.url, /scene=p12&seed=3$/);
  await second.close();

  const next = await ctx.newPage();
  collectErrors(next);
  await openLab(next, url);
  await next.waitForSelector(dialog);
  assert.match(await next.textContent(dialog), /while restoring the link/);
  const labels = await historyLabels(next);
  assert.ok(labels.some((l) => /could not be restored · a link to Step PRM$/.test(l)), 'the link is kept: ' + labels.join(' | '));
  assert.ok(!labels.some((l) => /could not be restored · Step PRM$/.test(l)), 'the other tab\'s work is not filed as failed: ' + labels.join(' | '));
  assert.deepEqual(await api(owner, 'get_scene'), WORK, 'the other tab goes on');
  assert.deepEqual(errors, []);
}));

test('a tab that starts hidden, whose timers the browser slows: its old marker is not a failed restore',
  () => withBrowser(async ({ browser, url }) => {
  const ctx = await contextWithWork(browser, url);
  const hidden = await ctx.newPage();
  await backgroundTab(hidden);
  await hidden.goto(url);
  await hidden.waitForFunction(() => !!window.cspacelab, null, { timeout: 30000 });
  assert.equal(await hidden.evaluate(() => window.cspacelab.status().frames), 0, 'a background tab draws no frames');
  assert.equal((await markers(hidden)).length, 1, 'so its restore marker stays');
  await hidden.evaluate(() => window.cslTab.throttle(true));
  await hidden.waitForTimeout(7000);  // its marker is older than the 6 s of a frozen page

  const page = await ctx.newPage();
  const errors = collectErrors(page);
  await openLab(page, url);
  await waitFrames(page, 3);
  assert.equal(await page.isVisible(dialog), false, 'no "could not be restored" dialog');
  assert.deepEqual(await api(page, 'get_scene'), WORK, 'the saved work is restored');
  assert.doesNotMatch((await api(page, 'status')).notice, /defaults/);
  assert.ok(!(await historyLabels(page)).some((l) => /could not be restored/.test(l)));
  assert.ok((await markers(page)).some((x) => x.hidden === true), 'the hidden tab\'s marker says it is hidden');

  // Brought to the front, the tab draws its frames and its marker goes.
  await hidden.evaluate(() => { window.cslTab.throttle(false); window.cslTab.show(); });
  await hidden.waitForFunction(() => window.cspacelab.status().frames >= 3);
  await hidden.waitForFunction(() => !Object.keys(localStorage).some((k) => k.includes(':restoring:')), null, { timeout: 10000 });
  assert.deepEqual(await api(hidden, 'get_scene'), WORK);
  assert.deepEqual(errors, []);
}));
