// cspacelab plan, bound, visibility and experiment: their contracts, determinism, bad input.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { json, fails, run, scene, tempScene } from './lib/cli.mjs';
import { p9RightArea } from '../lib/p9.mjs';

const GAP = scene('wall-gap.json');

test('plan finds a path through the gap, with every field of the contract', () => {
  const r = json('plan', GAP, '--samples', '300', '--k', '10', '--seed', '3');
  for (const k of ['solved', 'path', 'path_length', 'nodes', 'edges', 'components', 'edge_checks', 'evaluations',
                   'build_seconds', 'query_seconds'])
    assert.ok(k in r, k);
  assert.equal(r.solved, true);
  assert.deepEqual(r.path[0], [0.15, 0.85]);
  assert.deepEqual(r.path.at(-1), [0.85, 0.75]);
  // The path crosses x = 1/2 inside the opening.
  for (let i = 0; i + 1 < r.path.length; ++i) {
    const [a, b] = [r.path[i], r.path[i + 1]];
    if ((a[0] - 0.5) * (b[0] - 0.5) < 0) {
      const y = a[1] + (b[1] - a[1]) * (0.5 - a[0]) / (b[0] - a[0]);
      assert.ok(y > 0.45 && y < 0.55, `crosses the wall at y = ${y}`);
    }
  }
  let length = 0;
  for (let i = 0; i + 1 < r.path.length; ++i) length += Math.hypot(r.path[i + 1][0] - r.path[i][0], r.path[i + 1][1] - r.path[i][1]);
  assert.ok(Math.abs(length - r.path_length) < 1e-12);
  assert.ok(r.nodes <= 302 && r.edges > 0 && r.components >= 1);
});

test('plan is deterministic: the same seed gives the same roadmap, another seed another', () => {
  const a = json('plan', GAP, '--samples', '200', '--seed', '5', '--roadmap');
  const b = json('plan', GAP, '--samples', '200', '--seed', '5', '--roadmap');
  const c = json('plan', GAP, '--samples', '200', '--seed', '6');
  assert.equal(a.roadmap_hash, b.roadmap_hash);
  assert.deepEqual(a.vertices, b.vertices);
  assert.deepEqual(a.edge_list, b.edge_list);
  assert.notEqual(a.roadmap_hash, c.roadmap_hash);
  assert.equal(a.edge_list.length, a.edges);
  assert.equal(a.vertices.length, a.nodes);
});

test('plan with each neighbour rule and checker', () => {
  for (const opts of [['--radius', '0.15'], ['--prm-star'], ['--checker', 'grid:20'], ['--checker', 'step:0.01']]) {
    const r = json('plan', GAP, '--samples', '300', ...opts);
    assert.equal(r.solved, true, opts.join(' '));
  }
  assert.equal(json('plan', GAP, '--prm-star').neighbors, 'prm*');
});

test('a closed wall: no path', () => {
  const closed = tempScene({ version: 1, obstacles: [{ type: 'segment', a: [0.5, 0], b: [0.5, 1] }],
                             start: [0.2, 0.5], goal: [0.8, 0.5] });
  const r = json('plan', closed, '--samples', '200');
  assert.equal(r.solved, false);
  assert.deepEqual(r.path, []);
  assert.equal(r.path_length, null);
});

test('bound and bound --tiling', () => {
  const b = json('bound', '--length', '1', '--clearance', '0.1', '--dim', '2', '--free-volume', '0.9', '--samples', '1000');
  assert.equal(b.balls, 20);
  assert.ok(Math.abs(b.sigma - Math.PI / 3.6) < 1e-15);
  assert.ok(Math.abs(b.failure_bound - 20 * Math.exp(-Math.PI / 3.6 * 10)) < 1e-15);
  assert.equal(b.vacuous, false);
  assert.equal(json('bound', '--length', '1', '--clearance', '0.1', '--dim', '2', '--free-volume', '1', '--samples', '5').vacuous, true);
  const t = json('bound', '--tiling', '--clearance', '0.1', '--dim', '3', '--samples', '1000');
  assert.equal(t.balls, 8000);
  assert.equal(t.balls_per_axis, 20);
  assert.equal(t.boundary_balls, 8000 - 18 ** 3);  // the first and last along some axis
  assert.ok(Math.abs(t.sigma - 4 / 3 * Math.PI / 8) < 1e-15);
  const e = Math.PI / 6 * 1e-3 * 1000;
  assert.ok(Math.abs(t.interior_bound / (8000 * Math.exp(-e)) - 1) < 1e-12);
  // Balls reaching out along j axes count at rate e / 2^j: C(3,j) 2^j 18^(3-j) of them.
  const sound = 18 ** 3 * Math.exp(-e) + 3 * 2 * 18 ** 2 * Math.exp(-e / 2) + 3 * 4 * 18 * Math.exp(-e / 4) + 8 * Math.exp(-e / 8);
  assert.ok(Math.abs(t.failure_bound / sound - 1) < 1e-12, `${t.failure_bound} against ${sound}`);
  // P8 counts for a covering: past d = 4, ceil(sqrt(d)/r) per axis.
  assert.equal(json('bound', '--tiling', '--clearance', '0.1', '--dim', '6', '--samples', '0').balls_per_axis, 25);
  // L / (r/2) as the decimals typed mean it: 7 balls, although 0.07 / 0.01 is 7.000000000000001.
  assert.equal(json('bound', '--length', '0.07', '--clearance', '0.02', '--dim', '2', '--free-volume', '1', '--samples', '10').balls, 7);
});

