// Lesson "Collision checking" in the browser: the P12 edge checked both ways, the bisection
// trace identical to `cspacelab check --trace`, an obstacle dragged with the mouse changing the
// verdict live, and the arm variant.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, worldToPage, drag, keys, waitFrames, screenshot, inspectPng, api, cli,
         tempJson, pageButton, click, expectView, sceneProbes } from './lib/harness.mjs';

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
  // The picture: the disk, p and q, free space off the line (and off the λ label in the top
  // left corner), and the midpoints t = 0.5 (free, green) and t = 0.25 (in the disk, vermillion).
  const p12 = await api(page, 'get_scene');
  const [wx0] = p12.workspace.min, [wx1, wy1] = p12.workspace.max;
  await expectView(page, browser, 'collision-p12.png', [
    ...sceneProbes(p12, { avoid: [[s.p, s.q], [[wx0, wy1], [wx0 + 0.6 * (wx1 - wx0), wy1]]] }),
    { at: [0.2, 0.11], look: 'obstacle', why: 'the disk above the line' },
    { at: [0.5, 0], look: [0, 158, 115], why: 'the free midpoint t = 0.5' },
    // (its dot's upper part: the piece under test is drawn across its middle, in the current step's pink)
    { at: [0.25, 0], dy: -4, look: [213, 94, 0], why: 'the midpoint t = 0.25, in the disk' },
    { at: [0.25, 0], look: [204, 121, 167], why: 'the piece under test' },
  ]);

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
  // The arm turns from θ₁ = 3 to -3 the short way, through π: every arm drawn points left, and
  // the right of the workspace stays empty (an arm turned the long way would sweep through it).
  const right = [];
  for (const x of [0.78, 0.88, 0.96]) for (const y of [0.08, 0.3, 0.5, 0.7, 0.92]) right.push({ at: [x, y], look: 'canvas', why: 'right of the base' });
  await expectView(page, browser, 'collision-arm.png', right);
}));

// The counts in a 900 px wide embed (a panel of 280 px): in view without scrolling.
test('Collision checking: the P12 counts in a 900 px embed', () => withPage({ viewport: { width: 900, height: 640 },
  open: 'embed.html?lesson=collision&scene=p12' }, async ({ page, browser }) => {
  const s = await api(page, 'state');
  assert.deepEqual([s.min_grid, s.min_grid_one_end, s.min_grid_interior], [5, 4, 3]);
  await api(page, 'run');
  await page.mouse.move(5, 5);
  await waitFrames(page, 3);
  const scene = await api(page, 'get_scene');
  await expectView(page, browser, 'collision-embed.png', [
    ...sceneProbes(scene, { free: 0 }),  // (free space is crossed by the last piece's clearance circles)
    { at: [0.2, 0.11], look: 'obstacle', why: 'the disk above the line' },
  ]);
}));

