// cspacelab check and distance: the homework's P10-P12 numbers and every kind of bad input.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { CLI, json, fails, scene, tempScene } from './lib/cli.mjs';

const P12 = scene('p12.json');

test('P12 bisection: the trace of midpoints ends at the one in collision', () => {
  const r = json('check', P12, '--from', '0,0', '--to', '1,0', '--checker', 'bisection', '--trace');
  assert.equal(r.collision, true);
  assert.equal(r.evaluations, 4);
  assert.equal(r.collision_t, 0.25);
  assert.deepEqual(r.trace.map((s) => s.t), [0, 1, 0.5, 0.25]);
  assert.deepEqual(r.trace.map((s) => s.lambda), [0, 0, 1, 0.5]);
  assert.deepEqual(r.trace[3].q, [0.25, 0]);
  assert.ok(Math.abs(r.trace[0].eta - (Math.hypot(0.2, 0.05) - 0.1)) < 1e-15);
  assert.ok(r.trace[3].eta < 0 && r.trace[3].free === false);
  for (const s of r.trace) for (const k of ['t', 'q', 'eta', 't0', 't1', 'lambda']) assert.ok(k in s, k);
});

test('P12 grid: N = 4 misses the disk, N = 5 finds it, and --min-grid says 5', () => {
  assert.equal(json('check', P12, '--checker', 'grid:4').collision, false);
  const five = json('check', P12, '--checker', 'grid:5', '--trace');
  assert.equal(five.collision, true);
  assert.equal(five.collision_t, 0.25);
  assert.deepEqual(five.trace.map((s) => s.t), [0, 0.25]);
  const min = json('check', P12, '--min-grid');
  assert.deepEqual([min.min_grid, min.max], [5, 1000]);
  assert.ok(min.evaluations >= 4 + 2 && min.evaluations < 20, `${min.evaluations} configurations`);
  const none = json('check', P12, '--min-grid', '--max', '4');
  assert.deepEqual([none.min_grid, none.max], [null, 4]);
});

test('a free edge: no collision, null collision_t, certified pieces', () => {
  const r = json('check', P12, '--from', '0,0.3', '--to', '1,0.3', '--trace');
  assert.equal(r.collision, false);
  assert.equal(r.collision_t, null);
  const covered = r.pieces.reduce((sum, p) => sum + (p.t1 - p.t0), 0);
  assert.ok(Math.abs(covered - 1) < 1e-12);
  for (const p of r.pieces) assert.ok(p.lambda < p.eta0 + p.eta1);  // strictly: obstacles are closed
});

test('the arm: angles wrap, the edge takes the short way round', () => {
  const arm = tempScene({ version: 1, robot: { type: 'arm2', base: [0.5, 0.5], lengths: [0.3, 0.2] },
                          obstacles: [{ type: 'disk', center: [0.1, 0.5], radius: 0.05 }] });
  // From 3 to -3 rad the short way crosses pi, where link 1 points at the disk (x = 0.2..0.5).
  const r = json('check', arm, '--from', '3,0', '--to', '-3,0');
  assert.equal(r.collision, true);
  assert.deepEqual(r.to, [-3, 0]);
  // The long way round is not what an edge means: 3 -> 0 -> -3 stays clear on the right.
  assert.equal(json('check', arm, '--from', '1,0', '--to', '-1,0').collision, false);
});

