// cspacelab plan and experiment with --planner rrt and rrt-connect (issue 24): the same JSON as
// PRM's, a tree's edges as the roadmap's edge_list, the path along them, and bad flags refused.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { json, fails, run, scene } from './lib/cli.mjs';

const GAP = scene('wall-gap.json');
const ARM = scene('arm-2link.json');

// The path starts at the start, ends at the goal, and each consecutive pair of its
// configurations is an edge of edge_list (either way round); the length is the space's.
function checkTreePath(r, start, goal, distance) {
  assert.equal(r.solved, true);
  assert.deepEqual(r.path[0], start);
  assert.deepEqual(r.path.at(-1), goal);
  const index = new Map(r.vertices.map((q, i) => [JSON.stringify(q), i]));
  const edges = new Set(r.edge_list.map(([a, b]) => `${Math.min(a, b)}-${Math.max(a, b)}`));
  let length = 0;
  for (let i = 0; i + 1 < r.path.length; ++i) {
    const a = index.get(JSON.stringify(r.path[i])), b = index.get(JSON.stringify(r.path[i + 1]));
    assert.ok(a !== undefined && b !== undefined, `path point ${i} is a vertex`);
    assert.ok(edges.has(`${Math.min(a, b)}-${Math.max(a, b)}`), `path pair ${a}-${b} is an edge of edge_list`);
    const d = distance(r.path[i], r.path[i + 1]);
    assert.ok(d <= r.step * (1 + 1e-12), `path edge ${a}-${b} of ${d} is within the step ${r.step}`);
    length += d;
  }
  assert.ok(Math.abs(length - r.path_length) < 1e-9, `length ${length} against ${r.path_length}`);
  // A tree: every vertex but the two roots has its edge to its parent, plus at most the join.
  assert.ok(r.edge_list.length === r.nodes - 2 || r.edge_list.length === r.nodes - 1);
  assert.equal(r.edge_list.length, r.edges);
}