// The bisection's picture stays readable when it goes deep (issue 21): q dragged to (1, -0.3)
// makes the edge graze the disk, and the check splits about 15 times near it. The table keeps
// one meaning per column on every row, each number as the geometry gives it (computed here);
// the strip's third row magnifies the piece under test, its midpoints drawn where they fall.
test('Collision checking: a deep bisection, its table column by column and the zoom on the piece',
  () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'collision' });
  await waitFrames(page, 2);
  const [q, there] = await worldToPage(page, [[1, 0], [1, -0.3]]);
  await drag(page, q, there);
  let s = await api(page, 'state');
  assert.ok(Math.abs(s.q[0] - 1) < 0.005 && Math.abs(s.q[1] + 0.3) < 0.005, `q = ${s.q}`);
  await click(page, await pageButton(page, 'finish-phase'));
  s = await api(page, 'state');
  const events = s.bisection.trace.length + s.bisection.pieces.length;
  assert.equal(s.shown, events, 'run to its end');
  assert.ok(s.bisection.trace.length >= 12, `${s.bisection.trace.length} evaluations: a deep check`);

  const { header, rows } = s.trace_table;
  assert.deepEqual(header, ['#', 'piece', 'λ', '', 'η₀+η₁', 't', 'η(t)']);
  assert.equal(rows.length, events);
  const scene = await api(page, 'get_scene');
  const [{ center: [cx, cy], radius }] = scene.obstacles;
  const [px, py] = s.p, [qx, qy] = s.q;
  const eta = (t) => Math.hypot(px + t * (qx - px) - cx, py + t * (qy - py) - cy) - radius;
  const len = Math.hypot(qx - px, qy - py);
  const number = /^-?\d+(\.\d+)?(e-?\d+)?$/;
  let evaluations = 0, certified = 0;
  for (const r of rows) {
    const [n, piece, lambda, cmp, sum, t, etaT] = r;
    // Evaluations are numbered 1, 2, ... and have a t and its clearance; nothing else does.
    if (n !== '') {
      assert.equal(Number(n), ++evaluations, r.join(' | '));
      assert.match(t, number);
      assert.ok(Math.abs(Number(etaT) - eta(Number(t))) < 6e-4, `η(${t}) = ${etaT}, the geometry's ${eta(Number(t))}`);
    } else {
      assert.equal(t, '', r.join(' | '));
      assert.equal(etaT, '', r.join(' | '));
    }
    if (piece === 'end') {  // an endpoint's evaluation: no piece, no bound, no comparison
      assert.deepEqual([lambda, cmp, sum], ['', '', ''], r.join(' | '));
      continue;
    }
    const m = /^\[(\S+), (\S+)\]$/.exec(piece);
    assert.ok(m, `piece: "${piece}"`);
    const [t0, t1] = [Number(m[1]), Number(m[2])];
    assert.ok(t0 < t1, piece);
    // lambda of a piece of a point's straight motion is its length; eta0 + eta1 its ends' clearances.
    assert.ok(Math.abs(Number(lambda) - (t1 - t0) * len) < 2e-3 * Math.max(1, len), `λ of ${piece}: ${lambda}`);
    assert.ok(Math.abs(Number(sum) - (eta(t0) + eta(t1))) < 2e-3, `η₀+η₁ of ${piece}: ${sum}`);
    assert.doesNotMatch(sum, /\+/, 'a sum, as one number');
    // "<": proven free, and so no midpoint tested; "≥": split at its midpoint.
    if (cmp === '<') {
      ++certified;
      assert.ok(Number(lambda) < Number(sum), r.join(' | '));
      assert.equal(n, '', r.join(' | '));
    } else {
      assert.equal(cmp, '≥', r.join(' | '));
      assert.ok(Math.abs(Number(t) - (t0 + t1) / 2) < 1e-3, `the midpoint of ${piece}: ${t}`);
    }
  }
  assert.equal(evaluations, s.bisection.trace.length);
  assert.equal(certified, s.bisection.pieces.filter((x) => !x.unresolved).length);

  // The zoom row: four times the last piece's width around it, the midpoints inside it as dots.
  const last = s.bisection.pieces.at(-1);
  const width = last.t1 - last.t0, mid = (last.t0 + last.t1) / 2;
  const lo = Math.max(0, Math.min(mid - 2 * width, 1 - 4 * width)), hi = Math.min(1, lo + 4 * width);
  const strip = (await api(page, 'page_state')).buttons['collision-strip'];
  const [x0, x1, row3] = [strip[0] + 60, strip[2] - 30, strip[1] + 112];
  const zx = (t) => x0 + (t - lo) / (hi - lo) * (x1 - x0);
  const inside = s.bisection.trace.filter((e) => e.t > lo + 0.02 * (hi - lo) && e.t < hi - 0.02 * (hi - lo));
  assert.ok(inside.length >= 2, `${inside.length} midpoints in the zoomed window [${lo}, ${hi}]`);
  await page.mouse.move(5, 5);
  await waitFrames(page, 3);
  const { png } = await screenshot(page, 'collision-deep-bisection.png');
  const { at } = await inspectPng(browser, png, inside.map((e) => [zx(e.t), row3]));
  for (const [i, [r, g, b]] of at.entries())
    assert.ok(g > r + 60 && g > b, `the dot of t = ${inside[i].t} at x = ${zx(inside[i].t).toFixed(1)}: ${[r, g, b]}`);
}));
