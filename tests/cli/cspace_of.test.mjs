// cspace-of: the homework's answers (P1, P6, P7), --check, and one-line errors for bad descriptions.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';

const CLI = process.env.CSPACELAB_CLI;
const run = (...args) => spawnSync(CLI, args, { encoding: 'utf8' });
const ok = (...args) => {
  const r = run(...args);
  assert.equal(r.status, 0, r.stderr);
  assert.equal(r.stderr, '');
  return JSON.parse(r.stdout);
};

test('P1: a mobile robot that translates and rotates in the plane is SE(2)', () => {
  const q = ok('cspace-of', 'base=planar');
  assert.equal(q.notation, 'SE(2)');
  assert.equal(q.dimension, 3);
  assert.deepEqual(q.factors.map((f) => [f.factor, f.dimension]), [['SE(2)', 3]]);
  assert.match(q.factors[0].reason, /turns/);
  assert.ok(q.equivalent.includes('R^2 x S^1'));
  assert.equal(q.check, undefined);
});

test('P6: a six-link arm with a spherical wrist is T^6', () => {
  const q = ok('cspace-of', 'joints=RRR wrist=spherical');
  assert.equal(q.notation, 'T^6');
  assert.equal(q.dimension, 6);
  assert.deepEqual(Object.keys(q), ['notation', 'dimension', 'factors', 'equivalent']);
  assert.deepEqual(Object.keys(q.factors[0]), ['factor', 'dimension', 'reason']);
});

test('P7: the same arm on a planar mobile base is SE(2) x T^6', () => {
  const q = ok('cspace-of', 'base=planar, joints=RRR, wrist=spherical');
  assert.equal(q.notation, 'SE(2) x T^6');
  assert.equal(q.dimension, 9);
  assert.deepEqual(q.factors.map((f) => f.factor), ['SE(2)', 'T^6']);
  assert.ok(q.equivalent.includes('R^2 x S^1 x T^6'));
  assert.ok(q.equivalent.includes('R^2 x T^7'));
});

test('--check confirms right answers and explains wrong ones', () => {
  const p7 = 'base=planar joints=RRR wrist=spherical';
  let q = ok('cspace-of', p7, '--check', 'Q = R² × S¹ × T⁶');
  assert.equal(q.check.correct, true);
  assert.match(q.check.explanation, /^correct: SE\(2\) x T\^6 = /);

  q = ok('cspace-of', '--check=R^2 x T^6', p7);
  assert.equal(q.check.correct, false);
  assert.match(q.check.explanation, /one circle factor is missing: expected 7 circle factors/);

  q = ok('cspace-of', 'joints=RR', '--check', 'S^2');
  assert.equal(q.check.correct, false);
  assert.match(q.check.explanation, /S\^2 is the sphere: S\^1 x S\^1 is the torus T\^2/);

  q = ok('cspace-of', 'joints=RRR wrist=spherical', '--check', 'T^3 x SO(3)');
  assert.equal(q.check.correct, false);
  assert.match(q.check.explanation, /SO\(3\) is not T\^3/);

  // An unreadable answer is a verdict, not an error.
  q = ok('cspace-of', p7, '--check', 'SE(2) + T^6');
  assert.equal(q.check.correct, false);
  assert.match(q.check.explanation, /^could not read the answer: expected a product sign/);
});

test('bad descriptions and usage are one-line errors with exit status 2', () => {
  const cases = [
    [['cspace-of', 'joints=RRX'], /joints: 'X' in 'RRX' is not a joint letter/],
    [['cspace-of', 'base=flying'], /base: unknown value 'flying'/],
    [['cspace-of', 'legs=4'], /unknown key 'legs'/],
    [['cspace-of', 'joints=RR\nbase=nowhere'], /base: unknown value 'nowhere'/],
    [['cspace-of'], /missing DESCRIPTION/],
    [['cspace-of', 'joints=R', 'extra'], /unexpected argument 'extra'/],
    [['cspace-of', 'joints=R', '--check'], /--check needs a value/],
  ];
  for (const [args, message] of cases) {
    const r = run(...args);
    assert.equal(r.status, 2, args.join(' '));
    assert.equal(r.stdout, '');
    assert.equal(r.stderr.trim().split('\n').length, 1, r.stderr);
    assert.match(r.stderr, /^cspacelab: /);
    assert.match(r.stderr, message);
  }
});

test('help documents the description format', () => {
  const r = run('help', 'cspace-of');
  assert.equal(r.status, 0);
  for (const word of ['base=', 'planar-translating', 'spatial', 'joints=', 'wrist=spherical', '--check'])
    assert.ok(r.stdout.includes(word), word);
  assert.match(run('--help').stdout, /cspace-of/);
});