const plane = (p, q) => Math.hypot(q[0] - p[0], q[1] - p[1]);
// T^2: each angle the short way round.
const torus = (p, q) => Math.hypot(...p.map((a, i) => Math.abs(Math.remainder?.(q[i] - a, 2 * Math.PI) ??
  ((((q[i] - a + Math.PI) % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI)) - Math.PI)));

test('plan --planner rrt and rrt-connect: the path runs along the tree edges from start to goal', () => {
  for (const planner of ['rrt', 'rrt-connect']) {
    const r = json('plan', GAP, '--planner', planner, '--samples', '3000', '--step', '0.05', '--seed', '4', '--roadmap');
    for (const k of ['solved', 'path', 'path_length', 'nodes', 'edges', 'components', 'edge_checks', 'evaluations',
                     'build_seconds', 'query_seconds', 'samples', 'neighbors', 'checker', 'connector', 'seed', 'steps',
                     'roadmap_hash', 'phase', 'done', 'samples_drawn', 'last_event', 'vertices', 'edge_list'])
      assert.ok(k in r, `${planner}: ${k}`);
    assert.equal(r.planner, planner);
    assert.equal(r.step, 0.05);
    assert.equal(r.neighbors, null);
    assert.equal(r.goal_bias, planner === 'rrt' ? 0.05 : null);
    assert.equal(r.last_event, 'path_found');
    assert.ok(r.samples_drawn <= 3000);
    checkTreePath(r, [0.15, 0.85], [0.85, 0.75], plane);
    // Deterministic: the same seed, the same tree; another seed, another.
    const again = json('plan', GAP, '--planner', planner, '--samples', '3000', '--step', '0.05', '--seed', '4');
    assert.equal(again.roadmap_hash, r.roadmap_hash);
    const other = json('plan', GAP, '--planner', planner, '--samples', '3000', '--step', '0.05', '--seed', '5');
    assert.notEqual(other.roadmap_hash, r.roadmap_hash);
  }
});

test('plan --planner rrt-connect on the arm: tree edges on T^2, the short way round', () => {
  const r = json('plan', ARM, '--planner', 'rrt-connect', '--samples', '2000', '--seed', '2', '--roadmap');
  // The default step: a fifth of T^2's extent, sqrt(2) pi.
  assert.ok(Math.abs(r.step - 0.2 * Math.SQRT2 * Math.PI) < 1e-12);
  checkTreePath(r, [0.2, 0.3], [2.6, -0.4], torus);
  for (const [a, b] of r.edge_list) assert.ok(torus(r.vertices[a], r.vertices[b]) <= r.step * (1 + 1e-12));
});

test('plan --planner prm and prm-star keep PRM\'s output; --prm-star still works', () => {
  const a = json('plan', GAP, '--samples', '200', '--seed', '5');
  const b = json('plan', GAP, '--planner', 'prm', '--samples', '200', '--seed', '5');
  assert.equal(a.roadmap_hash, b.roadmap_hash);
  assert.equal(a.planner, 'prm');
  const star = json('plan', GAP, '--samples', '200', '--seed', '5', '--prm-star');
  const star2 = json('plan', GAP, '--planner', 'prm-star', '--samples', '200', '--seed', '5');
  assert.equal(star.roadmap_hash, star2.roadmap_hash);
  assert.equal(star2.neighbors, 'prm*');
  assert.equal(star2.step, null);
});

test('experiment --planner rrt-connect: rows from the tree planner', () => {
  const r = json('experiment', GAP, '--planner', 'rrt-connect', '--samples-list', '0,2000', '--trials', '6', '--seed', '2');
  assert.equal(r.planner, 'rrt-connect');
  assert.equal(r.neighbors, null);
  assert.equal(r.rows.length, 2);
  for (const row of r.rows) assert.equal(row.trials, 6);
  // No samples: the trees never grow; two thousand nearly always meet through the gap.
  assert.equal(r.rows[0].failures, 6);
  assert.ok(r.rows[1].failures <= 1);
  const prm = json('experiment', GAP, '--samples-list', '10', '--trials', '3', '--seed', '2', '--k', '5');
  assert.equal(prm.planner, 'prm');
});

test('bad planner flags: one clear line and exit status 2', () => {
  fails(/--planner: unknown planner 'rrt-star' \(prm, prm-star, lazy-prm, rrt, rrt-connect/, 'plan', GAP, '--planner', 'rrt-star');
  fails(/--goal-bias: '1.5' is not a number in \[0, 1\]/, 'plan', GAP, '--planner', 'rrt', '--goal-bias', '1.5');
  fails(/--goal-bias: 'nan' is not/, 'plan', GAP, '--planner', 'rrt', '--goal-bias', 'nan');
  fails(/--step: '-0.1' is not a number >= 0/, 'plan', GAP, '--planner', 'rrt', '--step', '-0.1');
  fails(/--step: /, 'plan', GAP, '--planner', 'rrt-connect', '--step', 'inf');
  fails(/--goal-bias is RRT's .* rrt-connect has no goal bias/, 'plan', GAP, '--planner', 'rrt-connect', '--goal-bias', '0.1');
  fails(/--step is the tree planners' .* not prm's/, 'plan', GAP, '--step', '0.1');
  fails(/--k is PRM's: rrt grows trees/, 'plan', GAP, '--planner', 'rrt', '--k', '5');
  fails(/--prm-star is PRM's: rrt-connect grows trees/, 'plan', GAP, '--planner', 'rrt-connect', '--prm-star');
  fails(/--radius does not go with --planner prm-star/, 'plan', GAP, '--planner', 'prm-star', '--radius', '0.1');
  fails(/--connector is PRM's/, 'plan', GAP, '--planner', 'rrt', '--connector', 'potential');
  fails(/--samples: '2000000' is not an integer in \[0, 1000000\]/, 'plan', GAP, '--planner', 'rrt', '--samples', '2000000');
  fails(/--planner: unknown planner/, 'experiment', GAP, '--planner', 'RRT', '--samples-list', '10');
  fails(/--goal-bias: '-1' is not/, 'experiment', GAP, '--planner', 'rrt', '--goal-bias', '-1', '--samples-list', '10');
  // Work is priced before the run, as PRM's is.
  fails(/^cspacelab: rrt with 200 samples, step 0\.28\d* and bisection means about .* \(--max-work\)/, 'plan', GAP,
        '--planner', 'rrt', '--max-work', '100');
  fails(/of work in all, more than the .* \(--max-total-work/, 'experiment', GAP, '--planner', 'rrt-connect',
        '--samples-list', '1000000', '--trials', '100000');
});

test('--help documents the planners and their options', () => {
  for (const cmd of ['plan', 'experiment']) {
    const r = run(cmd, '--help');
    assert.equal(r.status, 0);
    for (const word of ['--planner NAME', 'rrt-connect', '--goal-bias B', '--step D', 'prm-star'])
      assert.ok(r.stdout.includes(word), `${cmd} --help names ${word}`);
  }
});
