// The scene editor's context menu with a mouse: a right-click (that does not pan) on an obstacle
// or on empty space offers what can be done there; each choice is one undo step.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, api, waitFrames, worldToPage, pageButton, click, chord, screenshot } from './lib/harness.mjs';

async function rightClick(page, at) {
  await page.mouse.move(at.x, at.y);
  await waitFrames(page, 2);
  await page.mouse.down({ button: 'right' });
  await waitFrames(page, 2);
  await page.mouse.up({ button: 'right' });
  await waitFrames(page, 3);
}

test('right-click: delete, duplicate, move the goal; a right-drag pans and opens nothing',
  () => withPage({ open: '?lesson=step-prm&scene=prm-demo' }, async ({ page }) => {
  const before = await api(page, 'get_scene');
  // On the first disk (centre (0.3, 0.3)).
  const [disk] = await worldToPage(page, [[0.3, 0.3]]);
  await rightClick(page, disk);
  assert.ok(await pageButton(page, 'context-delete'), 'the obstacle menu');
  await screenshot(page, 'context-menu-obstacle.png');
  await click(page, await pageButton(page, 'context-delete'));
  let scene = await api(page, 'get_scene');
  assert.equal(scene.obstacles.length, before.obstacles.length - 1);
  assert.ok(!scene.obstacles.some((o) => o.type === 'disk' && o.center[0] === 0.3 && o.center[1] === 0.3), 'that disk went');
  await chord(page, 'Control', 'z');
  assert.deepEqual(await api(page, 'get_scene'), before, 'one undo step');

  // Duplicate the wall: a second, moved beside it, same length.
  const [wall] = await worldToPage(page, [[0.5, 0.7]]);
  await rightClick(page, wall);
  await click(page, await pageButton(page, 'context-duplicate'));
  scene = await api(page, 'get_scene');
  const copy = scene.obstacles.at(-1);
  assert.equal(copy.type, 'segment');
  assert.ok(Math.abs(Math.hypot(copy.b[0] - copy.a[0], copy.b[1] - copy.a[1]) - 0.5) < 1e-12, 'the same length');
  assert.ok(Math.abs(copy.a[0] - 0.5) > 0.01, 'beside the original, not on it');
  await chord(page, 'Control', 'z');

  // Empty space: move the goal there.
  const target = [0.2, 0.45];
  const [free] = await worldToPage(page, [target]);
  await rightClick(page, free);
  assert.equal(await pageButton(page, 'context-delete'), null);
  await click(page, await pageButton(page, 'context-goal'));
  scene = await api(page, 'get_scene');
  const { layout } = await api(page, 'status');
  const px = 1 / layout.views.find((v) => v.name === 'workspace').w;
  assert.ok(Math.hypot(scene.goal[0] - target[0], scene.goal[1] - target[1]) < 3 * px, `the goal is where the click was: ${scene.goal}`);
  assert.deepEqual(scene.obstacles, before.obstacles);

  // A right-drag pans: the view moves, and no menu opens at the release.
  const zoomBefore = (await api(page, 'view', { points: [[0.5, 0.5]] })).points[0];
  await page.mouse.move(free.x, free.y);
  await page.mouse.down({ button: 'right' });
  for (let i = 1; i <= 6; ++i) {
    await page.mouse.move(free.x + 10 * i, free.y);
    await waitFrames(page, 1);
  }
  await page.mouse.up({ button: 'right' });
  await waitFrames(page, 3);
  const zoomAfter = (await api(page, 'view', { points: [[0.5, 0.5]] })).points[0];
  assert.ok(Math.abs(zoomAfter[0] - zoomBefore[0] - 60) < 2, `panned 60 px: ${zoomBefore} -> ${zoomAfter}`);
  assert.equal(await pageButton(page, 'context-goal'), null, 'no menu after a pan');
  // Fit the view from the menu.
  await rightClick(page, free);
  await click(page, await pageButton(page, 'context-fit'));
  assert.deepEqual((await api(page, 'view', { points: [[0.5, 0.5]] })).points[0], zoomBefore, 'fitted back');
}));
