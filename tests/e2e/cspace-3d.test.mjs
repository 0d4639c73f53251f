// Lesson "C-spaces in 3-D" with real mouse and finger events: the cut plane scrubbed in the
// volume view turns the robot in the workspace (state and pixels), the robot dragged in the
// workspace moves its point in the volume, a drag turns the block, PRM's path is drawn in 3-D,
// for the polygon robot (SE(2)) and the 3-link arm (T^3); and the lesson on a phone.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import zlib from 'node:zlib';
import {
  withPage, withBrowser, openLab, openPage, collectErrors, worldToPage, drag, keys, waitFrames, screenshot, inspectPng, api, refusal,
} from './lib/harness.mjs';
import { cliFreeFraction } from './lib/cspace-volume.mjs';

const TWO_PI = 2 * Math.PI;
const wrap = (a) => a - TWO_PI * Math.floor((a + Math.PI) / TWO_PI);
const angleGap = (a, b) => Math.abs(wrap(a - b));

// A layout area in page coordinates (status().layout's are the canvas's).
async function area(page, name) {
  const v = (await api(page, 'status')).layout.views.find((x) => x.name === name);
  assert.ok(v, `the area "${name}" is drawn`);
  const box = await page.locator('canvas').boundingBox();
  return { x: box.x + v.x, y: box.y + v.y, w: v.w, h: v.h };
}

// The strip's inner range (12 px in from each end): the page y of the cut at `unit`.
const stripY = (strip, unit) => strip.y + strip.h - 12 - unit * (strip.h - 24);

// Pixels of a screenshot (device pixels = CSS px here) whose colour is near `rgb`, in a box.
async function countNear(browser, png, box, rgb, tolerance = 40) {
  const probes = [];
  for (let y = box.y; y < box.y + box.h; y += 2) for (let x = box.x; x < box.x + box.w; x += 2) probes.push([x, y]);
  const { at } = await inspectPng(browser, png, probes);
  return at.filter((c) => Math.abs(c[0] - rgb[0]) + Math.abs(c[1] - rgb[1]) + Math.abs(c[2] - rgb[2]) <= tolerance).length;
}

// Roadmap edges whose short way round crosses +-pi on a glued angle (`glued`: which coordinates
// are angles), from the roadmap the API lists.
function seamEdges(prm, glued) {
  let n = 0;
  for (const [a, b] of prm.edge_list) {
    const p = prm.vertices[a], q = prm.vertices[b];
    n += glued.some((g, i) => g && Math.abs(wrap(q[i]) - wrap(p[i])) > Math.PI);
  }
  return n;
}

// The theme API's colours are [r, g, b].
const rgbOf = (c) => c.slice(0, 3);
const close = (a, b, tol = 45) => Math.abs(a[0] - b[0]) + Math.abs(a[1] - b[1]) + Math.abs(a[2] - b[2]) <= tol;
// Whether a pixel within 2 px of a page point has (nearly) that colour: a 3 px outline, anti-aliased.
async function drawnNear(browser, png, at, rgb) {
  const probes = [];
  for (let dy = -2; dy <= 2; ++dy) for (let dx = -2; dx <= 2; ++dx) probes.push([at.x + dx, at.y + dy]);
  return (await inspectPng(browser, png, probes)).at.some((c) => close(c, rgb));
}

