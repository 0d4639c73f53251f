// Scene editing by keyboard alone (issue "Keyboard alone"): no mouse event at all in this file
// (no page.mouse, no click), the lab focused by Tab from page load, the API used only to open
// lessons by URL and to read state. A disk placed with D and Enter, moved by the arrows by the
// step the view defines, resized with + and -; the start focused with N and moved; the planner
// stepped and played with '.' and Space; the arm's start moved in its C-space square; and Tab
// leaves the canvas, in the page and in an embed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, withPage, collectErrors, keys, waitFrames, screenshot, inspectPng, api } from './lib/harness.mjs';

// The keyboard's step in a view: its visible width / 50, rounded down to 1, 2 or 5 times a power
// of ten (scene_editor_keys.cpp says why).
async function keyStep(page, view = 'workspace') {
  const v = await page.evaluate((name) => window.cspacelab.view([], name), view);
  const x = (v.canvas_max[0] - v.canvas_min[0]) / v.scale / 50;
  const p = 10 ** Math.floor(Math.log10(x));
  const m = x / p;
  return (m >= 5 - 1e-9 ? 5 : m >= 2 - 1e-9 ? 2 : 1) * p;
}

// The world point at the middle of a view's canvas (where Enter places a new obstacle).
async function viewMiddle(page, view = 'workspace') {
  const v = await page.evaluate((name) => window.cspacelab.view([[0, 0], [1, 1]], name), view);
  const [[x0, y0], [x1, y1]] = v.points;
  const mx = (v.canvas_min[0] + v.canvas_max[0]) / 2, my = (v.canvas_min[1] + v.canvas_max[1]) / 2;
  return [(mx - x0) / (x1 - x0), (my - y0) / (y1 - y0)];
}

const canvasFocused = (page) => page.evaluate(() => document.activeElement === document.querySelector('canvas'));

// Tab until the canvas has the focus (the page may give it the focus on load: then Tab first
// leaves it, which is checked too, and Shift+Tab comes back). Returns how many presses it took.
// After the canvas come the lab's own HTML controls (web/lab-access.js), so the way round to it
// by Tab alone is long.
async function tabToCanvas(page) {
  if (await canvasFocused(page)) {
    await keys(page, 'Tab');
    assert.equal(await canvasFocused(page), false, 'Tab leaves the canvas: no keyboard trap');
    await keys(page, 'Shift+Tab');
    if (await canvasFocused(page)) return 2;
  }
  for (let i = 1; i <= 60; ++i) {
    await keys(page, 'Tab');
    if (await canvasFocused(page)) return i;
  }
  assert.fail('Tab never reached the canvas');
}

const close = (a, b, what, eps = 1e-9) => assert.ok(Math.abs(a - b) <= eps, `${what}: ${a} vs ${b}`);

