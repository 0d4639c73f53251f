// Keyboard chords that land within one frame. ImGui 1.86 reads the keys as one state a frame,
// and its SDL backend takes the modifiers from SDL_GetModState(), which by the frame is past
// every queued key. The app goes by each key event's own modifiers and holds back a release
// that would hide a press (and what follows it) for a frame: see Platform::frame_once. The
// events are synthetic, dispatched on the canvas in one task of the page, so within one frame.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { click, pageButton, withPage, waitFrames } from './lib/harness.mjs';

test('Ctrl chords count whatever else lands in their frame, and nothing else makes one',
  () => withPage({ viewport: { width: 1100, height: 720 } }, async ({ page }) => {
  const disk = { type: 'disk', center: [0.6, 0.4], radius: 0.1 };
  await page.evaluate((d) => {
    window.cspacelab.selectLesson('step-prm');
    window.cspacelab.setScene({ version: 1, start: [0.05, 0.05], goal: [0.95, 0.95] });
    window.cspacelab.setScene({ version: 1, start: [0.05, 0.05], goal: [0.95, 0.95], obstacles: [d] });
  }, disk);
  await waitFrames(page, 2);
  const count = async () => (await page.evaluate(() => window.cspacelab.getScene())).obstacles.length;
  // Sends the events, then waits a few frames (held-back releases take one each).
  const send = async (...events) => {
    await page.evaluate((list) => {
      const canvas = document.querySelector('canvas');
      for (const [type, key, code, ctrlKey] of list)
        canvas.dispatchEvent(new KeyboardEvent(type, { key, code, ctrlKey, bubbles: true, cancelable: true }));
    }, events);
    await waitFrames(page, 4);
  };
  const down = (key, ctrl = true) => ['keydown', key, `Key${key.toUpperCase()}`, ctrl];
  const up = (key, ctrl = true) => ['keyup', key, `Key${key.toUpperCase()}`, ctrl];
  const ctrlDown = ['keydown', 'Control', 'ControlLeft', true], ctrlUp = ['keyup', 'Control', 'ControlLeft', false];
  const redo = () => send(ctrlDown, down('y'), up('y'), ctrlUp);

  await send(ctrlDown, down('z'), up('z'), ctrlUp);
  assert.equal(await count(), 0, 'Ctrl+Z, pressed and released in one frame, undid the disk');
  await redo();
  assert.equal(await count(), 1, 'Ctrl+Y in one frame redid it');

  await send(ctrlDown);  // held from frames before; Z and the release together
  await send(down('z'), up('z'), ctrlUp);
  assert.equal(await count(), 0, 'Z and the release of a held Ctrl in one frame undid it');
  await redo();

  // A key after the chord in the same frame: it was pressed with no Ctrl, the Z with one.
  await send(ctrlDown, down('z'), ctrlUp, down('x', false), up('x', false), up('z', false));
  assert.equal(await count(), 0, 'a key after the released Ctrl did not take the undo away');
  await redo();

  // A plain Z, then Ctrl pressed in the same frame: the Z had no Ctrl.
  await send(down('z', false), up('z', false), ctrlDown);
  assert.equal(await count(), 1, 'a Ctrl pressed after a plain Z made no undo');
  await send(ctrlUp);
  assert.equal(await count(), 1);
}));

// Issue 21: F, which the keys dialog lists, fits the view again after zooming and panning (it did
// nothing), and a scene of another size is shown whole.
test('F fits the view after zooming and panning; a scene of another size is shown whole',
  () => withPage({ viewport: { width: 1280, height: 800 } }, async ({ page }) => {
  await page.evaluate(() => window.cspacelab.selectLesson('step-prm'));
  await waitFrames(page, 2);
  const fitted = await page.evaluate(() => window.cspacelab.view([[0, 0], [1, 1]]));
  const box = await page.locator('canvas').boundingBox();
  const [x, y] = fitted.points[1];
  await page.mouse.move(box.x + x - 40, box.y + y + 40);
  await waitFrames(page, 2);
  for (let i = 0; i < 4; ++i) { await page.mouse.wheel(0, -200); await waitFrames(page, 1); }
  await page.mouse.down({ button: 'right' });
  await page.mouse.move(box.x + x + 60, box.y + y + 90, { steps: 4 });
  await page.mouse.up({ button: 'right' });
  await waitFrames(page, 2);
  const zoomed = await page.evaluate(() => window.cspacelab.view([[0, 0], [1, 1]]));
  assert.ok(zoomed.scale > fitted.scale * 1.5, `zoomed in: ${fitted.scale} -> ${zoomed.scale}`);
  await page.keyboard.press('f');
  await waitFrames(page, 2);
  assert.deepEqual(await page.evaluate(() => window.cspacelab.view([[0, 0], [1, 1]])), fitted, 'F fits it again');
  // Zoomed again, then a larger scene: shown whole.
  for (let i = 0; i < 3; ++i) { await page.mouse.wheel(0, -200); await waitFrames(page, 1); }
  await page.evaluate(() => window.cspacelab.setScene({ version: 1, workspace: { min: [0, 0], max: [4, 2] }, goal: [4, 2] }));
  await waitFrames(page, 2);
  const wide = await page.evaluate(() => window.cspacelab.view([[0, 0], [4, 2]]));
  for (const [px, py] of wide.points) {
    assert.ok(px >= wide.canvas_min[0] && px <= wide.canvas_max[0] && py >= wide.canvas_min[1] && py <= wide.canvas_max[1],
              `corner (${px}, ${py}) on the canvas`);
  }
}));

// The same, with the mouse alone (issue 21 asks for a visible command): zoomed in, the view shows
// a "Fit view (F)" button, and pressing it fits the view; the press is the button's, not the
// editor's (with the disk tool on, a press on the canvas would start a disk).
test('a zoomed view shows a Fit button that fits it, and the press draws nothing',
  () => withPage({ viewport: { width: 1280, height: 800 } }, async ({ page }) => {
  await page.evaluate(() => window.cspacelab.selectLesson('step-prm'));
  await waitFrames(page, 2);
  const fitted = await page.evaluate(() => window.cspacelab.view([[0, 0], [1, 1]]));
  assert.equal(fitted.fit_button, false, 'no button while the view is whole');
  const before = (await page.evaluate(() => window.cspacelab.getScene())).obstacles.length;
  const box = await page.locator('canvas').boundingBox();
  const [x, y] = fitted.points[1];
  await page.mouse.move(box.x + x - 120, box.y + y + 160);
  await waitFrames(page, 2);
  for (let i = 0; i < 3; ++i) { await page.mouse.wheel(0, -200); await waitFrames(page, 1); }
  const zoomed = await page.evaluate(() => window.cspacelab.view([[0, 0], [1, 1]]));
  assert.ok(zoomed.scale > fitted.scale * 1.3 && zoomed.fit_button, `zoomed, with its button: ${zoomed.scale}`);
  await page.keyboard.press('d');  // the disk tool: a press on the canvas would begin a disk
  await waitFrames(page, 2);
  const fit = await pageButton(page, 'fit##prm-workspace');
  assert.ok(fit, 'the button is on screen');
  await click(page, fit);
  await waitFrames(page, 1);
  const after = await page.evaluate(() => window.cspacelab.view([[0, 0], [1, 1]]));
  assert.deepEqual(after.points, fitted.points, 'fitted again');
  assert.equal(after.scale, fitted.scale);
  assert.equal(after.fit_button, false);
  assert.equal((await page.evaluate(() => window.cspacelab.getScene())).obstacles.length, before, 'no disk was drawn');
}));