test('SE(2): scrubbing the cut turns the robot, dragging it moves its point, a drag turns the block, PRM in 3-D',
  () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'cspace-3d' });
  await page.mouse.move(5, 5);
  await waitFrames(page, 3);
  let s = await api(page, 'state');
  assert.equal(s.robot, 'polygon');
  assert.equal(s.cut.axis, 'theta');
  assert.equal(s.cut.value, s.q[2]);
  assert.ok(s.drawn.faces > 100, `${s.drawn.faces} faces drawn`);
  const scene = await api(page, 'get_scene');
  assert.deepEqual(s.free_fraction_cells, [128, 128, 64]);
  const cliFree = cliFreeFraction(scene, s.free_fraction_cells);
  assert.ok(Math.abs(s.free_fraction - cliFree) < 2e-5, `free fraction ${s.free_fraction}, the CLI's ${cliFree}`);

  // A point on the robot's outline (its short edge's middle, robot frame (0.08, 0)) at q.
  const edge = (q) => [q[0] + 0.08 * Math.cos(q[2]), q[1] + 0.08 * Math.sin(q[2])];
  const before = await screenshot(page, 'cspace3d-se2-before.png');
  const [oldEdge] = await worldToPage(page, [edge(s.q)]);
  const robotRgb = (await inspectPng(browser, before.png, [[oldEdge.x, oldEdge.y]])).at[0];

  // Scrub: a drag in the strip from the cut to 85 % of the way up.
  const strip = await area(page, 'volume_cut');
  await drag(page, { x: strip.x + strip.w / 2, y: stripY(strip, s.cut.unit) },
             { x: strip.x + strip.w / 2, y: stripY(strip, 0.85) });
  let t = await api(page, 'state');
  const want = -Math.PI + TWO_PI * 0.85;
  assert.ok(angleGap(t.q[2], want) < TWO_PI * 2 / (strip.h - 24), `theta ${t.q[2]}, wanted ${want}`);
  assert.equal(t.q[0], s.q[0]);
  assert.equal(t.q[1], s.q[1]);
  assert.equal(t.cut.value, t.q[2]);
  assert.ok(Math.abs(t.q_in_volume[2] - 0.85) < 0.02);
  // The workspace shows the robot turned: its edge is where the new angle puts it, and the old
  // edge point shows something else.
  const after = await screenshot(page, 'cspace3d-se2-scrubbed.png');
  const [newEdge] = await worldToPage(page, [edge(t.q)]);
  assert.ok(await drawnNear(browser, after.png, newEdge, robotRgb), `the turned robot's edge is drawn in ${robotRgb}`);
  const [a2] = (await inspectPng(browser, after.png, [[oldEdge.x, oldEdge.y]])).at;
  assert.ok(!close(a2, robotRgb), `the old edge point ${a2} is no longer the robot`);

  // Page Up over the view moves the plane one layer (of 32) up.
  const vol = await area(page, 'volume');
  await page.mouse.move(vol.x + vol.w * 0.3, vol.y + vol.h * 0.8);
  await waitFrames(page, 2);
  await keys(page, 'PageUp');
  const u = await api(page, 'state');
  assert.ok(Math.abs(u.cut.unit - (t.cut.unit + 1 / 32)) < 1e-6, `cut ${t.cut.unit} -> ${u.cut.unit}`);

  // Drag the robot's body in the workspace: its point in the volume follows.
  const [body, there] = await worldToPage(page, [[u.q[0], u.q[1]], [0.25, 0.6]]);
  await drag(page, body, there);
  const m = await api(page, 'state');
  const px = (await api(page, 'view', { view: 'workspace' })).scale;
  assert.ok(Math.abs(m.q[0] - 0.25) < 3 / px && Math.abs(m.q[1] - 0.6) < 3 / px, `moved to ${m.q}`);
  assert.equal(m.q[2], u.q[2], 'theta unchanged');
  // x and y across the [0, 1] box, theta from -pi: at (0.25, 0.75, 0) a quarter, three quarters, half way up.
  assert.deepEqual(scene.workspace, { min: [0, 0], max: [1, 1] });
  await api(page, 'set_params', { params: { q: [0.25, 0.75, 0] } });
  assert.deepEqual((await api(page, 'state')).q_in_volume, [0.25, 0.75, 0.5]);
  // Outside the space: refused with the ranges, and q stays.
  for (const q of [[1e300, 0, 0], [1.5, 0.5, 0], [0.5, -0.1, 0], [0.5, 0.5, 1e300], [0.5, 0.5]])
    assert.equal(await refusal(page, 'call', 'set_params', { params: { q } }),
                 'q: [x, y, theta], x in [0, 1], y in [0, 1], theta in [-1000, 1000] (radians)', `q = ${q}`);
  assert.deepEqual((await api(page, 'state')).q, [0.25, 0.75, 0]);
  await api(page, 'set_params', { params: { q: m.q } });

  // A drag across the block turns it (0.01 rad a pixel) and changes what it shows.
  const turnBefore = await screenshot(page, 'cspace3d-se2-turn0.png');
  const from = { x: vol.x + vol.w * 0.3, y: vol.y + vol.h * 0.5 };
  await drag(page, from, { x: from.x + 100, y: from.y + 20 });
  const r = await api(page, 'state');
  assert.ok(Math.abs(wrap(r.drawn.yaw - m.drawn.yaw - 1.0)) < 0.05, `yaw ${m.drawn.yaw} -> ${r.drawn.yaw}`);
  assert.ok(Math.abs(r.drawn.pitch - m.drawn.pitch - 0.2) < 0.05, `pitch ${m.drawn.pitch} -> ${r.drawn.pitch}`);
  assert.deepEqual(r.q, m.q, 'turning does not move the robot');
  const turnAfter = await screenshot(page, 'cspace3d-se2-turn1.png');
  const probes = [];
  for (let i = 0; i < 400; ++i) probes.push([vol.x + (i % 20 + 0.5) * vol.w / 20 * 0.9, vol.y + (Math.floor(i / 20) + 0.5) * vol.h / 20]);
  const p0 = (await inspectPng(browser, turnBefore.png, probes)).at, p1 = (await inspectPng(browser, turnAfter.png, probes)).at;
  const differ = p0.filter((c, i) => !close(c, p1[i], 20)).length;
  assert.ok(differ > 40, `${differ} of 400 probes changed as the block turned`);

  // PRM in SE(2): a path, drawn in the path's colour in the volume (none of it before the run).
  const pathRgb = rgbOf((await api(page, 'theme')).colours.path);
  const volBox = { x: vol.x, y: vol.y, w: vol.w - 30, h: vol.h };
  const pathBefore = await countNear(browser, turnAfter.png, volBox, pathRgb);
  await api(page, 'set_params', { params: { samples: 1000, neighbors: 'k:10', seed: 2 } });
  await api(page, 'run');
  await page.mouse.move(5, 5);
  await waitFrames(page, 3);
  const planned = await api(page, 'state');
  assert.ok(planned.prm.solved, 'PRM found a path in SE(2)');
  const shot = await screenshot(page, 'cspace3d-se2-path.png');
  const pathAfter = await countNear(browser, shot.png, volBox, pathRgb);
  assert.ok(pathAfter > pathBefore + 40, `path-coloured pixels in the volume: ${pathBefore} -> ${pathAfter}`);
}));