test('place, move and resize a disk, move the start, and run PRM by keyboard alone',
  () => withPage({ open: 'index.html?lesson=step-prm&samples=40&seed=3', viewport: { width: 1280, height: 800 } }, async ({ page, browser }) => {
  await tabToCanvas(page);
  const s = await keyStep(page);
  assert.ok(s > 0.005 && s < 0.1, `a step of the 0..1 workspace: ${s}`);
  const before = await api(page, 'get_scene');

  // D, Enter: a disk in the middle of the view, radius 5 steps.
  const mid = await viewMiddle(page);
  await keys(page, 'd', 'Enter');
  let scene = await api(page, 'get_scene');
  assert.equal(scene.obstacles.length, before.obstacles.length + 1, 'Enter placed an obstacle');
  const i = scene.obstacles.length - 1;
  let disk = scene.obstacles[i];
  assert.equal(disk.type, 'disk');
  close(disk.center[0], mid[0], 'centre x', 1e-4);
  close(disk.center[1], mid[1], 'centre y', 1e-4);
  close(disk.radius, 5 * s, 'radius');
  const c0 = disk.center;

  // The arrows move it by exactly a step each; Shift by a tenth of one.
  await keys(page, 'ArrowRight', 'ArrowRight', 'ArrowRight', 'ArrowUp');
  disk = (await api(page, 'get_scene')).obstacles[i];
  close(disk.center[0], c0[0] + 3 * s, 'three steps right');
  close(disk.center[1], c0[1] + s, 'one step up');
  await keys(page, 'Shift+ArrowLeft');
  disk = (await api(page, 'get_scene')).obstacles[i];
  close(disk.center[0], c0[0] + 3 * s - 0.1 * s, 'a fine step left', 1e-12 + 1e-9);
  await keys(page, 'ArrowDown');
  disk = (await api(page, 'get_scene')).obstacles[i];
  close(disk.center[1], c0[1], 'back down');

  // + and - resize it; each press is one undo step.
  await keys(page, '+', '+', '-');
  disk = (await api(page, 'get_scene')).obstacles[i];
  close(disk.radius, 6 * s, 'two up, one down');
  await keys(page, 'Control+z');
  close((await api(page, 'get_scene')).obstacles[i].radius, 7 * s, 'Ctrl+Z undid the last press only');
  await keys(page, 'Control+y');
  close((await api(page, 'get_scene')).obstacles[i].radius, 6 * s, 'and Ctrl+Y redid it');
  // A radius that would go to zero is refused, with a message, and nothing changes.
  for (let k = 0; k < 6; ++k) await keys(page, '-');
  assert.match((await api(page, 'status')).notice, /radius must stay above zero/);
  close((await api(page, 'get_scene')).obstacles[i].radius, s, 'the smallest radius a step allows');
  await keys(page, '+', '+', '+');
  await waitFrames(page, 2);
  const ringed = await screenshot(page, 'keyboard-edit-disk-focus.png');
  const [x, y] = (await page.evaluate((c) => window.cspacelab.view([c]), disk.center)).points[0];
  const box = await page.evaluate(() => document.querySelector('canvas').getBoundingClientRect().toJSON());
  // The ring: yellow inside black, 8 px outside the rim (4 steps of radius now).
  const rPx = 4 * s * (await page.evaluate(() => window.cspacelab.view([]))).scale + 8;
  // (On the left: the selection's "r = ..." label is on the right.)
  const { at: [probe] } = await inspectPng(browser, ringed.png, [[box.x + x - rPx, box.y + y]]);
  assert.ok(probe[0] > 200 && probe[1] > 190 && probe[2] < 120, `the focus ring is drawn round the disk: ${probe}`);

  // N: the next thing after the last obstacle is the start. The arrows move it.
  const start0 = (await api(page, 'get_scene')).start;
  await keys(page, 'n');
  await keys(page, 'ArrowRight', 'ArrowRight', 'ArrowUp');
  scene = await api(page, 'get_scene');
  close(scene.start[0], Math.min(start0[0] + 2 * s, scene.workspace.max[0]), 'start moved right');
  close(scene.start[1], Math.min(start0[1] + s, scene.workspace.max[1]), 'start moved up');
  assert.deepEqual(scene.obstacles[i], (await api(page, 'get_scene')).obstacles[i], 'the disk stayed');
  await waitFrames(page, 2);
  await screenshot(page, 'keyboard-edit-start-focus.png');
  // Delete with the start focused removes nothing (the disk is no longer selected).
  await keys(page, 'Delete');
  assert.equal((await api(page, 'get_scene')).obstacles.length, before.obstacles.length + 1);
  // Esc leaves the focus: the arrows then move nothing.
  await keys(page, 'Escape', 'ArrowLeft');
  assert.deepEqual((await api(page, 'get_scene')).start, scene.start, 'no focus, no move');
  // (That arrow walked ImGui's own keyboard navigation into the panel, where Space would press
  // its first button: Esc leaves it.)
  await keys(page, 'Escape');

  // The planner by its keys: '.' steps, Space plays until the end.
  await keys(page, '.', '.', '.');
  assert.equal((await api(page, 'state')).steps, 3, "'.' stepped three times");
  await keys(page, ' ');  // 40 samples at 20 steps/s: a few seconds
  await page.waitForFunction(() => window.cspacelab.state().done, null, { timeout: 90000 });
  const result = await api(page, 'state');
  assert.equal(result.done, true);
  assert.ok(result.nodes > 0, `a roadmap: ${result.nodes} nodes, solved ${result.solved}`);
  assert.deepEqual(result.path.length > 0, result.solved, 'a path exactly when solved');
  await screenshot(page, 'keyboard-edit-run.png');

  // And Tab still leaves the canvas.
  assert.equal(await canvasFocused(page), true);
  await keys(page, 'Tab');
  assert.equal(await canvasFocused(page), false, 'Tab leaves the canvas after all that');
}));

