// cspacelab plan/experiment --sampler: PRM's samplers from the command line, their JSON, bad values.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { json, fails, run, scene, tempScene } from './lib/cli.mjs';

const GAP = scene('wall-gap.json');
// A thick wall (x in [0.4, 0.6]) with a gap of 4% of the width at y in [0.48, 0.52]: the bridge
// test needs obstacles with an inside.
const PASSAGE = tempScene({
  version: 1,
  obstacles: [{ type: 'polygon', vertices: [[0.4, 0], [0.6, 0], [0.6, 0.48], [0.4, 0.48]] },
              { type: 'polygon', vertices: [[0.4, 0.52], [0.6, 0.52], [0.6, 1], [0.4, 1]] }],
  start: [0.1, 0.5], goal: [0.9, 0.5],
});
const inPassage = ([x, y]) => x >= 0.4 && x <= 0.6 && y >= 0.48 && y <= 0.52;

test('plan --sampler: uniform is the default to the bit; each sampler is named in the JSON', () => {
  const plain = json('plan', GAP, '--samples', '200', '--seed', '4');
  const uniform = json('plan', GAP, '--samples', '200', '--seed', '4', '--sampler', 'uniform');
  assert.equal(plain.sampler, 'uniform');
  assert.equal(uniform.roadmap_hash, plain.roadmap_hash);
  for (const s of ['gaussian:0.05', 'bridge:0.1', 'bridge:0.1,uniform:0.3', 'halton']) {
    const r = json('plan', PASSAGE, '--samples', '400', '--seed', '4', '--sampler', s);
    assert.equal(r.sampler, s);
    assert.equal(r.samples_drawn, 400, s);  // n counts the sampler's draws
    assert.ok(r.nodes <= 402, s);
  }
  assert.equal(json('plan', GAP, '--sampler', 'gaussian:1e-1').sampler, 'gaussian:0.1');
  // A uniform share of 0 is the plain sampler, to the bit.
  const pure = json('plan', PASSAGE, '--samples', '400', '--seed', '4', '--sampler', 'bridge:0.1');
  const zero = json('plan', PASSAGE, '--samples', '400', '--seed', '4', '--sampler', 'bridge:0.1,uniform:0');
  assert.equal(zero.sampler, 'bridge:0.1');
  assert.equal(zero.roadmap_hash, pure.roadmap_hash);
});

test('plan --sampler halton ignores the seed; gaussian and bridge follow it', () => {
  const h1 = json('plan', GAP, '--samples', '150', '--seed', '1', '--sampler', 'halton');
  const h2 = json('plan', GAP, '--samples', '150', '--seed', '2', '--sampler', 'halton');
  assert.equal(h1.roadmap_hash, h2.roadmap_hash);
  const g1 = json('plan', PASSAGE, '--samples', '150', '--seed', '1', '--sampler', 'gaussian:0.05');
  const g1again = json('plan', PASSAGE, '--samples', '150', '--seed', '1', '--sampler', 'gaussian:0.05');
  const g2 = json('plan', PASSAGE, '--samples', '150', '--seed', '2', '--sampler', 'gaussian:0.05');
  assert.equal(g1.roadmap_hash, g1again.roadmap_hash);
  assert.notEqual(g1.roadmap_hash, g2.roadmap_hash);
});

test('plan --sampler bridge: its vertices sit in the passage; uniform\'s mostly elsewhere', () => {
  const share = (s) => {
    const r = json('plan', PASSAGE, '--samples', '2000', '--seed', '3', '--sampler', s, '--roadmap');
    const samples = r.vertices.slice(2);
    return samples.filter(inPassage).length / samples.length;
  };
  const uniform = share('uniform'), bridge = share('bridge:0.1');
  // The passage is 0.2 x 0.04 of a free area of 0.84: uniform's share about 1%.
  assert.ok(uniform < 0.03, `uniform: ${uniform}`);
  assert.ok(bridge > 0.5, `bridge: ${bridge}`);
});

test('experiment --sampler: the trials use it and the JSON names it', () => {
  const r = json('experiment', PASSAGE, '--samples-list', '30', '--trials', '4', '--sampler', 'bridge:0.1', '--k', '5');
  assert.equal(r.sampler, 'bridge:0.1');
  assert.equal(r.rows.length, 1);
  assert.equal(json('experiment', GAP, '--samples-list', '30', '--trials', '2').sampler, 'uniform');
});

test('bad --sampler values: one line each, naming the problem', () => {
  for (const cmd of [['plan', GAP], ['experiment', GAP, '--samples-list', '10']]) {
    fails(/--sampler: sampler 'gaussian:0': sigma must be a finite number > 0/, ...cmd, '--sampler', 'gaussian:0');
    fails(/--sampler: sampler 'bridge:-1': sigma must be a finite number > 0/, ...cmd, '--sampler', 'bridge:-1');
    fails(/--sampler: sampler 'gaussian:nan': not a number after ':'/, ...cmd, '--sampler', 'gaussian:nan');
    fails(/--sampler: sampler 'gaussian' needs its sigma: gaussian:S/, ...cmd, '--sampler', 'gaussian');
    fails(/--sampler: unknown sampler 'sobol' \(uniform, gaussian:S, bridge:S or halton; a hybrid adds a uniform share: bridge:S,uniform:W\)/,
          ...cmd, '--sampler', 'sobol');
    fails(/--sampler: sampler 'bridge:0.1,uniform:1': the uniform share W must be a number in \[0, 1\)/, ...cmd,
          '--sampler', 'bridge:0.1,uniform:1');
  }
});

test('--help documents --sampler for plan and experiment', () => {
  for (const cmd of ['plan', 'experiment']) {
    const r = run(cmd, '--help');
    assert.equal(r.status, 0);
    assert.match(r.stdout, /--sampler uniform\|gaussian:S\|bridge:S\|halton/);
    assert.match(r.stdout, /Boor et al\. 1999/);
    assert.match(r.stdout, /bridge:S,uniform:W/);
    assert.match(r.stdout, /"sampler"/);
  }
});
