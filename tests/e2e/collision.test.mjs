// Lesson "Collision checking" in the browser: the P12 edge checked both ways, the bisection
// trace identical to `cspacelab check --trace`, an obstacle dragged with the mouse changing the
// verdict live, and the arm variant.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, worldToPage, drag, keys, waitFrames, screenshot, inspectPng, api, cli,
         tempJson } from './lib/harness.mjs';

// The smallest N for which N equally spaced configurations see a disk, by brute force here for
// the point robot: with the ends (t = i/(N-1), i = 0..N-1), with one end (t = i/N, i = 1..N) or
// with neither (t = i/(N+1), i = 1..N). null when none up to max does.
function bruteMinN(p, q, disks, reading, max = 2000) {
  const hits = (t) => disks.some(({ center: [cx, cy], radius }) =>
    Math.hypot(p[0] + t * (q[0] - p[0]) - cx, p[1] + t * (q[1] - p[1]) - cy) <= radius);
  for (let n = reading === 'ends' ? 2 : 1; n <= max; ++n) {
    const [first, last, steps] = reading === 'ends' ? [0, n - 1, n - 1] : reading === 'one' ? [1, n, n] : [1, n, n + 1];
    for (let i = first; i <= last; ++i) if (hits(i / steps)) return n;
  }
  return null;
}

test('Collision checking: P12 both ways, matching the CLI, live edits', () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'collision' });
  await waitFrames(page, 2);

  // P12: N = 4 misses the disk, the smallest N that sees it is 5.
  let s = await api(page, 'state');
  assert.deepEqual(s.p, [0, 0]);
  assert.deepEqual(s.q, [1, 0]);
  assert.equal(s.grid_n, 4);
  assert.equal(s.grid.collision, false);
  assert.equal(s.min_grid, 5);
  // The handout's N read three ways: with p and q 5, with one of them 4, with neither 3.
  const p12Disk = [{ center: [0.2, 0.05], radius: 0.1 }];
  assert.deepEqual([s.min_grid, s.min_grid_one_end, s.min_grid_interior],
                   ['ends', 'one', 'none'].map((r) => bruteMinN([0, 0], [1, 0], p12Disk, r)));
  assert.deepEqual([s.min_grid_one_end, s.min_grid_interior], [4, 3]);
  await api(page, 'set_params', { params: { grid_n: 5 } });
  assert.equal((await api(page, 'state')).grid.collision_t, 0.25);

  // Step the bisection midpoint by midpoint (the '.' key), then compare with the CLI.
  await page.mouse.move(700, 300);
  for (let i = 0; i < 3; ++i) await keys(page, '.');
  assert.equal((await api(page, 'state')).shown, 3);
  await api(page, 'run');
  s = await api(page, 'state');
  assert.equal(s.shown, s.bisection.trace.length + s.bisection.pieces.length);
  const scene = tempJson(await api(page, 'get_scene'));
  const check = cli('check', scene, '--from', s.p.join(','), '--to', s.q.join(','), '--checker', 'bisection', '--trace');
  assert.deepEqual(s.bisection.trace, check.trace);
  assert.deepEqual(s.bisection.pieces, check.pieces);
  assert.equal(s.bisection.collision_t, check.collision_t);
  assert.deepEqual(s.bisection.trace.map((e) => e.t), [0, 1, 0.5, 0.25]);
  const shotP12 = await screenshot(page, 'collision-p12.png');
  assert.ok((await inspectPng(browser, shotP12.png)).colours > 30);

  // Drag the disk off the line with the mouse: the edge becomes free, live.
  await keys(page, 'v');
  const [disk, away] = await worldToPage(page, [[0.2, 0.05], [0.2, 0.3]]);
  await drag(page, disk, away);
  s = await api(page, 'state');
  assert.equal(s.bisection.collision, false);
  assert.equal(s.min_grid, null);
  assert.equal(s.min_grid_interior, null);
  assert.equal(s.min_grid_one_end, null);
  const moved = tempJson(await api(page, 'get_scene'));
  const freeCheck = cli('check', moved, '--from', '0,0', '--to', '1,0', '--trace');
  assert.deepEqual(s.bisection.trace, freeCheck.trace);
  assert.deepEqual(s.bisection.pieces, freeCheck.pieces);

  // A disk the line barely cuts, on a slant: a deep bisection (its numbers crowd the plot below
  // the view: none may cover another) and larger counts, each as brute force finds it.
  const deep = { version: 1, robot: { type: 'point' }, workspace: { min: [-0.5, -0.5], max: [1.5, 0.5] },
                 obstacles: [{ type: 'disk', center: [0.3, 0.0995], radius: 0.1 }], start: [0, 0], goal: [1, 0] };
  await api(page, 'set_scene', { scene: deep });
  await api(page, 'set_params', { params: { p: [0, 0.001], q: [1, -0.002] } });
  await api(page, 'run');
  s = await api(page, 'state');
  const disks = deep.obstacles;
  assert.deepEqual([s.min_grid, s.min_grid_one_end, s.min_grid_interior],
                   ['ends', 'one', 'none'].map((r) => bruteMinN(s.p, s.q, disks, r)));
  assert.ok(s.min_grid > 8, `min_grid ${s.min_grid}`);
  const deepCheck = cli('check', tempJson(await api(page, 'get_scene')), '--from', s.p.join(','), '--to', s.q.join(','),
                        '--min-grid');
  assert.equal(s.min_grid, deepCheck.min_grid);
  assert.ok(s.bisection.trace.length > 10, `${s.bisection.trace.length} evaluations`);
  await page.mouse.move(5, 5);
  await waitFrames(page, 3);
  await screenshot(page, 'collision-deep-labels.png');

  // The arm: the same machinery on T^2, drawn as arms.
  await api(page, 'set_scene', { scene: { version: 1, robot: { type: 'arm2', base: [0.5, 0.5], lengths: [0.3, 0.2] },
                                          obstacles: [{ type: 'disk', center: [0.1, 0.5], radius: 0.05 }],
                                          start: [3, 0], goal: [-3, 0] } });
  s = await api(page, 'state');
  assert.equal(s.robot, 'arm2');
  assert.equal(s.bisection.collision, true);  // the short way round passes the disk
  const arm = cli('check', tempJson(await api(page, 'get_scene')), '--from', '3,0', '--to', '-3,0', '--trace');
  assert.deepEqual(s.bisection.trace, arm.trace);
  await api(page, 'run');
  await page.mouse.move(5, 5);
  await waitFrames(page, 3);
  const shotArm = await screenshot(page, 'collision-arm.png');
  assert.ok((await inspectPng(browser, shotArm.png)).colours > 30);
}));

// The counts in a 900 px wide embed (a panel of 280 px): in view without scrolling.
test('Collision checking: the P12 counts in a 900 px embed', () => withPage({ viewport: { width: 900, height: 640 },
  open: 'embed.html?lesson=collision&scene=p12' }, async ({ page, browser }) => {
  const s = await api(page, 'state');
  assert.deepEqual([s.min_grid, s.min_grid_one_end, s.min_grid_interior], [5, 4, 3]);
  await api(page, 'run');
  await page.mouse.move(5, 5);
  await waitFrames(page, 3);
  const shot = await screenshot(page, 'collision-embed.png');
  assert.ok((await inspectPng(browser, shot.png)).colours > 20);
}));
