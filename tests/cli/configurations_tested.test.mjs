// configurations_tested in plan's and experiment's JSON (issue 24): every configuration a planner
// gave the collision checker, the same measure for every planner, beside each planner's own
// "evaluations" (kept as it was: PRM's leaves its samples out).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { json, tempScene, scene } from './lib/cli.mjs';

const PLANNERS = ['prm', 'prm-star', 'lazy-prm', 'rrt', 'rrt-connect'];

test('plan: configurations_tested on an empty square is what a hand count gives', () => {
  // No obstacles: every configuration is free, every clearance infinite, so every edge is proven
  // free by the motion bound without a point tested between its ends. PRM with the exact
  // checker tests the two endpoints, each sample (is_free, then its clearance: each vertex's is
  // kept), and on the path's exact re-check the two ends of each path edge.
  const empty = tempScene({ version: 1, name: 'empty', workspace: { min: [0, 0], max: [1, 1] }, robot: { type: 'point' },
                            obstacles: [], start: [0.1, 0.5], goal: [0.9, 0.5] });
  for (const n of [10, 40]) {
    const r = json('plan', empty, '--samples', String(n), '--seed', '3');
    assert.equal(r.solved, true);
    const pathEdges = r.path.length - 1;
    assert.equal(r.configurations_tested, 2 + 2 * n + 2 * pathEdges, `n = ${n}`);
    // PRM's own evaluations (as before) count the points tested between an edge's ends: none.
    assert.equal(r.evaluations, 0, 'evaluations as before: the samples and ends left out');
  }
});

test('plan: every planner reports configurations_tested, at least its evaluations', () => {
  const gap = scene('wall-gap.json');
  for (const planner of PLANNERS) {
    const r = json('plan', gap, '--planner', planner, '--samples', '300', '--seed', '2');
    assert.ok(Number.isInteger(r.configurations_tested), planner);
    assert.ok(r.configurations_tested >= r.evaluations, `${planner}: ${r.configurations_tested} >= ${r.evaluations}`);
    // At least one test per sample drawn (the tree planners test each new end).
    assert.ok(r.configurations_tested >= r.samples_drawn, planner);
  }
  // Tests outside the edge checks: a uniform draw tests one configuration, a Gaussian draw two
  // (both ends of its pair), a bridge draw one to three; plus the two endpoints.
  const draws = (sampler) => {
    const r = json('plan', gap, '--samples', '300', '--sampler', sampler, '--seed', '2');
    return r.configurations_tested - r.evaluations;
  };
  assert.ok(draws('uniform') >= 300 + 2);
  assert.ok(draws('gaussian:0.05') >= 2 * 300 + 2, 'gaussian: two tests a draw');
  const bridge = draws('bridge:0.05');
  assert.ok(bridge >= 300 + 2 && bridge <= 3 * 300 + 2 + 300, `bridge: ${bridge}`);
});

test('experiment: each row gives the mean configurations_tested of its runs', () => {
  const gap = scene('wall-gap.json');
  for (const planner of ['prm', 'rrt-connect']) {
    const r = json('experiment', gap, '--planner', planner, '--samples-list', '20,80', '--trials', '4',
                   '--reference-samples', '2000');
    for (const row of r.rows) {
      assert.equal(typeof row.configurations_tested, 'number');
      // PRM draws exactly n samples a run, each tested; a tree planner tests at least one end
      // a draw until it stops (at most n draws).
      if (planner === 'prm') assert.ok(row.configurations_tested >= row.samples + 2, `${planner} n = ${row.samples}`);
      else assert.ok(row.configurations_tested > 2, `${planner} n = ${row.samples}`);
    }
    // More samples, more tests (on average over the runs).
    assert.ok(r.rows[1].configurations_tested > r.rows[0].configurations_tested, planner);
  }
});
