// The chain works end to end: the wasm app loads in real Chromium at a HiDPI pixel ratio,
// renders, and a mouse drag on the workspace creates a disk (centre = press point, radius =
// drag distance) that the app's JS API reports and the screenshot shows.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, chord, worldToPage, drag, click, keys, waitFrames, screenshot, inspectPng, api,
         refusal, expectView, sceneProbes } from './lib/harness.mjs';

test('dragging on the workspace canvas creates a disk obstacle',
  () => withPage({ viewport: { width: 1100, height: 720 }, deviceScaleFactor: 2 }, async ({ page, browser }) => {
  assert.equal((await page.evaluate(() => window.cspacelab.status())).pixel_ratio, 2, 'renders at the device pixel ratio');

  await page.evaluate(() => {
    window.cspacelab.selectLesson('step-prm');
    window.cspacelab.setScene({ version: 1, start: [0.05, 0.05], goal: [0.95, 0.95] });
  });
  await waitFrames(page, 2);
  await keys(page, 'd');  // the disk tool
  const [from, to] = await worldToPage(page, [[0.5, 0.6], [0.65, 0.6]]);
  await drag(page, from, to);

  const scene = await page.evaluate(() => window.cspacelab.getScene());
  assert.equal(scene.obstacles.length, 1, 'one disk after one drag');
  const disk = scene.obstacles[0];
  const { scale } = await page.evaluate(() => window.cspacelab.view());
  const pixel = 1 / scale;  // one CSS pixel in world units
  assert.equal(disk.type, 'disk');
  assert.ok(Math.abs(disk.center[0] - 0.5) <= 1.5 * pixel, `centre x ${disk.center[0]}`);
  assert.ok(Math.abs(disk.center[1] - 0.6) <= 1.5 * pixel, `centre y ${disk.center[1]}`);
  assert.ok(Math.abs(disk.radius - 0.15) <= 2.5 * pixel, `radius ${disk.radius}`);

  // A click without a drag makes no disk, and says why.
  const [elsewhere] = await worldToPage(page, [[0.2, 0.2]]);
  await click(page, elsewhere);
  assert.equal((await page.evaluate(() => window.cspacelab.getScene())).obstacles.length, 1);
  assert.match((await page.evaluate(() => window.cspacelab.status())).notice, /Drag/);

  // Bad input through the API is refused and loses nothing.
  const refused = await refusal(page, 'setScene', { version: 1, obstacles: [{ type: 'disk', center: [0, 0], radius: -1 }] });
  assert.equal(refused, 'obstacles[0].radius: must be >= 0');
  assert.equal((await page.evaluate(() => window.cspacelab.getScene())).obstacles.length, 1);

  // The picture, at device resolution: the disk filled where it is, free workspace white, S and G.
  await keys(page, 'Escape');  // deselect: a selected disk is drawn in the selection colour
  const { png } = await expectView(page, browser, 'draw-disk.png',
                                   sceneProbes(await page.evaluate(() => window.cspacelab.getScene()), { free: 16 }));
  assert.equal((await inspectPng(browser, png)).width, 2200, 'screenshot at device resolution');
}));

