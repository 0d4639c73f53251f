// cspacelab cspace: the PGM it writes (header, size, pixel layout), known blocked and free
// configurations, the free fraction against the pixels, and one-line errors for bad input.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { json, fails, scene, tempScene } from './lib/cli.mjs';

const outFile = (name) => path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'csl-pgm-')), name);

/** Parses a binary PGM (P5, maxval 255): { width, height, pixels }. */
function readPgm(file) {
  const data = fs.readFileSync(file);
  const header = /^P5\n(\d+) (\d+)\n255\n/.exec(data.subarray(0, 64).toString('latin1'));
  assert.ok(header, 'a P5 header with maxval 255');
  const width = Number(header[1]), height = Number(header[2]);
  const pixels = data.subarray(header[0].length);
  assert.equal(pixels.length, width * height);
  return { width, height, pixels };
}

const angle = (index, r) => -Math.PI + ((index + 0.5) * 2 * Math.PI) / r;

// Base (0.5, 0.5), links 0.3 and 0.2; a disk on link 1's path at theta1 = 0, another that only
// link 2 reaches.
const ARM = { version: 1, robot: { type: 'arm2', base: [0.5, 0.5], lengths: [0.3, 0.2] },
              obstacles: [{ type: 'disk', center: [0.8, 0.5], radius: 0.05 },
                          { type: 'disk', center: [0.5, 0.95], radius: 0.06 }] };

// Squared distance from p to segment ab.
function segDist2([px, py], [ax, ay], [bx, by]) {
  const dx = bx - ax, dy = by - ay;
  const t = Math.max(0, Math.min(1, ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy)));
  const x = ax + t * dx - px, y = ay + t * dy - py;
  return x * x + y * y;
}

function armBlocked(t1, t2) {
  const [bx, by] = ARM.robot.base, [l1, l2] = ARM.robot.lengths;
  const e = [bx + l1 * Math.cos(t1), by + l1 * Math.sin(t1)];
  const tip = [e[0] + l2 * Math.cos(t1 + t2), e[1] + l2 * Math.sin(t1 + t2)];
  return ARM.obstacles.some(({ center, radius }) =>
    Math.min(segDist2(center, [bx, by], e), segDist2(center, e, tip)) <= radius * radius);
}

test('writes an R x R P5 image: 255 free, 0 blocked, columns theta1, rows theta2', () => {
  const file = outFile('arm.pgm');
  const r = 64;
  const out = json('cspace', tempScene(ARM), '--resolution', String(r), '--out', file);
  assert.deepEqual(Object.keys(out), ['free_fraction', 'seconds']);
  assert.ok(out.seconds >= 0 && out.seconds < 10);
  const { width, height, pixels } = readPgm(file);
  assert.equal(width, r);
  assert.equal(height, r);
  const at = (i, j) => pixels[j * r + i];
  // Column 32 is theta1 = pi/64: link 1 ends at (0.7996, 0.5147), inside the first disk:
  // the whole column is blocked.
  for (let j = 0; j < r; ++j) assert.equal(at(32, j), 0);
  // Column 0, theta1 ~ -pi: the arm points left, away from both disks, whatever theta2.
  for (let j = 0; j < r; ++j) assert.equal(at(0, j), 255);
  // Column 48, theta1 ~ pi/2 + pi/64: link 1 points up to (0.49, 0.80); link 2 hits the upper
  // disk when it points up too (theta2 = 0, row 32) and not when it points down (row 0).
  assert.equal(at(48, 32), 0);
  assert.equal(at(48, 31), 0);
  assert.equal(at(48, 0), 255);
  // Every pixel agrees with a direct test of the arm against the disks (the map is exact;
  // boundaries may differ by rounding, there are none so close here).
  let differ = 0;
  for (let i = 0; i < r; ++i)
    for (let j = 0; j < r; ++j) differ += (at(i, j) === 0) !== armBlocked(angle(i, r), angle(j, r));
  assert.ok(differ <= (r * r) / 1000, `${differ} pixels differ`);
  // The free fraction is the fraction of 255 pixels, exactly.
  const free = pixels.reduce((n, p) => n + (p === 255), 0);
  assert.equal(pixels.every((p) => p === 0 || p === 255), true);
  assert.equal(out.free_fraction, free / (r * r));
  assert.ok(out.free_fraction > 0.5 && out.free_fraction < 0.99);
});

test('the lab scene at the default resolution, and resolution 1', () => {
  const file = outFile('lab.pgm');
  const out = json('cspace', scene('arm-2link.json'), '--out', file);
  const { width, pixels } = readPgm(file);
  assert.equal(width, 512);
  assert.equal(out.free_fraction, pixels.reduce((n, p) => n + (p === 255), 0) / (512 * 512));
  const one = json('cspace', scene('arm-2link.json'), '--resolution', '1', '--out', file);
  const img = readPgm(file);
  assert.equal(img.width, 1);
  assert.equal(one.free_fraction, img.pixels[0] === 255 ? 1 : 0);
});

test('bad input: one line naming the problem, exit status 2', () => {
  const arm = tempScene(ARM);
  const file = outFile('x.pgm');
  fails(/needs an arm2 robot, a 3-link arm or a polygon robot, the scene's robot is 'point'/, 'cspace', scene('p12.json'), '--out', file);
  fails(/--resolution: '0' is not an integer in \[1, 8192\]/, 'cspace', arm, '--resolution', '0', '--out', file);
  fails(/--resolution: '8193' is not an integer in \[1, 8192\]/, 'cspace', arm, '--resolution', '8193', '--out', file);
  fails(/--resolution: 'many' is not an integer/, 'cspace', arm, '--resolution', 'many', '--out', file);
  fails(/missing --out/, 'cspace', arm);
  fails(/no-such-dir\/x\.pgm: cannot write file/, 'cspace', arm, '--out', path.join(os.tmpdir(), 'no-such-dir', 'x.pgm'));
  fails(/cannot write file/, 'cspace', arm, '--out', os.tmpdir());  // a directory
  fails(/nope\.json: cannot read file/, 'cspace', 'nope.json', '--out', file);
  fails(/unknown option --frobnicate/, 'cspace', arm, '--out', file, '--frobnicate');
  assert.equal(fs.existsSync(file), false);
});