test('visibility: exact and Monte Carlo agree', () => {
  const v = json('visibility', '--x', '0.3', '--y', '0.2', '--gap', '0.1', '--trials', '200000', '--seed', '4');
  assert.ok(v.exact > 0.5 && v.exact < 1);
  assert.ok(Math.abs(v.exact - v.monte_carlo) < 0.006);
  assert.equal(v.trials, 200000);
  assert.equal(json('visibility', '--x', '0.1', '--y', '0.5', '--gap', '0').exact, 0.5);
  // No samples, no estimate: the exact value alone.
  const none = json('visibility', '--x', '0.25', '--y', '0.5', '--gap', '0.2', '--trials', '0');
  assert.deepEqual([none.exact, none.trials, none.monte_carlo, none.ci_low, none.ci_high, none.within_ci], [0.7, 0, null, null, null, null]);
});

test('experiment: rows with failure rates, intervals and the bound', () => {
  const r = json('experiment', GAP, '--samples-list', '10,300', '--trials', '12', '--seed', '2', '--k', '5');
  assert.equal(r.reference.path_exists, true);
  assert.equal(r.rows.length, 2);
  for (const row of r.rows) {
    assert.equal(row.trials, 12);
    assert.ok(row.ci_low <= row.failure_rate && row.failure_rate <= row.ci_high);
    assert.equal(typeof row.bound, 'number');
  }
  assert.ok(r.rows[0].failures >= r.rows[1].failures);
});

test('bad input for plan, bound, visibility, experiment', () => {
  const inside = tempScene({ version: 1, obstacles: [{ type: 'disk', center: [0, 0], radius: 0.2 }] });
  fails(/the start is in collision with obstacles\[0\] \(a disk\)/, 'plan', inside);
  fails(/--samples: '1e9' is not an integer/, 'plan', GAP, '--samples', '1e9');
  fails(/--samples: '2000000' is not an integer in \[0, 1000000\]/, 'plan', GAP, '--samples', '2000000');
  fails(/choose one neighbour rule/, 'plan', GAP, '--k', '5', '--prm-star');
  fails(/--k: k must be an integer/, 'plan', GAP, '--k', '0');
  fails(/--radius: the radius must be > 0/, 'plan', GAP, '--radius', '-1');
  fails(/clearance must be a finite number > 0/, 'bound', '--length', '1', '--clearance', '0', '--dim', '2', '--free-volume', '1', '--samples', '10');
  fails(/more than 1e308 balls: take a shorter path or a larger clearance/, 'bound', '--length', '1e308', '--clearance', '1e-300', '--dim', '1', '--free-volume', '1', '--samples', '1e303');
  fails(/clearance\^d overflows a double/, 'bound', '--length', '1', '--clearance', '1e300', '--dim', '2', '--free-volume', '1', '--samples', '0');
  fails(/clearance\^d overflows a double/, 'bound', '--tiling', '--clearance', '1e300', '--dim', '2', '--samples', '0');
  fails(/more than 1e308 balls/, 'bound', '--tiling', '--clearance', '1e-10', '--dim', '64', '--samples', '10');
  fails(/missing --free-volume/, 'bound', '--length', '1', '--clearance', '0.1', '--dim', '2', '--samples', '10');
  fails(/x1 must be in \[0, 1\/2\)/, 'visibility', '--x', '0.7', '--y', '0.5', '--gap', '0.1');
  fails(/--gap: 'nan' is not a finite number/, 'visibility', '--x', '0.2', '--y', '0.5', '--gap', 'nan');
  fails(/missing --samples-list/, 'experiment', GAP);
  fails(/--trials: '0' is not an integer in \[1, 100000\]/, 'experiment', GAP, '--samples-list', '10', '--trials', '0');
  fails(/--trials: '-1' is not an integer in \[1, 100000\]/, 'experiment', GAP, '--samples-list', '10', '--trials', '-1');
  fails(/--samples: ' 5' is not an integer/, 'plan', GAP, '--samples', ' 5');
});

