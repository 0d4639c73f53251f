// cspacelab cspace for 3-D C-spaces: the polygon robot's SE(2) and the 3-link arm's T^3 as a
// raw volume with a JSON header (layout, axes, cell centres, 255 free / 0 blocked), checked
// cell by cell against collision tests written here independently; --slice as exact JSON;
// one-line errors for bad input.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { json, fails, scene, tempScene } from './lib/cli.mjs';

const outFile = (name) => path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'csl-vol-')), name);
const angle = (index, n) => -Math.PI + ((index + 0.5) * 2 * Math.PI) / n;
const centre = (lo, hi, index, n) => lo + ((index + 0.5) * (hi - lo)) / n;

function segDist2([px, py], [ax, ay], [bx, by]) {
  const dx = bx - ax, dy = by - ay;
  const t = Math.max(0, Math.min(1, ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy)));
  const x = ax + t * dx - px, y = ay + t * dy - py;
  return x * x + y * y;
}

// A bar robot [0, 0.12] x [-0.03, 0.03], its reference point at one end (so that a body turned
// or not reflected would show), one disk and one wall, in a workspace that is not the unit
// square.
const SQUARE = { version: 1, workspace: { min: [0, 0], max: [1.2, 1] },
                 robot: { type: 'polygon', vertices: [[0, -0.03], [0.12, -0.03], [0.12, 0.03], [0, 0.03]] },
                 obstacles: [{ type: 'disk', center: [0.5, 0.5], radius: 0.1 },
                             { type: 'segment', a: [0.9, 0.2], b: [0.9, 0.8] }],
                 start: [0.1, 0.1, 0], goal: [1.1, 0.9, 0] };

// The bar at (x, y, theta) against the disk (the disk's centre in the robot's frame, its
// distance to the axis-aligned bar) and the wall (crossing the bar's edges, an end inside the
// bar, or within 1e-6 of it).
const BAR = { x0: 0, x1: 0.12, y0: -0.03, y1: 0.03 };
const barDistance = ([px, py]) =>
  Math.hypot(Math.max(BAR.x0 - px, px - BAR.x1, 0), Math.max(BAR.y0 - py, py - BAR.y1, 0));
function squareBlocked(x, y, t) {
  const c = Math.cos(t), s = Math.sin(t);
  const toRobot = ([px, py]) => [c * (px - x) + s * (py - y), -s * (px - x) + c * (py - y)];
  if (barDistance(toRobot([0.5, 0.5])) <= 0.1) return true;
  const a = toRobot([0.9, 0.2]), b = toRobot([0.9, 0.8]);
  if (barDistance(a) === 0 || barDistance(b) === 0) return true;
  const corners = [[BAR.x0, BAR.y0], [BAR.x1, BAR.y0], [BAR.x1, BAR.y1], [BAR.x0, BAR.y1]];
  // The wall crossing an edge (proper crossings: touching is within 1e-6 below).
  const side = (p, q, o) => Math.sign((q[0] - p[0]) * (o[1] - p[1]) - (q[1] - p[1]) * (o[0] - p[0]));
  for (let k = 0; k < 4; ++k) {
    const p = corners[k], q = corners[(k + 1) % 4];
    if (side(p, q, a) * side(p, q, b) < 0 && side(a, b, p) * side(a, b, q) < 0) return true;
  }
  let d2 = Infinity;
  for (const p of corners) d2 = Math.min(d2, segDist2(p, a, b));
  for (let k = 0; k < 4; ++k) for (const p of [a, b]) d2 = Math.min(d2, segDist2(p, corners[k], corners[(k + 1) % 4]));
  return Math.sqrt(d2) <= 1e-6;
}

// Base (0.5, 0.5), links 0.2, 0.15, 0.1; a disk at link 1's end when theta1 = 0 (link 1 meets it
// for |theta1| <= asin(0.045 / 0.2) = 0.227), another above.
const ARM3 = { version: 1, robot: { type: 'arm', base: [0.5, 0.5], lengths: [0.2, 0.15, 0.1] },
               obstacles: [{ type: 'disk', center: [0.7, 0.5], radius: 0.045 },
                           { type: 'disk', center: [0.5, 0.9], radius: 0.06 }],
               start: [Math.PI / 2 + 0.3, 0, 0], goal: [-Math.PI / 2, 0, 0] };

