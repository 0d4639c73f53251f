// cspacelab plan and experiment with --planner lazy-prm (issue 24): PRM's roadmap built without
// checking its edges, only a shortest path's edges checked. The path runs along checked edges,
// the edges never checked are counted and flagged, and with the same seed and samples it finds
// a path exactly when PRM does, as short, with far fewer edge checks.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { json, fails, scene } from './lib/cli.mjs';

const GAP = scene('wall-gap.json');
const ARM = scene('arm-2link.json');

function checkLazy(r) {
  assert.equal(r.planner, 'lazy-prm');
  assert.equal(r.edge_checked.length, r.edge_list.length, 'a flag per edge');
  assert.equal(r.edges_unchecked, r.edge_checked.filter((c) => !c).length, 'edges_unchecked counts the false flags');
  if (!r.solved) return;
  const index = new Map(r.vertices.map((q, i) => [JSON.stringify(q), i]));
  const checked = new Set(r.edge_list.filter((_, i) => r.edge_checked[i]).map(([a, b]) => `${Math.min(a, b)}-${Math.max(a, b)}`));
  assert.deepEqual(r.path[0], r.vertices[0]);
  assert.deepEqual(r.path.at(-1), r.vertices[1]);
  for (let i = 0; i + 1 < r.path.length; ++i) {
    const a = index.get(JSON.stringify(r.path[i])), b = index.get(JSON.stringify(r.path[i + 1]));
    assert.ok(checked.has(`${Math.min(a, b)}-${Math.max(a, b)}`), `path edge ${a}-${b} was checked`);
  }
}

test('plan --planner lazy-prm: a path of checked edges, as long as PRM\'s, for far fewer checks', () => {
  for (const [file, samples] of [[GAP, 400], [ARM, 300]]) {
    for (const seed of ['3', '8']) {
      const lazy = json('plan', file, '--planner', 'lazy-prm', '--samples', String(samples), '--seed', seed, '--roadmap');
      const prm = json('plan', file, '--planner', 'prm', '--samples', String(samples), '--seed', seed);
      checkLazy(lazy);
      assert.equal(lazy.solved, prm.solved, `${file} seed ${seed}: solved as PRM`);
      assert.equal(lazy.nodes, prm.nodes, 'the same samples kept');
      if (prm.solved) {
        assert.ok(Math.abs(lazy.path_length - prm.path_length) < 1e-9, `${lazy.path_length} vs ${prm.path_length}`);
        assert.ok(lazy.edge_checks * 3 < prm.edge_checks, `${lazy.edge_checks} checks vs PRM's ${prm.edge_checks}`);
        assert.ok(lazy.edges_unchecked > 0, 'most edges never checked');
      }
    }
  }
});

test('plan --planner lazy-prm takes a sampler; refuses a connector; trees refuse a sampler', () => {
  const r = json('plan', GAP, '--planner', 'lazy-prm', '--sampler', 'halton', '--samples', '300', '--roadmap');
  assert.equal(r.sampler, 'halton');
  checkLazy(r);
  fails(/connector/, 'plan', GAP, '--planner', 'lazy-prm', '--connector', 'potential');
  fails(/--sampler is the roadmap planners'/, 'plan', GAP, '--planner', 'rrt', '--sampler', 'bridge:0.05');
  const tree = json('plan', GAP, '--planner', 'rrt-connect', '--samples', '500');
  assert.equal(tree.sampler, null, 'a tree planner has no sampler');
});

test('experiment --planner lazy-prm counts failures of Lazy PRM runs', () => {
  const r = json('experiment', GAP, '--planner', 'lazy-prm', '--samples-list', '0,400', '--trials', '4');
  assert.equal(r.planner, 'lazy-prm');
  assert.equal(r.rows[0].failures, 4, 'no samples: no path through the wall');
  assert.ok(r.rows[1].failures <= 2, `400 samples mostly find the gap: ${r.rows[1].failures} of 4 failed`);
});