test('T^3: the 3-link arm, its cut at theta1 and PRM through glued faces', () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'cspace-3d' });
  const bundled = await api(page, 'bundled_scenes');
  await api(page, 'set_scene', { scene: bundled['arm-3link'] });
  await page.mouse.move(5, 5);
  await waitFrames(page, 3);
  const s = await api(page, 'state');
  assert.equal(s.robot, 'arm3');
  assert.equal(s.cut.axis, 'theta1');
  assert.equal(s.cut.value, s.q[0]);
  const arm = (await api(page, 'get_scene')).robot;
  // Link 1's middle at theta1.
  const mid1 = (t1) => [arm.base[0] + 0.5 * arm.lengths[0] * Math.cos(t1), arm.base[1] + 0.5 * arm.lengths[0] * Math.sin(t1)];
  const before = await screenshot(page, 'cspace3d-arm-before.png');
  const [oldMid] = await worldToPage(page, [mid1(s.q[0])]);
  const robotRgb = (await inspectPng(browser, before.png, [[oldMid.x, oldMid.y]])).at[0];
  const strip = await area(page, 'volume_cut');
  await drag(page, { x: strip.x + strip.w / 2, y: stripY(strip, s.cut.unit) },
             { x: strip.x + strip.w / 2, y: stripY(strip, 0.1) });
  const t = await api(page, 'state');
  assert.ok(angleGap(t.q[0], -Math.PI + TWO_PI * 0.1) < TWO_PI * 2 / (strip.h - 24), `theta1 ${t.q[0]}`);
  assert.deepEqual(t.q.slice(1), s.q.slice(1), 'theta2 and theta3 unchanged');
  const after = await screenshot(page, 'cspace3d-arm-scrubbed.png');
  const [newMid] = await worldToPage(page, [mid1(t.q[0])]);
  const [a2] = (await inspectPng(browser, after.png, [[oldMid.x, oldMid.y]])).at;
  const hit = rgbOf((await api(page, 'theme')).colours.hit);
  assert.ok(await drawnNear(browser, after.png, newMid, t.q_free ? robotRgb : hit), `link 1 is drawn at theta1 = ${t.q[0]}`);
  assert.ok(!close(a2, robotRgb) && !close(a2, hit), `link 1 has left its old place: ${a2}`);

  await api(page, 'set_params', { params: { samples: 800, neighbors: 'k:10', seed: 1 } });
  await api(page, 'run');
  await page.mouse.move(5, 5);
  await waitFrames(page, 3);
  const planned = await api(page, 'state');
  assert.ok(planned.prm.solved, 'PRM found a path in T^3');
  // The edges through glued faces, counted from the roadmap's own vertices: all three angles wrap.
  const listed = (await api(page, 'state', { roadmap: true })).prm;
  const seams = seamEdges(listed, [true, true, true]);
  assert.ok(seams > 0, 'some edge crosses a glued face');
  assert.equal(planned.prm.seam_crossing_edges, seams);
  // The free fraction against the CLI's volume of the same scene, and a known configuration's place.
  assert.deepEqual(planned.free_fraction_cells, [96, 96, 96]);
  const cliFree = cliFreeFraction(await api(page, 'get_scene'), planned.free_fraction_cells);
  assert.ok(Math.abs(planned.free_fraction - cliFree) < 2e-5, `free fraction ${planned.free_fraction}, the CLI's ${cliFree}`);
  await api(page, 'set_params', { params: { q: [Math.PI / 2, -Math.PI / 2, 0] } });
  const inVolume = (await api(page, 'state')).q_in_volume;
  assert.ok([0.25, 0.5, 0.75].every((v, i) => Math.abs(inVolume[i] - v) < 1e-12), `(theta2, theta3, theta1) from -pi: ${inVolume}`);
  assert.match(await refusal(page, 'call', 'set_params', { params: { q: [0, 0, 1e300] } }),
               /^q: \[theta1, theta2, theta3\], three angles in \[-1000, 1000\] \(radians\)$/);
  const vol = await area(page, 'volume');
  const shot = await screenshot(page, 'cspace3d-arm-path.png');
  const pathRgb = rgbOf((await api(page, 'theme')).colours.path);
  const n = await countNear(browser, shot.png, { x: vol.x, y: vol.y, w: vol.w - 30, h: vol.h }, pathRgb);
  assert.ok(n > 40, `${n} path-coloured pixels in the volume`);
}));