// A radius makes the candidate pairs grow with n^2: a run expected to check more than
// --max-pairs (default 2e7) is refused before it starts, and says the largest radius that fits.
test('plan and experiment refuse a run with too many candidate pairs, and say what fits', () => {
  // The radius the error names, as printed, fits (1% more does not), under any --max-pairs.
  for (const [samples, maxPairs] of [['2000', '20000'], ['5000', '123457'], ['300', '1000']]) {
    const refused = run('plan', GAP, '--samples', samples, '--radius', '0.5', '--max-pairs', maxPairs);
    assert.equal(refused.status, 2);
    const printed = refused.stderr.match(/r at most ([0-9.e+-]+)/)[1];
    assert.ok(json('plan', GAP, '--samples', samples, '--radius', printed, '--max-pairs', maxPairs).edge_checks > 0, printed);
    fails(/candidate pairs/, 'plan', GAP, '--samples', samples, '--radius', String(Number(printed) * 1.01), '--max-pairs', maxPairs);
  }
  // 20000 of 2002 x 2001 / 2 pairs: pi r^2 = 0.00998..., r = 0.056376...
  fails(/r at most 0\.05637$/, 'plan', GAP, '--samples', '2000', '--radius', '0.5', '--max-pairs', '20000');

  // k rules: (n + 2) k pairs at most.
  fails(/--k 50 with 1000 samples means up to 50100 candidate pairs, more than the 10000 .*--k\)$/, 'plan', GAP, '--samples', '1000', '--k', '50', '--max-pairs', '10000');
  assert.equal(json('plan', GAP, '--samples', '1000', '--k', '9', '--max-pairs', '10000').samples, 1000);
  fails(/--max-pairs: must be at least 1/, 'plan', GAP, '--max-pairs', '0');

  // The default budget (these would run for hours without it: small budgets first).
  fails(/--radius 5 with 200000 samples means about 2e\+10 candidate pairs, more than the 2e\+07 .*r at most 0\.0178/,
        'plan', GAP, '--samples', '200000', '--radius', '5');
  fails(/--prm-star with 1000000 samples means up to 5\.7e\+07 candidate pairs/, 'plan', GAP, '--samples', '1000000', '--prm-star');
  // Just over: the count has as many digits as tell it from the limit.
  fails(/--k 20 with 1000000 samples means up to 2\.000004e\+07 candidate pairs, more than the 2e\+07 /,
        'plan', GAP, '--samples', '1000000', '--k', '20');

  // experiment: the reference run (4 x the largest n, at least 2000) counts too.
  fails(/the reference run .*--radius 0\.3 with 2000 samples/, 'experiment', GAP, '--samples-list', '100',
        '--radius', '0.3', '--max-pairs', '20000', '--trials', '1');
  fails(/^cspacelab: --radius 0\.3 with 1000 samples/, 'experiment', GAP, '--samples-list', '100,1000',
        '--radius', '0.3', '--max-pairs', '20000', '--trials', '1');

  // experiment: and all its runs together, T for each n plus the reference run. With k = 10,
  // a run of n samples is expected to check (n + 2) 10 pairs: 3 x (1020 + 2020) + 20020 for
  // the reference run's 2000 samples = 29140.
  const small = ['experiment', GAP, '--samples-list', '100,200', '--trials', '3', '--k', '10'];
  assert.equal(json(...small, '--max-total-pairs', '29140').rows.length, 2);
  fails(/^cspacelab: --trials 3 with --samples-list 100,200 means about 29140 candidate pairs in all \(the reference run: 20020\), more than the 29139 an experiment may check \(--max-total-pairs\); take fewer trials, fewer samples or fewer neighbours \(--k\)$/,
        ...small, '--max-total-pairs', '29139');
  // The default: 50 runs at --max-pairs. Each of these runs passes it; all of them together would
  // take days.
  fails(/--trials 100000 with --samples-list 1000000 means about 1e\+12 candidate pairs in all .* more than the 1e\+09 /,
        'experiment', GAP, '--trials', '100000', '--samples-list', '1000000');
  // 1000 x 20020 + 80020 (reference: 8000 samples) > 50 x 80020.
  fails(/means about 2\.01e\+07 candidate pairs in all \(the reference run: 80020\), more than the 4\.001e\+06 /,
        'experiment', GAP, '--trials', '1000', '--samples-list', '2000', '--k', '10', '--max-pairs', '80020');
  fails(/--max-total-pairs: must be at least 1/, ...small, '--max-total-pairs', '0');
});