test('distance s1 and segment-disk (P10, P11)', () => {
  const s1 = json('distance', 's1', '-3', '3');
  assert.ok(Math.abs(s1.distance - (2 * Math.PI - 6)) < 1e-15);
  assert.ok(Math.abs(s1.rotation - s1.modulus) < 1e-14);
  // Huge angles mean little, but the answer stays a distance on S^1, in [0, pi].
  for (const [a, b] of [['1e18', '0'], ['1e308', '-1e308'], ['-1e300', '3']]) {
    const h = json('distance', 's1', a, b);
    for (const v of [h.distance, h.modulus, h.rotation]) assert.ok(v >= 0 && v <= Math.PI, `${a} ${b}: ${v}`);
    assert.ok(h.signed_turn >= -Math.PI && h.signed_turn < Math.PI);
  }
  fails(/--p2: coordinates must be within \+-1e6/, 'distance', 'segment-disk', '--p1', '0,0', '--p2', '1e308,0', '--center', '0,1', '--radius', '1');
  fails(/--radius: must be in \[0, 1e6\]/, 'distance', 'segment-disk', '--p1', '0,0', '--p2', '1,0', '--center', '0,1', '--radius', '1e7');
  // Numbers are plain decimals; one too small for a normal double is still a number.
  fails(/--p1: '0x1p-2' is not a finite number/, 'distance', 'segment-disk', '--p1', '0x1p-2,0', '--p2', '1,0', '--center', '0,1', '--radius', '1');
  fails(/--radius: ' 1' is not a finite number/, 'distance', 'segment-disk', '--p1', '0,0', '--p2', '1,0', '--center', '0,1', '--radius', ' 1');
  // In a list, spaces around the items are fine.
  assert.equal(json('distance', 'segment-disk', '--p1', ' 0, 0 ', '--p2', '1,\t0', '--center', '0, 1', '--radius', '0.5').distance, 0.5);
  fails(/--radius: '1e999' is not a finite number/, 'distance', 'segment-disk', '--p1', '0,0', '--p2', '1,0', '--center', '0,1', '--radius', '1e999');
  assert.equal(json('distance', 'segment-disk', '--p1', '0,0', '--p2', '1,0', '--center', '0,1', '--radius', '1e-310').distance, 1 - 1e-310);
  const sd = json('distance', 'segment-disk', '--p1', '0,0', '--p2', '1,0', '--center', '0.2,0.05', '--radius', '0.1');
  assert.equal(sd.distance, 0);
  assert.ok(Math.abs(sd.signed + 0.05) < 1e-15);
  assert.deepEqual(sd.closest_point, [0.2, 0]);
  const far = json('distance', 'segment-disk', '--p1', '0,0', '--p2', '1,0', '--center', '1.3,0.4', '--radius', '0.1');
  assert.ok(Math.abs(far.distance - 0.4) < 1e-15);  // beyond the end: distance to p2 minus r
  assert.equal(json('distance', 'segment-disk', '--p1', '0,0', '--p2', '0,0', '--center', '0,1', '--radius', '0').distance, 1);
});

test('bad input: one line naming the problem, exit status 2', () => {
  fails(/nope\.json: cannot read file/, 'check', 'nope.json');
  fails(/not valid JSON/, 'check', tempScene('{"version": 1,'));
  fails(/obstacles\[0\]\.radius: must be >= 0/, 'check',
        tempScene({ version: 1, obstacles: [{ type: 'disk', center: [0, 0], radius: -1 }] }));
  fails(/obstacles\[0\]\.vertices: a polygon needs at least 3 vertices/, 'check',
        tempScene({ version: 1, obstacles: [{ type: 'polygon', vertices: [[0, 0], [1, 1]] }] }));
  fails(/--from: expected 2 comma-separated numbers for robot type 'point', got 3/, 'check', P12, '--from', '0,0,0');
  fails(/--to: 'nan' is not a finite number/, 'check', P12, '--to', 'nan,0');
  fails(/--from: .* lies outside the workspace/, 'check', P12, '--from', '5,5');
  fails(/--checker: unknown checker 'exact'/, 'check', P12, '--checker', 'exact');
  fails(/--checker: .*N must be an integer/, 'check', P12, '--checker', 'grid:1');
  fails(/unknown option --frobnicate/, 'check', P12, '--frobnicate');
  fails(/--radius: must be in \[0, 1e6\]/, 'distance', 'segment-disk', '--p1', '0,0', '--p2', '1,0', '--center', '0,0', '--radius', '-1');
  fails(/unknown distance kind 'l2'/, 'distance', 'l2');
  fails(/missing --center/, 'distance', 'segment-disk', '--p1', '0,0', '--p2', '1,0', '--radius', '1');
});

test('an edge along a wall at a hair\'s clearance ends, as a collision, at the bisection budget', () => {
  // Found while bounding the CLI fuzzer's inputs: this ran on past 20 s and 1.4 GB (about 2^40
  // midpoints, breadth first). A time limit makes a regression fail instead of hanging the run.
  const args = ['check', scene('wall-gap.json'), '--from', '0.500001,0.05', '--to', '0.500001,0.4'];
  const r = spawnSync(CLI, args, { encoding: 'utf8', timeout: 60000 });
  assert.equal(r.status, 0, `cspacelab ${args.join(' ')}: ${r.error || r.stderr}`);
  const out = JSON.parse(r.stdout);
  assert.equal(out.collision, true);
  assert.equal(out.evaluations, 2 ** 20);
});