// A polygon-robot scene whose 3-D C-space costs far past the lab's limit: 100 concave stars
// of 64 vertices (62 triangles each) over the box, the robot made a 32-gon (one convex piece).
function heavyScene(base) {
  const [lo, hi] = [base.workspace.min, base.workspace.max];
  const w = [(hi[0] - lo[0]) / 10, (hi[1] - lo[1]) / 10];
  const obstacles = [];
  for (let i = 0; i < 10; ++i) for (let j = 0; j < 10; ++j) {
    const c = [lo[0] + (i + 0.5) * w[0], lo[1] + (j + 0.5) * w[1]];
    const vertices = [];
    for (let k = 0; k < 64; ++k) {
      const r = (k % 2 ? 0.2 : 0.4) * Math.min(w[0], w[1]), a = TWO_PI * k / 64;
      vertices.push([c[0] + r * Math.cos(a), c[1] + r * Math.sin(a)].map((v) => +v.toFixed(5)));
    }
    obstacles.push({ type: 'polygon', vertices });
  }
  const robot = { type: 'polygon', vertices: [] };
  for (let k = 0; k < 32; ++k) robot.vertices.push([0.02 * Math.cos(TWO_PI * k / 32), 0.02 * Math.sin(TWO_PI * k / 32)]);
  return { ...base, robot, obstacles };
}