function armBlocked(t1, t2, t3) {
  const [l1, l2, l3] = ARM3.robot.lengths;
  const j0 = ARM3.robot.base;
  const j1 = [j0[0] + l1 * Math.cos(t1), j0[1] + l1 * Math.sin(t1)];
  const j2 = [j1[0] + l2 * Math.cos(t1 + t2), j1[1] + l2 * Math.sin(t1 + t2)];
  const j3 = [j2[0] + l3 * Math.cos(t1 + t2 + t3), j2[1] + l3 * Math.sin(t1 + t2 + t3)];
  return ARM3.obstacles.some(({ center, radius }) =>
    Math.min(segDist2(center, j0, j1), segDist2(center, j1, j2), segDist2(center, j2, j3)) <= radius * radius);
}

function readVolume(out, file) {
  const header = JSON.parse(fs.readFileSync(file + '.json', 'utf8'));
  const bytes = fs.readFileSync(file);
  assert.equal(out.header, file + '.json');
  for (const key of ['format', 'version', 'robot', 'data', 'dims', 'axes', 'free', 'blocked', 'free_fraction'])
    assert.deepEqual(out[key], header[key], key);
  assert.equal(header.format, 'cspacelab-volume');
  assert.equal(header.version, 1);
  assert.equal(header.data, path.basename(file));
  assert.equal(bytes.length, header.dims[0] * header.dims[1] * header.dims[2]);
  assert.ok(bytes.every((b) => b === 0 || b === 255));
  assert.equal(header.free_fraction, bytes.reduce((n, b) => n + (b === 255), 0) / bytes.length);
  return { header, bytes };
}

test('polygon robot: an R x R x K SE(2) volume, x fastest, theta slowest, against direct tests', () => {
  const file = outFile('se2.raw');
  const r = 40, k = 12;
  const out = json('cspace', tempScene(SQUARE), '--resolution', String(r), '--slices', String(k), '--out', file);
  const { header, bytes } = readVolume(out, file);
  assert.equal(header.robot, 'polygon');
  assert.deepEqual(header.dims, [r, r, k]);
  assert.deepEqual(header.axes.map((a) => [a.name, a.min, a.max, a.cells, a.periodic]),
                   [['x', 0, 1.2, r, false], ['y', 0, 1, r, false], ['theta', -Math.PI, Math.PI, k, true]]);
  let differ = 0;
  for (let kk = 0; kk < k; ++kk)
    for (let j = 0; j < r; ++j)
      for (let i = 0; i < r; ++i) {
        const blocked = squareBlocked(centre(0, 1.2, i, r), centre(0, 1, j, r), angle(kk, k));
        differ += (bytes[(kk * r + j) * r + i] === 0) !== blocked;
      }
  assert.ok(differ <= bytes.length / 1000, `${differ} cells differ`);
  // The disk at the workspace's centre blocks the cell there in every slice; a corner is free.
  const i = Math.floor((0.5 / 1.2) * r), j = r / 2;
  for (let kk = 0; kk < k; ++kk) {
    assert.equal(bytes[(kk * r + j) * r + i], 0);
    assert.equal(bytes[kk * r * r], 255);
  }
  assert.ok(out.free_fraction > 0.5 && out.free_fraction < 0.95);
  assert.ok(out.seconds >= 0 && out.seconds < 10);
});