test('a polygon and a wall placed by keyboard: vertices by H and the arrows, refusals kept',
  () => withPage({ open: 'index.html?lesson=step-prm' }, async ({ page }) => {
  await tabToCanvas(page);
  const s = await keyStep(page);
  const n = (await api(page, 'get_scene')).obstacles.length;
  // P, Enter: a square of side 10 steps; H focuses its first vertex, the arrows move it alone.
  await keys(page, 'p', 'Enter');
  let poly = (await api(page, 'get_scene')).obstacles[n];
  assert.equal(poly.type, 'polygon');
  assert.equal(poly.vertices.length, 4);
  close(poly.vertices[2][0] - poly.vertices[0][0], 10 * s, 'side');
  const v0 = poly.vertices;
  await keys(page, 'h', 'ArrowLeft');
  poly = (await api(page, 'get_scene')).obstacles[n];
  close(poly.vertices[0][0], v0[0][0] - s, 'the vertex moved a step left');
  assert.deepEqual(poly.vertices.slice(1), v0.slice(1), 'the others stayed');
  // Up and up: the vertex would cross the square's top edge; that move is refused.
  for (let k = 0; k < 12; ++k) await keys(page, 'ArrowUp');
  assert.match((await api(page, 'status')).notice, /cross itself/);
  poly = (await api(page, 'get_scene')).obstacles[n];
  assert.ok(poly.vertices[0][1] < v0[0][1] + 12 * s - 1e-9, `the vertex stopped short: ${poly.vertices[0][1]}`);
  assert.ok(poly.vertices[0][1] >= v0[3][1] - 1e-9, 'after the moves that kept it simple');
  // Shift+H back to the whole polygon; + scales it about its centroid by 10 %.
  await keys(page, 'Shift+H');
  const before = (await api(page, 'get_scene')).obstacles[n].vertices;
  await keys(page, '+');
  const after = (await api(page, 'get_scene')).obstacles[n].vertices;
  const cx = before.reduce((a, v) => a + v[0], 0) / 4;
  close(after[1][0] - cx, 1.1 * (before[1][0] - cx), 'scaled about the centroid', 1e-12);
  // W, Enter: a wall 10 steps long; + lengthens it by a step.
  await keys(page, 'w', 'Enter');
  let wall = (await api(page, 'get_scene')).obstacles[n + 1];
  assert.equal(wall.type, 'segment');
  close(wall.b[0] - wall.a[0], 10 * s, 'length');
  await keys(page, '+');
  wall = (await api(page, 'get_scene')).obstacles[n + 1];
  close(wall.b[0] - wall.a[0], 11 * s, 'a step longer');
  await waitFrames(page, 2);
  await screenshot(page, 'keyboard-edit-wall.png');
}));

