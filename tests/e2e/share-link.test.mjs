// Share: the app's Share button (a real click) makes a link, puts it on the clipboard and in a
// dialog; the link opens the identical state in a new page (same roadmap, same step), in a fresh
// browser profile and in one holding other work (which goes to "previous work", restorable).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, withPage, collectErrors, openLab, click, waitFrames, api, pageButton,
         screenshot, expectView, sceneProbes } from './lib/harness.mjs';

const SCENE = {
  version: 1,
  name: 'shared scene',
  workspace: { min: [0, 0], max: [1, 1] },
  robot: { type: 'point' },
  obstacles: [
    { type: 'disk', center: [0.31, 0.62], radius: 0.1234567 },
    { type: 'polygon', vertices: [[0.55, 0.1], [0.8, 0.15], [0.7, 0.4]] },
    { type: 'segment', a: [0.45, 0.3], b: [0.45, 0.9] },
  ],
  start: [0.05, 0.1],
  goal: [0.93, 0.91],
};

async function shareViaButton(page) {
  await click(page, await pageButton(page, 'share'));
  await page.waitForSelector('.lab-dialog textarea');
  const link = await page.inputValue('.lab-dialog textarea');
  const clip = await page.evaluate(() => navigator.clipboard.readText());
  return { link, clip };
}

test('a share link reproduces the identical roadmap and step in a new page',
  () => withBrowser(async ({ browser, url }) => {
  const ctx = await browser.newContext({ viewport: { width: 1280, height: 800 }, permissions: ['clipboard-read', 'clipboard-write'] });
  const page = await ctx.newPage();
  const errors = collectErrors(page);
  await openLab(page, url);
  await api(page, 'select_lesson', { id: 'step-prm' });
  await api(page, 'set_scene', { scene: SCENE });
  await api(page, 'set_params', { params: { samples: 140, neighbors: 'radius:0.21', checker: 'grid:7', seed: 12345 } });
  await api(page, 'run_to', { steps: 173 });
  const original = await api(page, 'state', { roadmap: true });
  const originalScene = await api(page, 'get_scene');
  assert.ok(original.nodes > 20 && original.steps === 173, 'a roadmap under way');

  const { link, clip } = await shareViaButton(page);
  assert.equal(clip, link, 'the link is on the clipboard and in the dialog');
  const u = new URL(link);
  assert.equal(u.origin + u.pathname, url, 'the link points at the lab');
  assert.equal(u.searchParams.get('lesson'), 'step-prm');
  assert.equal(u.searchParams.get('steps'), '173');
  assert.equal(u.searchParams.get('seed'), '12345');
  assert.match(u.searchParams.get('neighbors'), /^radius:0\.2/);
  assert.equal(Number(u.searchParams.get('neighbors').slice(7)), 0.21, 'the radius round-trips exactly');
  assert.match(u.searchParams.get('scene'), /^z\.[A-Za-z0-9_-]+$/, 'a custom scene is deflated and base64url-encoded');
  assert.ok(link.length < 2000, `a compact link (${link.length} characters)`);
  await screenshot(page, 'share-dialog.png');
  // The dialog is on screen, in front, and shows the link whole.
  const dialog = await page.evaluate(() => {
    const d = document.querySelector('.lab-dialog'), r = d.getBoundingClientRect();
    const top = document.elementFromPoint(r.left + r.width / 2, r.top + 8);
    return { w: r.width, h: r.height, inside: r.left >= 0 && r.top >= 0 && r.right <= innerWidth && r.bottom <= innerHeight,
             front: d.contains(top), text: d.querySelector('textarea').value };
  });
  assert.ok(dialog.w > 200 && dialog.h > 80 && dialog.inside && dialog.front, JSON.stringify(dialog));
  assert.equal(dialog.text, link);

  // A new page in a fresh profile: the identical state.
  const fresh = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const other = await fresh.newPage();
  const otherErrors = collectErrors(other);
  await openLab(other, link);
  const reproduced = await api(other, 'state', { roadmap: true });
  assert.equal(reproduced.roadmap_hash, original.roadmap_hash, 'same roadmap');
  assert.deepEqual(reproduced.vertices, original.vertices);
  assert.deepEqual(reproduced.edge_list, original.edge_list);
  assert.equal(reproduced.steps, 173, 'same step');
  assert.deepEqual(reproduced.params, original.params);
  assert.deepEqual(await api(other, 'get_scene'), originalScene, 'same scene, to the last digit');
  assert.equal((await api(other, 'status')).notice, '', 'no complaint about a good link');
  // And it draws that scene: the disk, the polygon, S and G (the roadmap covers the free space).
  await expectView(other, browser, 'share-opened.png', sceneProbes(originalScene, { free: 0 }));
  await other.close();
  await fresh.close();

  // The same profile, after more work on the same lesson: the link's state wins, the work is
  // kept as "previous work", and the app's button brings it back.
  await page.keyboard.press('Escape');
  await api(page, 'set_scene', { scene: { ...SCENE, obstacles: [...SCENE.obstacles, { type: 'disk', center: [0.8, 0.7], radius: 0.05 }] } });
  await api(page, 'run_to', { steps: 20 });
  await page.evaluate(() => window.cspacelab.shell.saveNow());
  const second = await ctx.newPage();
  collectErrors(second);
  await openLab(second, link);
  assert.equal((await api(second, 'state')).roadmap_hash, original.roadmap_hash);
  assert.equal((await api(second, 'state')).steps, 173);
  assert.match((await api(second, 'status')).notice, /previous work is kept/);
  assert.match((await api(second, 'page_state')).previous, /your work of/);
  await waitFrames(second, 2);
  await click(second, await pageButton(second, 'restore-previous'));
  await second.waitForFunction(() => window.cspacelab.getScene().obstacles.length === 4);
  assert.equal((await api(second, 'state')).steps, 20, 'the previous work, at its step');
  await expectView(second, browser, 'share-restored-previous.png', sceneProbes(await api(second, 'get_scene'), { free: 0 }));
  // ...and the link's state is now the previous work: nothing was lost either way.
  await click(second, await pageButton(second, 'restore-previous'));
  await second.waitForFunction(() => window.cspacelab.getScene().obstacles.length === 3);
  assert.equal((await api(second, 'state')).roadmap_hash, original.roadmap_hash);
  assert.deepEqual(errors, [], 'no console errors');
  assert.deepEqual(otherErrors, [], 'no console errors in the opened link');
}));

const ARM_LINK = '?lesson=collision&scene=arm-2link&grid_n=9&p=0.2,0.3&q=2.6,-0.4&steps=3';

test('links of the collision lesson (arm scene, by name) reproduce its step',
  () => withPage({ open: ARM_LINK }, async ({ page, browser, url }) => {
  const state = await api(page, 'state');
  assert.equal((await api(page, 'status')).notice, '');
  assert.equal(state.robot, 'arm2');
  assert.equal(state.grid_n, 9);
  assert.equal(state.shown, 3);
  assert.ok(state.bisection.trace.length > 3, 'the step is inside the trace');
  const link = (await page.evaluate(() => window.cspacelab.shell.shareLink())).url;
  assert.match(link, /[?&]scene=arm-2link(&|$)/, 'a bundled scene is named, not encoded');
  const other = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  await openLab(other, link);
  assert.deepEqual(await api(other, 'state'), state);
}));