// P8 as the handout has it: m = N^d balls put into the path bound, and the n it needs.
test('bound --tiling: the handout\'s rate and samples for the target', () => {
  for (const [r, d, p] of [[0.042, 2, 0.01], [0.1, 3, 0.05], [0.2, 6, 1e-4]]) {
    const t = json('bound', '--tiling', '--clearance', String(r), '--dim', String(d), '--samples', '1000', '--target', String(p));
    const perAxis = Math.ceil(Math.max(2, Math.sqrt(d)) / r);
    const ball = d === 2 ? Math.PI : d === 3 ? 4 / 3 * Math.PI : Math.PI ** 3 / 6;  // mu(B_1) in R^d
    const rate = ball / 2 ** d * r ** d;
    assert.equal(t.balls_per_axis, perAxis);
    assert.equal(t.balls, perAxis ** d);
    assert.ok(Math.abs(t.rate / rate - 1) < 1e-13, `rate ${t.rate} against ${rate}`);
    const n = Math.log(perAxis ** d / p) / rate;
    assert.ok(Math.abs(t.interior_samples_for_target / n - 1) < 1e-12, `${t.interior_samples_for_target} against ${n}`);
    // The refined bound, faces counted, needs more.
    assert.ok(t.samples_for_target > t.interior_samples_for_target);
  }
});

// P9 by cases: the rays' exits, their areas and the probability, against a polygon clipped apart
// from the lab (tests/lib/p9.mjs).
test('visibility: the breakdown by cases', () => {
  const clipArea = p9RightArea;
  const cases = [[0.3, 0.2, 0.2, 'top/right edge'], [0.45, 0.5, 0.2, 'top/bottom'], [0.45, 0.95, 0.1, 'bottom/bottom'],
                 [0.1, 0.5, 0.1, 'right edge/right edge'], [0.4, 0.1, 0.2, 'top/top'], [0.2, 0.9, 0.4, 'right edge/bottom']];
  for (const [x, y, gap, name] of cases) {
    const v = json('visibility', '--x', String(x), '--y', String(y), '--gap', String(gap), '--trials', '0');
    const b = v.breakdown;
    assert.equal(b.case, name, `(${x}, ${y}) gap ${gap}`);
    assert.equal(b.upper.exit + '/' + b.lower.exit, name);
    assert.equal(b.left_area, 0.5);
    assert.ok(Math.abs(b.upper.slope - (0.5 + gap / 2 - y) / (0.5 - x)) < 1e-12);
    assert.ok(Math.abs(b.lower.slope - (0.5 - gap / 2 - y) / (0.5 - x)) < 1e-12);
    assert.ok(Math.abs(b.right_area - clipArea(x, y, gap)) < 1e-12, `${b.right_area} against ${clipArea(x, y, gap)}`);
    assert.ok(Math.abs(b.probability - v.exact) < 1e-12);
  }
  // With samples, the same breakdown beside the estimate.
  const withMc = json('visibility', '--x', '0.3', '--y', '0.2', '--gap', '0.2', '--trials', '1000');
  assert.equal(withMc.breakdown.case, 'top/right edge');
  assert.equal(typeof withMc.within_ci, 'boolean');
});

// Issue 23: the --help lines of the options described in core/base/params.hpp are generated from the
// same spec the parser checks with, so the range the help states is the range an error names.
test('--help states the ranges and defaults the parsers check', () => {
  const cases = [
    ['plan', '--samples', '2000001', ['plan', GAP]],
    ['plan', '--k', null, null],
    ['experiment', '--trials', '100001', ['experiment', GAP, '--samples-list', '10']],
    ['experiment', '--reference-samples', '1000001', ['experiment', GAP, '--samples-list', '10']],
    ['visibility', '--trials', '-1', ['visibility', '--x', '0.2', '--y', '0.5', '--gap', '0.1']],
    ['check', '--max', '1', ['check', GAP, '--min-grid']],
  ];
  for (const [command, flag, bad, args] of cases) {
    const help = run('help', command).stdout;
    // "  --trials T   PRM runs for each n: an integer in [1, 100000], default 20", the range
    // perhaps on the next line.
    const m = help.match(new RegExp(`^  ${flag} \\S+ +[^\\n]*?:\\s+(an integer in \\[[0-9]+, [0-9]+\\])`, 'm'));
    assert.ok(m, `${command} --help has a line for ${flag}:\n${help}`);
    if (bad) fails(new RegExp(`${flag}: '${bad}' is not ${m[1].replace(/[[\]]/g, '\\$&')}$`), ...args, flag, bad);
  }
  assert.match(run('help', 'plan').stdout, /--samples N +samples drawn[^\n]*:\s+an integer in \[0, 1000000\], default 200/);
  assert.match(run('help', 'experiment').stdout, /--trials T +PRM runs for each n: an integer in \[1, 100000\], default 20/);
});