test('A scene whose volumes cost past the lab\'s limit is refused, by the API and by a link',
  () => withBrowser(async ({ browser, url }) => {
  const page = await browser.newPage();
  const errors = collectErrors(page);
  await openLab(page, url + '?lesson=cspace-3d');
  await waitFrames(page, 2);
  const before = await api(page, 'get_scene');
  const heavy = heavyScene(before);
  const t0 = Date.now();
  const why = await refusal(page, 'call', 'set_scene', { scene: heavy });
  assert.ok(Date.now() - t0 < 5000, `refused in ${Date.now() - t0} ms, before any volume is built`);
  assert.match(why, /too much work for the lab: 4 x [\d.e+]+ vertex sums \+ [\d.e+]+ C-obstacle pieces x 128 rows a slice x 64 slices = [\d.e+]+, plus [\d.e+]+ for the drawn block, over the lab's [\d.e+]+/);
  assert.deepEqual(await api(page, 'get_scene'), before, 'the old scene stays');
  assert.equal((await api(page, 'state')).robot, 'polygon');
  await page.close();

  // The same scene by link (samples=0: no roadmap to price) opens the lesson's own scene with a notice.
  const linked = await browser.newPage();
  const linkErrors = collectErrors(linked);
  const zipped = zlib.deflateRawSync(Buffer.from(JSON.stringify(heavy)), { level: 9 }).toString('base64url');
  const t1 = Date.now();
  await openLab(linked, url + `?lesson=cspace-3d&samples=0&scene=z.${zipped}`);
  await waitFrames(linked, 2);
  assert.ok(Date.now() - t1 < 20000, `the link opened in ${Date.now() - t1} ms`);
  assert.match((await api(linked, 'status')).notice, /too much work for the lab/);
  assert.equal((await api(linked, 'get_scene')).obstacles.length, before.obstacles.length, 'the bundled scene is shown');
  await linked.close();
  assert.deepEqual(errors, []);
  assert.deepEqual(linkErrors, []);
}));

test('Phone upright: the lesson is usable with fingers', () => withBrowser(async ({ browser, url }) => {
  const { page, errors } = await openPage(browser, url + '?lesson=cspace-3d',
                                         { viewport: { width: 390, height: 844 }, deviceScaleFactor: 3, hasTouch: true, isMobile: true });
  await waitFrames(page, 3);
  const layout = (await api(page, 'status')).layout;
  assert.equal(layout.mode, 'compact');
  const ws = layout.views.find((v) => v.name === 'workspace'), vol = layout.views.find((v) => v.name === 'volume');
  assert.ok(ws && vol, 'both views are drawn');
  assert.ok(vol.w >= 0.9 * 390 && vol.h >= 150, `the volume is ${vol.w} x ${vol.h}`);
  assert.ok(vol.y + vol.h <= 844, 'the volume is on screen');
  const cdp = await page.context().newCDPSession(page);
  const touch = async (type, points) => {
    await cdp.send('Input.dispatchTouchEvent', { type, touchPoints: points.map((p, i) => ({ x: p.x, y: p.y, id: i })) });
    await waitFrames(page, 2);
  };
  const fingerDrag = async (from, to, steps = 10) => {
    await touch('touchStart', [from]);
    for (let i = 1; i <= steps; ++i)
      await touch('touchMove', [{ x: from.x + (to.x - from.x) * i / steps, y: from.y + (to.y - from.y) * i / steps }]);
    await touch('touchEnd', []);
    await waitFrames(page, 2);
  };
  const s = await api(page, 'state');
  const strip = await area(page, 'volume_cut');
  await fingerDrag({ x: strip.x + strip.w / 2, y: stripY(strip, s.cut.unit) }, { x: strip.x + strip.w / 2, y: stripY(strip, 0.7) });
  const t = await api(page, 'state');
  assert.ok(Math.abs(t.cut.unit - 0.7) < 0.03, `a finger scrubs the cut: ${s.cut.unit} -> ${t.cut.unit}`);
  const v = await area(page, 'volume');
  await fingerDrag({ x: v.x + v.w * 0.3, y: v.y + v.h * 0.5 }, { x: v.x + v.w * 0.3 + 80, y: v.y + v.h * 0.5 });
  const r = await api(page, 'state');
  assert.ok(Math.abs(wrap(r.drawn.yaw - t.drawn.yaw)) > 0.3, `a finger turns the block: ${t.drawn.yaw} -> ${r.drawn.yaw}`);
  await screenshot(page, 'cspace3d-phone.png');
  assert.deepEqual(errors, []);
  await page.close();
}));
