// No lost saves (issue 27, findings 3, 7 and 9): a link with a bad part still starts autosave;
// every replaced state goes to a bounded history of previous work that the File menu lists and
// restores (real clicks); two tabs on one lab keep both tabs' work; a full origin still restores
// the saved work and says what failed; the project's server takes a link with a 60 KB scene.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import http from 'node:http';
import { withBrowser, collectErrors, openLab, api, click, pageButton, screenshot, waitFrames } from './lib/harness.mjs';
import { sceneWith, setWork, waitSavedScene, historyLabels, restoreFromMenu, savedWork, noticeMatching } from './lib/saves.mjs';

const ready = (page) => page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2, null, { timeout: 30000 });
const sceneName = async (page) => (await api(page, 'get_scene')).name;
const b64url = (value) => Buffer.from(JSON.stringify(value)).toString('base64url');

test('steps=999999999: a notice, the rest of the link applies, and autosave works',
  () => withBrowser(async ({ browser, url }) => {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const errors = collectErrors(page);
  await openLab(page, url + '?lesson=step-prm&scene=p12&samples=77&steps=999999999');
  const notice = (await api(page, 'status')).notice;
  assert.match(notice, /steps "999999999" \(more than the lab's 100000000 steps\)/);
  const state = await api(page, 'state');
  assert.equal(state.params.samples, 77, 'the other parts of the link apply');
  assert.equal((await api(page, 'get_scene')).name, (await api(page, 'bundled_scenes')).p12.name);
  // An edit afterwards survives a reload: autosave runs.
  const edited = sceneWith(2, 'edited after the link');
  await setWork(page, edited);
  await waitSavedScene(page, edited.name);
  await page.reload();
  await ready(page);
  assert.equal(await sceneName(page), edited.name);
  assert.deepEqual(errors, []);
}));

test('two links and two resets in a row: each replaced work is in the history, restorable from the File menu',
  () => withBrowser(async ({ browser, url }) => {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const errors = collectErrors(page);
  await openLab(page, url);
  const mine = sceneWith(3, 'my own work');
  await setWork(page, mine);
  await waitSavedScene(page, mine.name);

  const first = sceneWith(1, 'first link');
  const second = sceneWith(2, 'second link');
  await openLab(page, `${url}?lesson=step-prm&scene=j.${b64url(first)}`);
  assert.match((await api(page, 'status')).notice, /previous work is kept/);
  await openLab(page, `${url}?lesson=step-prm&scene=j.${b64url(second)}&seed=5`);
  assert.match((await api(page, 'status')).notice, /previous work is kept/);
  assert.equal(await sceneName(page), second.name);
  let labels = await historyLabels(page);
  assert.equal(labels.length, 2, 'both replaced works are kept');
  for (const l of labels) assert.match(l, /before a link · Step PRM$/);

  // The File menu lists them; the older one (my own work) with real clicks.
  await click(page, await pageButton(page, 'file'));
  assert.ok(await pageButton(page, 'history-0') && await pageButton(page, 'history-1'), 'the menu shows both');
  await screenshot(page, 'saves-file-menu-history.png');
  await page.keyboard.press('Escape');
  await waitFrames(page, 2);
  await restoreFromMenu(page, 1);
  assert.equal(await sceneName(page), mine.name, 'my own work is back');
  assert.match((await api(page, 'status')).notice, /^Restored .*before a link/);
  labels = await historyLabels(page);
  assert.equal(labels.length, 2, 'what was on screen went into the history, the restored entry left it');
  assert.match(labels[0], /before restoring other work/);
  // The first link's state, still there.
  await restoreFromMenu(page, 1);
  assert.equal(await sceneName(page), first.name);
  // The top bar's button restores the newest: the work that was on screen (my own).
  await click(page, await pageButton(page, 'restore-previous'));
  await page.waitForFunction((n) => window.cspacelab.getScene().name === n, mine.name);

  // Two resets, each after an edit: two entries, both restorable.
  const edit1 = sceneWith(4, 'edit before the first reset');
  const edit2 = sceneWith(5, 'edit before the second reset');
  for (const edit of [edit1, edit2]) {
    await setWork(page, edit);
    await click(page, await pageButton(page, 'file'));
    await click(page, await pageButton(page, 'reset'));
    await click(page, await pageButton(page, 'reset-confirm'));
    await page.waitForFunction(() => window.cspacelab.getScene().name !== undefined &&
                               /back to its default/.test(window.cspacelab.status().notice));
  }
  labels = await historyLabels(page);
  assert.match(labels[0], /before reset/);
  assert.match(labels[1], /before reset/);
  await restoreFromMenu(page, 1);
  assert.equal(await sceneName(page), edit1.name);
  labels = await historyLabels(page);
  const i = labels.findIndex((l) => /before reset/.test(l));
  await restoreFromMenu(page, i);
  assert.equal(await sceneName(page), edit2.name);

  // The history is bounded: 12 more links keep the newest 10 entries, and say so.
  for (let n = 0; n < 12; ++n) await openLab(page, `${url}?lesson=step-prm&scene=j.${b64url(sceneWith(1, 'link ' + n))}`);
  assert.match((await api(page, 'status')).notice, /oldest previous work \(1 entry\) was dropped/);
  assert.equal((await historyLabels(page)).length, 10);
  assert.deepEqual(errors, []);
}));

test('an old single "previous work" slot moves into the history', () => withBrowser(async ({ browser, url }) => {
  const page = await browser.newPage();
  await page.route(url + 'blank.html', (r) => r.fulfill({ contentType: 'text/html', body: '<link rel="icon" href="data:,">' }));
  await page.goto(url + 'blank.html');
  const old = sceneWith(2, 'kept by an older version');
  await page.evaluate((scene) => localStorage.setItem('cspacelab:v1:/:main:previous', JSON.stringify({
    format: 'cspacelab-work', version: 1, config: null, current: 'step-prm', savedAt: Date.now() - 3600e3,
    lessons: { 'step-prm': { lesson: 'step-prm', scene, params: { samples: 40 }, steps: 0 } } })), old);
  await openLab(page, url);
  assert.equal((await historyLabels(page)).length, 1);
  assert.equal(await page.evaluate(() => localStorage.getItem('cspacelab:v1:/:main:previous')), null, 'migrated');
  await click(page, await pageButton(page, 'restore-previous'));
  await page.waitForFunction((n) => window.cspacelab.getScene().name === n, old.name);
}));

test('two tabs of one lab: neither overwrites the other; a stale lease is taken over',
  () => withBrowser(async ({ browser, url }) => {
  const ctx = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const one = await ctx.newPage();
  const errors = collectErrors(one);
  await openLab(one, url);
  await setWork(one, sceneWith(1, 'tab one, first'));
  await waitSavedScene(one, 'tab one, first');

  const two = await ctx.newPage();
  collectErrors(two);
  await openLab(two, url);
  assert.match((await api(two, 'status')).notice, /also open in another tab/);
  assert.equal(await sceneName(two), 'tab one, first', 'the second tab starts from the saved work');
  await setWork(two, sceneWith(2, 'tab two'));
  await setWork(one, sceneWith(3, 'tab one, later'));
  await waitSavedScene(one, 'tab one, later');
  // The second tab saved into its own entry, which the first tab's File menu lists.
  await one.waitForFunction(() => window.cspacelab.pageState().history.some((h) => /another tab/.test(h.label)), null, { timeout: 15000 });
  assert.equal((await savedWork(two)).lessons['step-prm'].scene.name, 'tab one, later', 'the work slot is the first tab\'s');
  await two.close();
  await one.close();

  const three = await ctx.newPage();
  await openLab(three, url);
  assert.equal(await sceneName(three), 'tab one, later', 'the first tab\'s work is the saved work');
  const labels = await historyLabels(three);
  const i = labels.findIndex((l) => /another tab/.test(l));
  assert.ok(i >= 0, 'the second tab\'s work is in the history: ' + labels.join(' | '));
  await restoreFromMenu(three, i);
  assert.equal(await sceneName(three), 'tab two', 'and comes back with the File menu');
  await three.close();

  // A tab that crashed left its lease: the next start takes it over (no "another tab").
  const four = await ctx.newPage();
  await four.route(url + 'blank.html', (r) => r.fulfill({ contentType: 'text/html', body: '<link rel="icon" href="data:,">' }));
  await four.goto(url + 'blank.html');
  await four.evaluate(() => localStorage.setItem('cspacelab:v1:/:main:lease', JSON.stringify({ tab: 'gone', beat: Date.now() - 60000 })));
  await openLab(four, url);
  assert.doesNotMatch((await api(four, 'status')).notice, /another tab/);
  await setWork(four, sceneWith(4, 'tab four'));
  await waitSavedScene(four, 'tab four');
  assert.deepEqual(errors, []);
}));

/**
 * Fills the origin's storage up to its quota before the page's scripts run (every load), leaving
 * about `slack` characters free.
 */
async function fillStorage(page, slack = 0) {
  await page.addInitScript((room) => {
    for (const k of Object.keys(localStorage)) if (k.startsWith('filler-')) localStorage.removeItem(k);
    if (room) localStorage.setItem('slack', 'x'.repeat(room));
    let size = 1 << 20;
    for (let i = 0; size >= 1; ++i) {
      try {
        localStorage.setItem('filler-' + i, 'x'.repeat(size));
      } catch {
        size = Math.floor(size / 2);
      }
    }
    localStorage.removeItem('slack');
  }, slack);
}

test('storage full: the saved work is restored, the notice says what failed; the history makes room',
  () => withBrowser(async ({ browser, url }) => {
  const ctx = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const setup = await ctx.newPage();
  await openLab(setup, url);
  const mine = sceneWith(3, 'saved before the storage filled up');
  await setWork(setup, mine);
  await waitSavedScene(setup, mine.name);
  await setup.close();

  const page = await ctx.newPage();
  const errors = collectErrors(page);
  await fillStorage(page);
  await openLab(page, url);
  assert.equal(await sceneName(page), mine.name, 'the saved work is restored');
  assert.match((await api(page, 'status')).notice,
               /Your saved work was restored; changes are not being saved: storage for this site is full\. File > Export scene keeps a copy\./);
  await screenshot(page, 'saves-storage-full.png');
  // An edit cannot be saved; the saved work stays as it was (nothing is overwritten by halves).
  await setWork(page, sceneWith(6, 'not saved'));
  await page.waitForTimeout(2000);
  assert.equal((await savedWork(page)).lessons['step-prm'].scene.name, mine.name);
  assert.deepEqual(errors, []);
  await page.close();

  // With previous work in the history, the lab drops the oldest to make room, and says so.
  const clear = await ctx.newPage();
  await openLab(clear, url);
  await clear.evaluate(() => { for (const k of Object.keys(localStorage)) if (k.startsWith('filler-')) localStorage.removeItem(k); });
  const big = sceneWith(800, 'a large earlier work');
  await setWork(clear, big);
  await waitSavedScene(clear, big.name);
  await click(clear, await pageButton(clear, 'file'));
  await click(clear, await pageButton(clear, 'reset'));
  await click(clear, await pageButton(clear, 'reset-confirm'));
  await clear.waitForFunction(() => /back to its default/.test(window.cspacelab.status().notice));
  await setWork(clear, mine);
  await waitSavedScene(clear, mine.name);
  assert.equal((await historyLabels(clear)).length, 1);
  await clear.close();

  // Room for the start's own writes (its restore marker), not for 1 KB more: the start drops
  // nothing (it does not probe by writing), and says nothing is wrong, since room can be made.
  const roomy = await ctx.newPage();
  const roomyErrors = collectErrors(roomy);
  await fillStorage(roomy, 600);
  await openLab(roomy, url);
  assert.equal(await sceneName(roomy), mine.name);
  const notice = (await api(roomy, 'status')).notice;
  assert.doesNotMatch(notice, /not being saved|dropped/);
  assert.equal((await historyLabels(roomy)).length, 1, 'the start kept the previous work');
  await roomy.reload();
  await ready(roomy);
  assert.equal((await historyLabels(roomy)).length, 1, 'and so does the next');
  // A save that does not fit drops the oldest previous work, and says so.
  const saved = sceneWith(40, 'saved in the room made');
  await setWork(roomy, saved);
  await waitSavedScene(roomy, saved.name);
  assert.match(await noticeMatching(roomy, /dropped/), /oldest previous work \(1 entry\) was dropped to make room/);
  assert.equal((await historyLabels(roomy)).length, 0);
  assert.deepEqual(roomyErrors, []);
}));

test('the project\'s server serves a link with a 60 KB scene', () => withBrowser(async ({ browser, url }) => {
  // 700 disks: the JSON is ~45 KB, its base64url ~60 KB (the documented limit is 64 KB).
  const scene = sceneWith(1, 'sixty kilobytes');
  scene.obstacles = [];
  for (let i = 0; i < 700; ++i)
    scene.obstacles.push({ type: 'disk', center: [0.1 + 0.8 * (i % 40) / 40, 0.1 + 0.8 * Math.floor(i / 40) / 20], radius: 0.0012345 });
  const param = 'j.' + b64url(scene);
  assert.ok(param.length > 58 * 1024 && param.length < 64 * 1024, `a ${param.length}-character scene parameter`);
  const link = `${url}?lesson=step-prm&scene=${param}`;
  const status = await new Promise((resolve, reject) => http.get(link, (res) => { res.resume(); resolve(res.statusCode); }).on('error', reject));
  assert.equal(status, 200, 'served (not 431 Request Header Fields Too Large)');
  const page = await browser.newPage();
  const errors = collectErrors(page);
  await openLab(page, link);
  assert.equal((await api(page, 'get_scene')).obstacles.length, 700, 'and the lab opens its scene');
  assert.equal((await api(page, 'status')).notice, '');
  assert.deepEqual(errors, []);
}));