test("the arm's start moves by keyboard in its C-space square, round the torus",
  () => withPage({ open: 'index.html?lesson=torus', viewport: { width: 1280, height: 800 } }, async ({ page }) => {
  await tabToCanvas(page);
  const s = await keyStep(page, 'cspace');
  assert.ok(s > 0.01 && s < 0.5, `a step of the square [-pi, pi)^2: ${s}`);
  const start0 = (await api(page, 'state')).start;
  await keys(page, 'n', 'ArrowRight', 'ArrowRight', 'ArrowDown');
  const start1 = (await api(page, 'state')).start;
  const wrap = (a) => a - 2 * Math.PI * Math.floor((a + Math.PI) / (2 * Math.PI));
  close(start1[0], wrap(start0[0] + 2 * s), 'theta1 two steps', 1e-12);
  close(start1[1], wrap(start0[1] - s), 'theta2 a step down', 1e-12);
  await waitFrames(page, 2);
  await screenshot(page, 'keyboard-edit-torus-start.png');
  // Held down, the key repeats: theta1 goes round the square's edge and comes back on the other
  // side (below where it began), and the whole burst is one undo step.
  await page.keyboard.down('ArrowRight');
  await page.waitForFunction((t) => window.cspacelab.state().start[0] < t, start1[0], { timeout: 30000 });
  await page.keyboard.up('ArrowRight');
  await waitFrames(page, 3);
  const start2 = (await api(page, 'state')).start;
  assert.ok(start2[0] < start1[0] && start2[1] === start1[1], `theta1 wrapped round to ${start2[0]}`);
  await keys(page, 'Control+z');
  assert.deepEqual((await api(page, 'state')).start, start1, 'Ctrl+Z undid the whole burst');
}));

test('Tab goes into an embedded lab and out again to the page around it',
  () => withBrowser(async ({ browser, url }) => {
  const page = await browser.newPage({ viewport: { width: 1000, height: 700 } });
  const errors = collectErrors(page);
  const host = url + 'keyboard-host.html';
  await page.route(host, (route) => route.fulfill({
    contentType: 'text/html',
    body: `<!doctype html><html><head><meta charset="utf-8"><title>host</title></head><body>
      <a id="before" href="#x">before the lab</a>
      <iframe id="f" src="embed.html?lesson=step-prm" style="width:640px;height:420px" title="lab"></iframe>
      <button id="after">after the lab</button></body></html>`,
  }));
  await page.goto(host);
  const frame = await (await page.waitForSelector('iframe')).contentFrame();
  await frame.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2, null, { timeout: 30000 });
  const where = () => page.evaluate(() => document.activeElement.id || document.activeElement.tagName);
  const inLab = () => frame.evaluate(() => document.activeElement === document.querySelector('canvas'));
  const press = async (...names) => {  // the page's keyboard, the lab's frames
    for (const k of names) { await page.keyboard.press(k); await waitFrames(frame, 1); }
  };
  await press('Tab');
  assert.equal(await where(), 'before');
  await press('Tab');
  assert.equal(await where(), 'f');
  assert.equal(await inLab(), true, 'Tab reached the lab');
  // Keys reach it there: N and the arrows move the start.
  const start0 = (await frame.evaluate(() => window.cspacelab.getScene())).start;
  await press('n', 'ArrowUp');
  assert.ok((await frame.evaluate(() => window.cspacelab.getScene())).start[1] > start0[1], 'the start moved up');
  // Tab goes on through the lab's own HTML controls (web/lab-access.js), then out to the page.
  const inSection = () => frame.evaluate(() => document.querySelector('.lab-access').contains(document.activeElement));
  await press('Tab');
  assert.equal(await inLab(), false, 'Tab left the canvas');
  assert.equal(await inSection(), true, 'for the lab\'s HTML controls');
  let tabs = 1;
  while ((await where()) === 'f' && tabs < 60) { await press('Tab'); ++tabs; }
  assert.equal(await where(), 'after', `Tab left the lab for the page (after ${tabs} presses)`);
  await press('Shift+Tab');
  assert.equal(await where(), 'f', 'Shift+Tab came back into the lab');
  let back = 1;
  while ((await where()) === 'f' && back < 60) { await press('Shift+Tab'); ++back; }
  assert.equal(await where(), 'before', 'and Shift+Tab leaves it backwards');
  assert.equal(back, tabs + 1, 'through the same controls and the canvas (one more: the canvas)');
  assert.deepEqual(errors, []);
}));

