// Autosave: a scene drawn with the mouse survives a reload (the work of every open lesson, at
// its step); "Reset to lesson default" asks first (an in-app modal, real clicks), and what it
// replaced comes back with "Restore my previous work".
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, withPage, drawDisk, collectErrors, openLab, click, waitFrames, api, pageButton,
         screenshot, expectView, sceneProbes } from './lib/harness.mjs';

test('reload restores a drawn scene; reset asks first and can be undone', () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'collision' });
  await api(page, 'set_params', { params: { grid_n: 7 } });
  await api(page, 'run_to', { steps: 2 });
  await api(page, 'select_lesson', { id: 'step-prm' });
  await api(page, 'set_scene', { scene: { version: 1, start: [0.05, 0.05], goal: [0.95, 0.95] } });
  await waitFrames(page, 2);

  // Two disks drawn with real mouse events.
  await drawDisk(page, [0.3, 0.6], [0.42, 0.6]);
  await drawDisk(page, [0.7, 0.35], [0.78, 0.35]);
  await api(page, 'set_params', { params: { seed: 42, samples: 90 } });
  await api(page, 'run_to', { steps: 60 });
  const drawn = await api(page, 'get_scene');
  assert.equal(drawn.obstacles.length, 2);
  const before = await api(page, 'state');

  // Reload at once (the pagehide save), then again after the debounced autosave ran.
  await page.reload();
  await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2);
  assert.equal((await api(page, 'status')).lesson, 'step-prm', 'the lesson that was open');
  assert.deepEqual(await api(page, 'get_scene'), drawn, 'the drawn scene is back');
  const after = await api(page, 'state');
  assert.equal(after.steps, 60);
  assert.equal(after.roadmap_hash, before.roadmap_hash, 'and the same roadmap at the same step');
  assert.deepEqual(after.params, before.params);
  await api(page, 'select_lesson', { id: 'collision' });
  const collision = await api(page, 'state');
  assert.equal(collision.grid_n, 7, 'the other lesson kept its work too');
  assert.equal(collision.shown, 2);
  await api(page, 'select_lesson', { id: 'step-prm' });
  await page.waitForTimeout(2500);
  await page.reload();
  await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2);
  assert.deepEqual(await api(page, 'get_scene'), drawn);
  assert.equal((await api(page, 'status')).notice, '', 'a plain reload says nothing');

  // Reset: File, then the menu item, then the modal's Reset (Cancel first: nothing changes).
  await click(page, await pageButton(page, 'file'));
  await click(page, await pageButton(page, 'reset'));
  // The modal dims the lab behind it: the workspace's disks and free space alike lie under ImGui's
  // veil (dark grey at 35 %), so a disk is darker than the free space but neither as it was.
  const veiled = ([r, g, b]) => Math.max(r, g, b) - Math.min(r, g, b) <= 16 && r >= 150 && r <= 200;
  const under = ([r, g, b]) => Math.max(r, g, b) - Math.min(r, g, b) <= 16 && r >= 70 && r < 110;
  await expectView(page, browser, 'autosave-reset-modal.png',
                   sceneProbes(drawn, { free: 0, markers: false }).map((p) => ({ ...p, look: under, why: 'a disk under the veil' }))
                     .concat([[0.1, 0.9], [0.5, 0.1], [0.9, 0.6]].map((at) => ({ at, look: veiled, why: 'free space under the veil' }))),
                   'workspace', { keepMouse: true });
  await click(page, await pageButton(page, 'reset-cancel'));
  assert.deepEqual(await api(page, 'get_scene'), drawn, 'Cancel keeps the work');
  await click(page, await pageButton(page, 'file'));
  await click(page, await pageButton(page, 'reset'));
  assert.ok(await pageButton(page, 'reset-confirm'), 'the modal asks first');
  await click(page, await pageButton(page, 'reset-confirm'));
  await page.waitForFunction(() => window.cspacelab.getScene().name !== undefined);
  const reset = await api(page, 'get_scene');
  assert.equal(reset.obstacles.length, 5, 'the lesson default scene (prm-demo)');
  assert.equal((await api(page, 'state')).params.seed, 1, 'default parameters');
  assert.match((await api(page, 'status')).notice, /back to its default/);

  // The reset survives a reload; the previous work is still there to restore.
  await page.reload();
  await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2);
  assert.equal((await api(page, 'get_scene')).obstacles.length, 5);
  await waitFrames(page, 2);
  await click(page, await pageButton(page, 'restore-previous'));
  await page.waitForFunction(() => window.cspacelab.getScene().obstacles.length === 2);
  assert.deepEqual(await api(page, 'get_scene'), drawn);
  assert.equal((await api(page, 'state')).roadmap_hash, before.roadmap_hash);
  // And drawn: the two disks where they were drawn, S and G (the roadmap fills the free space).
  await expectView(page, browser, 'autosave-restored.png', sceneProbes(drawn, { free: 0 }));
}));

test('storage that cannot be read is reported and replaced, not trusted',
  () => withBrowser(async ({ browser, url }) => {
  const page = await browser.newPage({ viewport: { width: 1100, height: 700 } });
  // A blank page of the same origin, to write the storage before the lab starts.
  await page.route(url + 'blank.html', (r) => r.fulfill({ contentType: 'text/html', body: '<link rel="icon" href="data:,">' }));
  await page.goto(url + 'blank.html');
  const errors = collectErrors(page);
  await page.evaluate(() => {
    localStorage.setItem('cspacelab:v1:/:main:work', '{"format":"cspacelab-work","version":1,"current":"step-prm","lessons":{"step-prm":{"scene":{"version":1,"obstacles":[{"type":"disk","center":[0,0],"radius":-1}]}}}}');
  });
  await openLab(page, url);
  assert.match((await api(page, 'status')).notice, /saved work: Step PRM: .*radius/);
  assert.equal((await api(page, 'get_scene')).obstacles.length, 5, 'the default scene instead');
  // A parameter this version does not know (say, saved by another version): the scene stays.
  await page.evaluate(() => localStorage.setItem('cspacelab:v1:/:main:work', JSON.stringify({
    format: 'cspacelab-work', version: 1, current: 'step-prm',
    lessons: { 'step-prm': { scene: { version: 1, obstacles: [{ type: 'disk', center: [0.5, 0.5], radius: 0.2 }] },
                             params: { samples: 50, renamed: 3 }, steps: 4 } } })));
  await page.reload();
  await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2);
  assert.match((await api(page, 'status')).notice, /saved work: Step PRM: unknown parameter "renamed"/);
  assert.deepEqual((await api(page, 'get_scene')).obstacles, [{ type: 'disk', center: [0.5, 0.5], radius: 0.2 }], 'the scene is kept');
  await page.evaluate(() => localStorage.setItem('cspacelab:v1:/:main:work', 'not json {'));
  await page.reload();
  await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2);
  assert.match((await api(page, 'status')).notice, /saved work in this browser could not be read/);
  assert.deepEqual(errors, []);
}));