// Undo, redo or a new scene may arrive while the mouse still holds an obstacle (the keys and
// the release can even land in the same frame). The edit in progress must end there: before,
// the drag went on with the undone scene's index and crashed the app (found by the monkey).
test('undo or a new scene in the middle of a drag ends the drag and undoes it',
  () => withPage({ viewport: { width: 1100, height: 720 } }, async ({ page }) => {
  const base = {
    version: 1, start: [0.05, 0.05], goal: [0.95, 0.95],
    obstacles: [{ type: 'polygon', vertices: [[0.1, 0.6], [0.3, 0.6], [0.2, 0.8]] },
                { type: 'disk', center: [0.6, 0.4], radius: 0.1 }],
  };
  await page.evaluate((s) => {
    window.cspacelab.selectLesson('step-prm');
    window.cspacelab.setScene({ version: 1, start: [0.05, 0.05], goal: [0.95, 0.95] });
    window.cspacelab.setScene(s);  // undoable: one step back is the empty scene
  }, base);
  await waitFrames(page, 2);
  const scene = () => page.evaluate(() => window.cspacelab.getScene());
  const undoKeys = (key) => chord(page, 'Control', key);
  const [centre, rim, rimOut, moved] = await worldToPage(page, [[0.6, 0.4], [0.7, 0.4], [0.8, 0.4], [0.6, 0.3]]);
  // Presses at `from` and moves to `to`, frames between, and keeps the button down.
  const hold = async (from, to) => {
    await page.mouse.move(from.x, from.y);
    await waitFrames(page, 2);
    await page.mouse.down();
    await waitFrames(page, 2);
    await page.mouse.move(to.x, to.y, { steps: 4 });
    await waitFrames(page, 2);
  };
  const release = async () => {
    await page.mouse.up();
    await waitFrames(page, 2);
  };

  // Drag the disk's rim outwards, and undo with the button still down.
  await click(page, centre);  // select the disk (the select tool is the default)
  await hold(rim, rimOut);
  assert.ok((await scene()).obstacles[1].radius > 0.15, 'the rim drag is live');
  await undoKeys('z');
  assert.deepEqual((await scene()).obstacles, base.obstacles, 'undo undid the drag');
  await page.mouse.move(moved.x, moved.y, { steps: 4 });  // the button is still down: no drag any more
  await release();
  assert.deepEqual((await scene()).obstacles, base.obstacles, 'the rest of the gesture changed nothing');
  await undoKeys('y');
  assert.ok((await scene()).obstacles[1].radius > 0.15, 'redo brings the drag back');
  await undoKeys('z');

  // Move the whole disk, and undo and release within one frame (Ctrl held from a frame before
  // to one after: see chord()).
  await hold(centre, moved);
  await page.keyboard.down('Control');
  await waitFrames(page, 1);
  await page.keyboard.press('z');
  await page.mouse.up();
  await waitFrames(page, 1);
  await page.keyboard.up('Control');
  await waitFrames(page, 3);
  assert.deepEqual((await scene()).obstacles, base.obstacles);

  // Esc in the middle of a drag puts the disk back; a tool key only changes the tool.
  await hold(centre, moved);
  await keys(page, 'Escape');
  assert.deepEqual((await scene()).obstacles, base.obstacles, 'Esc cancelled the move');
  await release();
  await hold(centre, moved);  // a move that a tool key does not break
  await keys(page, 'w');
  await release();
  const after = (await scene()).obstacles[1];
  assert.ok(Math.abs(after.center[1] - 0.3) < 0.02, `the move went on to its end: ${JSON.stringify(after)}`);
  await keys(page, 'v');
  await undoKeys('z');
  assert.deepEqual((await scene()).obstacles, base.obstacles);

  // A drag whose lesson goes off screen ends there: on return it does not follow the mouse.
  await hold(centre, moved);
  await api(page, 'select_lesson', { id: 'collision' });
  await waitFrames(page, 2);
  await api(page, 'select_lesson', { id: 'step-prm' });
  await waitFrames(page, 2);
  await page.mouse.move(rimOut.x, rimOut.y, { steps: 4 });
  await release();
  const kept = (await scene()).obstacles[1];
  assert.ok(Math.abs(kept.center[1] - 0.3) < 0.02 && kept.radius === 0.1, `ended where it was: ${JSON.stringify(kept)}`);
  await undoKeys('z');
  assert.deepEqual((await scene()).obstacles, base.obstacles, 'and it is one undo step');

  // A new scene through the API while a drag is in progress replaces the scene; the drag ends.
  await hold(centre, moved);
  const single = { ...base, obstacles: [{ type: 'polygon', vertices: [[0.5, 0.1], [0.7, 0.1], [0.6, 0.2]] }] };
  await page.evaluate((s) => window.cspacelab.setScene(s), single);
  await page.mouse.move(centre.x, centre.y, { steps: 4 });
  await release();
  assert.deepEqual((await scene()).obstacles, single.obstacles);

  assert.equal((await page.evaluate(() => window.cspacelab.status())).lesson, 'step-prm');
}));