// The whole journey with no mouse event: from the front page, a lesson chosen in the
// lab's own HTML, a disk placed and the start moved on the canvas, PRM run from the HTML's Run
// all, and the result read in the HTML's description, which must agree with the app's state.
test('from page load to a planned path by keyboard alone, the result read from the DOM',
  () => withPage({ open: 'index.html' }, async ({ page }) => {
  const focused = () => page.evaluate(() => {
    const a = document.activeElement;
    return { lesson: a && a.dataset ? a.dataset.lesson || null : null, text: a ? a.textContent : '' };
  });
  await tabToCanvas(page);
  // Tab on from the canvas into the lab's HTML, to the Step PRM lesson button.
  let found = false;
  for (let i = 0; i < 40 && !found; ++i) {
    await keys(page, 'Tab');
    found = (await focused()).lesson === 'step-prm';
  }
  assert.ok(found, 'Tab reaches the Step PRM lesson button');
  await keys(page, 'Enter');
  await page.waitForFunction(() => window.cspacelab.status().lesson === 'step-prm');
  // Back to the canvas with Shift+Tab.
  for (let i = 0; i < 40 && !(await canvasFocused(page)); ++i) await keys(page, 'Shift+Tab');
  assert.equal(await canvasFocused(page), true, 'Shift+Tab returns to the canvas');

  const s = await keyStep(page);
  const before = await api(page, 'get_scene');
  await keys(page, 'd', 'Enter');
  const after = await api(page, 'get_scene');
  assert.equal(after.obstacles.length, before.obstacles.length + 1, 'a disk placed by D, Enter');
  // N after the new disk (the last obstacle) focuses the start; two steps left.
  await keys(page, 'n', 'ArrowLeft', 'ArrowLeft');
  const moved = (await api(page, 'get_scene')).start;
  close(moved[0], Math.max(before.start[0] - 2 * s, before.workspace.min[0]), 'the start moved two steps left');
  close(moved[1], before.start[1], 'and no step up or down');

  // Run all, in the HTML after the canvas.
  found = false;
  for (let i = 0; i < 60 && !found; ++i) {
    await keys(page, 'Tab');
    found = (await focused()).text.trim() === 'Run all';
  }
  assert.ok(found, 'Tab reaches Run all');
  await keys(page, 'Enter');
  await page.waitForFunction(() => window.cspacelab.state().done && !window.cspacelab.status().busy, null, { timeout: 90000 });
  const state = await api(page, 'state');
  // The description says what the app's state says (4 significant digits).
  await page.waitForFunction((solved) => {
    const d = document.querySelector('.lab-access-description');
    return d && (solved ? /Path found/.test(d.textContent) : /No path/.test(d.textContent));
  }, state.solved, { timeout: 10000 });
  const text = await page.evaluate(() => document.querySelector('.lab-access-description').textContent);
  if (state.solved) {
    const m = text.match(/Path found: (\d+) edges?, length ([0-9]+(?:\.[0-9]+)?)/);
    assert.ok(m, `the description gives the path: ${text}`);
    assert.equal(Number(m[1]), state.path.length - 1, 'its edges');
    assert.equal(Number(m[2]), Number(state.path_length.toPrecision(4)), 'its length');
  }
  const at = text.match(/Start at \(([-0-9.e]+), ([-0-9.e]+)\)/);
  assert.ok(at, `the description gives the start: ${text}`);
  assert.deepEqual([Number(at[1]), Number(at[2])], moved.map((v) => Number(v.toPrecision(4))), 'the moved start in words');
}));