test('3-link arm: a T^3 volume (theta2 fastest, then theta3, theta1 slowest) against direct tests', () => {
  const file = outFile('t3.raw');
  const r = 24, k = 16;
  const out = json('cspace', tempScene(ARM3), '--resolution', String(r), '--slices', String(k), '--out', file);
  const { header, bytes } = readVolume(out, file);
  assert.equal(header.robot, 'arm');
  assert.deepEqual(header.dims, [r, r, k]);
  assert.deepEqual(header.axes.map((a) => a.name), ['theta2', 'theta3', 'theta1']);
  assert.ok(header.axes.every((a) => a.periodic && a.min === -Math.PI && a.max === Math.PI));
  let differ = 0;
  for (let kk = 0; kk < k; ++kk)
    for (let j = 0; j < r; ++j)
      for (let i = 0; i < r; ++i)
        differ += (bytes[(kk * r + j) * r + i] === 0) !== armBlocked(angle(kk, k), angle(i, r), angle(j, r));
  assert.ok(differ <= bytes.length / 1000, `${differ} cells differ`);
  // theta1 = -+pi/16 (slices 7 and 8 of 16): link 1 passes 0.039 from the first disk's centre:
  // all blocked; slice 9 (3pi/16 = 0.589) is not.
  assert.ok(bytes.subarray(7 * r * r, 9 * r * r).every((b) => b === 0));
  assert.ok(bytes.subarray(9 * r * r, 10 * r * r).some((b) => b === 255));
  assert.ok(out.free_fraction > 0.5 && out.free_fraction < 0.99);
  // The default is the cube R^3.
  const cube = json('cspace', tempScene(ARM3), '--resolution', '8', '--out', file);
  assert.deepEqual(cube.dims, [8, 8, 8]);
});

test('--slice theta=V: the exact pieces of the polygon robot as JSON', () => {
  const out = json('cspace', tempScene(SQUARE), '--slice', 'theta=0');
  assert.equal(out.robot, 'polygon');
  assert.equal(out.theta, 0);
  assert.deepEqual(out.bounds, { min: [0, 0], max: [1.2, 1] });
  assert.equal(out.pieces.length, 2);
  // The body reflected through its reference point is [-0.12, 0] x [-0.03, 0.03]. The disk:
  // [0.38, 0.5] x [0.47, 0.53] grown by 0.1, its outline 0.1 from that rectangle.
  const box = (hull) => {
    const xs = hull.map((p) => p[0]), ys = hull.map((p) => p[1]);
    return [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
  };
  const near = (a, b) => a.every((v, i) => Math.abs(v - b[i]) < 1e-12);
  const disk = out.pieces[0];
  assert.equal(disk.obstacle, 0);
  assert.equal(disk.radius, 0.1);
  assert.equal(disk.hull.length, 4);
  assert.ok(near(box(disk.hull), [0.38, 0.5, 0.47, 0.53]), JSON.stringify(disk.hull));
  for (const [x, y] of disk.outline) {
    const d = Math.hypot(Math.max(0.38 - x, x - 0.5, 0), Math.max(0.47 - y, y - 0.53, 0));
    assert.ok(Math.abs(d - 0.1) < 1e-9, `outline point ${x}, ${y} is ${d} from the rectangle`);
  }
  // The wall: [0.78, 0.9] x [0.17, 0.83] within 1e-6.
  const wall = out.pieces[1];
  assert.equal(wall.obstacle, 1);
  assert.equal(wall.radius, 1e-6);
  assert.ok(near(box(wall.hull), [0.78, 0.9, 0.17, 0.83]), JSON.stringify(wall.hull));
  // A quarter turn: the body is [-0.03, 0.03] x [0, 0.12], reflected [-0.03, 0.03] x [-0.12, 0].
  const turned = json('cspace', tempScene(SQUARE), '--slice', `theta=${Math.PI / 2}`);
  assert.ok(Math.abs(turned.theta - Math.PI / 2) < 1e-15);
  assert.ok(near(box(turned.pieces[0].hull), [0.47, 0.53, 0.38, 0.5]), JSON.stringify(turned.pieces[0].hull));
});

test('--slice theta1=V: link 1 blocked, or exact theta3 intervals per theta2 column', () => {
  const blocked = json('cspace', tempScene(ARM3), '--slice', 'theta1=0', '--resolution', '8');
  assert.equal(blocked.link1_blocked, true);
  assert.equal(blocked.columns.length, 8);
  for (const c of blocked.columns) assert.deepEqual(c.blocked_theta3, [[-Math.PI, Math.PI]]);
  const t1 = Math.PI / 2 + 0.2;
  const out = json('cspace', tempScene(ARM3), '--slice', `theta1=${t1}`, '--resolution', '32');
  assert.equal(out.link1_blocked, false);
  let someBlocked = 0, checked = 0;
  for (const { theta2, blocked_theta3 } of out.columns) {
    for (const [lo, hi] of blocked_theta3) assert.ok(-Math.PI <= lo && lo <= hi && hi <= Math.PI);
    someBlocked += blocked_theta3.length > 0;
    for (let s = 0; s < 64; ++s) {
      const t3 = angle(s, 64);
      if (blocked_theta3.some(([lo, hi]) => Math.abs(t3 - lo) < 1e-6 || Math.abs(t3 - hi) < 1e-6)) continue;
      ++checked;
      assert.equal(blocked_theta3.some(([lo, hi]) => lo <= t3 && t3 <= hi), armBlocked(t1, theta2, t3),
                   `theta2 ${theta2}, theta3 ${t3}`);
    }
  }
  assert.ok(someBlocked > 0 && checked > 1000);
});

test('bad input: one line naming the problem and its limit, exit status 2', () => {
  const se2 = tempScene(SQUARE), arm3 = tempScene(ARM3);
  const arm2 = scene('arm-2link.json');
  const file = outFile('x.raw');
  const arm4 = tempScene({ ...ARM3, robot: { ...ARM3.robot, lengths: [0.1, 0.1, 0.1, 0.1] }, start: [0, 0, 0, 0], goal: [1, 0, 0, 0] });
  fails(/the scene's robot is 'arm' with 4 links/, 'cspace', arm4, '--out', file);
  fails(/needs an arm2 robot, a 3-link arm or a polygon robot, the scene's robot is 'point'/, 'cspace', scene('p12.json'), '--slice', 'theta=0');
  fails(/--resolution: '1025' is not an integer in \[1, 1024\]/, 'cspace', se2, '--resolution', '1025', '--out', file);
  fails(/--slices: '0' is not an integer in \[1, 1024\]/, 'cspace', arm3, '--slices', '0', '--out', file);
  fails(/--slices: 'NaN' is not an integer/, 'cspace', se2, '--slices', 'NaN', '--out', file);
  fails(/268435456 cells, more than the limit of 134217728/, 'cspace', se2, '--resolution', '1024', '--slices', '256', '--out', file);
  fails(/--slice theta: 'nan' is not a finite number/, 'cspace', se2, '--slice', 'theta=nan');
  fails(/--slice theta1: 'inf' is not a finite number/, 'cspace', arm3, '--slice', 'theta1=inf');
  fails(/--slice: expected theta=VALUE for the scene's polygon robot, got 'theta1=1'/, 'cspace', se2, '--slice', 'theta1=1');
  fails(/--slice: expected theta1=VALUE for the scene's 3-link arm, got 'x'/, 'cspace', arm3, '--slice', 'x');
  fails(/give --out or --slice, not both/, 'cspace', se2, '--slice', 'theta=0', '--out', file);
  fails(/missing --out FILE/, 'cspace', arm3);
  fails(/--slices: the arm2 map is 2-D/, 'cspace', arm2, '--slices', '4', '--out', file);
  fails(/--slice: the arm2 map is 2-D/, 'cspace', arm2, '--slice', 'theta1=0');
  fails(/cannot write file/, 'cspace', se2, '--out', os.tmpdir());
  assert.equal(fs.existsSync(file), false);
});

test('the work of a volume is priced first: many concave obstacles at a large size are refused', () => {
  // 300 eight-pointed stars (concave: several convex pieces each) and an L-shaped robot (two).
  const stars = [];
  for (let k = 0; k < 300; ++k) {
    const cx = ((k * 37) % 100) / 100 + 0.005, cy = ((k * 61) % 97) / 97 + 0.005;
    stars.push({ type: 'polygon', vertices: Array.from({ length: 8 }, (_, v) => {
      const t = (v * Math.PI) / 4, r = v % 2 ? 0.004 : 0.008;
      return [cx + r * Math.cos(t), cy + r * Math.sin(t)];
    }) });
  }
  const file = outFile('big.raw');
  const L = [[-0.05, -0.05], [0.1, -0.05], [0.1, 0], [0, 0], [0, 0.08], [-0.05, 0.08]];
  const se2 = tempScene({ ...SQUARE, robot: { type: 'polygon', vertices: L }, obstacles: stars });
  fails(/the volume's work is 4 x [0-9.e+]+ vertex sums \+ \d+ C-obstacle pieces x 512 rows a slice x 512 slices = [0-9.e+]+, more than the limit of 4e\+08/,
        'cspace', se2, '--resolution', '512', '--slices', '512', '--out', file);
  const arm = tempScene({ ...ARM3, obstacles: stars });
  fails(/the volume's work is 2400 obstacle edges x 256\^2 columns x 256 slices = [0-9.e+]+, more than the limit of 4e\+08/,
        'cspace', arm, '--resolution', '256', '--out', file);
  assert.equal(fs.existsSync(file), false);
  // A size within the limit runs.
  const ok = json('cspace', se2, '--resolution', '32', '--slices', '8', '--out', file);
  assert.deepEqual(ok.dims, [32, 32, 8]);
});

const ngon = (cx, cy, r, n, inner = r) => Array.from({ length: n }, (_, v) => {
  const t = (2 * Math.PI * v) / n, rr = v % 2 ? inner : r;
  return [cx + rr * Math.cos(t), cy + rr * Math.sin(t)];
});

test('the work is priced by vertex sums too: one convex piece against another can be the whole cost', () => {
  // A convex 32-gon robot among 1000 convex 256-gons: only 1000 pieces a slice, but each is
  // the hull of 32 x 256 vertex sums (8.2e6 a slice, about 37 s natively at the default size, by the 3.7 s measured with 100).
  const obstacles = Array.from({ length: 1000 }, (_, k) =>
    ({ type: 'polygon', vertices: ngon(0.02 + 0.032 * (k % 30), 0.02 + 0.032 * (Math.floor(k / 30) % 30), 0.01, 256) }));
  const scene = tempScene({ ...SQUARE, robot: { type: 'polygon', vertices: ngon(0, 0, 0.03, 32) }, obstacles });
  const file = outFile('convex.raw');
  fails(/the volume's work is 4 x 8\.192e\+06 vertex sums \+ 1000 C-obstacle pieces x 128 rows a slice x 64 slices = 2\.105e\+09, more than the limit of 4e\+08/,
        'cspace', scene, '--out', file);
  assert.equal(fs.existsSync(file), false);
  // One slice of it is within the limit: 4 x 8.2e6 + 1000 x 64.
  const slice = json('cspace', scene, '--slice', 'theta=0');
  assert.equal(slice.pieces.length, 1000);
});

test('one --slice is priced before it runs: a concave robot among 1000 concave 256-gons is refused', () => {
  // The robot's convex pieces x each star's x 1000 stars = 4.6e6 pieces, each an outline of
  // 64 units: 4.9e8 with the sums, where the output alone would be gigabytes.
  const obstacles = Array.from({ length: 1000 }, (_, k) =>
    ({ type: 'polygon', vertices: ngon(0.02 + 0.032 * (k % 30), 0.02 + 0.032 * (Math.floor(k / 30) % 30), 0.01, 256, 0.006) }));
  const scene = tempScene({ ...SQUARE, robot: { type: 'polygon', vertices: ngon(0, 0, 0.03, 32, 0.02) }, obstacles });
  fails(/the slice's work is 4 x [0-9.e+]+ vertex sums \+ 4\.572e\+06 C-obstacle pieces x 64 a slice = [0-9.e+]+, more than the limit of 4e\+08: lower --resolution or simplify the scene/,
        'cspace', scene, '--slice', 'theta=0.5');
});
