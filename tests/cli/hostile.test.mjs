// Issue 27's hostile inputs to the CLI: each was accepted, crashed, ran for minutes or printed
// raw control characters before the fix. Bounded work is checked by what the CLI reports it
// did (evaluations) and by refusals before any work, never by the clock.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { json, fails, run, tempScene } from './lib/cli.mjs';

test('a workspace too small or too thin to draw is refused (it crashed the app by link)', () => {
  fails(/workspace: each side must be at least 0\.001 long \(it is 1e-15 by 1e-15\)/, 'validate',
        tempScene({ version: 1, workspace: { min: [0, 0], max: [1e-15, 1e-15] } }));
  fails(/workspace: each side must be at least 0\.001/, 'validate',
        tempScene({ version: 1, workspace: { min: [0, 0], max: [5e-324, 1] } }));
  fails(/workspace: one side may be at most 100 times the other/, 'validate',
        tempScene({ version: 1, workspace: { min: [0, 0], max: [1000, 1] }, goal: [1000, 1] }));
  assert.equal(json('validate', tempScene({ version: 1, workspace: { min: [0, 0], max: [0.001, 0.1] },
                                            goal: [0.001, 0.1] })).valid, true);
});

test('touching is a collision: a disk of radius 0 on the edge, and plan does not pass through it', () => {
  const dot = tempScene({ version: 1, obstacles: [{ type: 'disk', center: [0.5, 0.5], radius: 0 }],
                          start: [0.5, 0.1], goal: [0.5, 0.9] });
  const bisection = json('check', dot, '--checker', 'bisection');
  assert.equal(bisection.collision, true);
  assert.equal(bisection.collision_t, 0.5);
  assert.equal(json('check', dot, '--checker', 'grid:3').collision, true, 'the grid agrees where it tests the point');
  const plan = json('plan', dot, '--samples', '0');
  assert.equal(plan.solved, false, 'the straight path through the point is no path');
});

test('the notation parser has a depth limit (65000 parentheses were a SIGSEGV)', () => {
  const r = json('cspace-of', 'joints=RR', '--check', '('.repeat(65000));
  assert.equal(r.check.correct, false);
  assert.match(r.check.explanation, /longer than 1000 characters/);
  const nested = json('cspace-of', 'joints=RR', '--check', '('.repeat(40) + 'T^2' + ')'.repeat(40));
  assert.match(nested.check.explanation, /too many nested parentheses \(at most 32\)/);
});

test('min-grid across a thin wall among 999 others: answered from few configurations', () => {
  // Walls far from the edge in a corner, and one thin wall across it at a slant: no grid up to
  // 3000 sees it (checking grid after grid took 8 s for --max 3000; --max 100000 ran past 600 s).
  const walls = [];
  for (let i = 0; i < 999; ++i) {
    const x = (i % 37) / 37 * 0.3, y = 0.75 + Math.floor(i / 37) / 27 * 0.2;
    walls.push({ type: 'segment', a: [x, y], b: [x + 0.005, y + 0.003] });
  }
  walls.push({ type: 'segment', a: [0.5, 0.0], b: [0.5001, 1.0] });
  const file = tempScene({ version: 1, obstacles: walls });
  const r = json('check', file, '--from', '0.01,0.5', '--to', '0.99,0.52', '--min-grid', '--max', '100000');
  assert.equal(typeof r.min_grid, 'number');
  assert.ok(r.min_grid > 3000, `N = ${r.min_grid}`);
  // Every grid up to N in full is N^2 / 2 configurations; this is a sliver of that.
  assert.ok(r.evaluations < r.min_grid, `${r.evaluations} configurations for N = ${r.min_grid}`);
  const brute = json('check', file, '--from', '0.01,0.5', '--to', '0.99,0.52', '--checker', `grid:${r.min_grid}`);
  assert.equal(brute.collision, true, 'that grid does see the wall');
  const one_less = json('check', file, '--from', '0.01,0.5', '--to', '0.99,0.52', '--checker', `grid:${r.min_grid - 1}`);
  assert.equal(one_less.collision, false, 'and the grid of one configuration less does not');
  fails(/--min-grid: gave up after \d+ configurations/, 'check', file, '--from', '0.01,0.5', '--to', '0.99,0.52',
        '--min-grid', '--max', '100000', '--max-work', '100000');
});

test('work that would never end is refused up front, with the figures', () => {
  // 1000 polygons of 256 vertices: a configuration costs 257001 units.
  const polygons = [];
  for (let i = 0; i < 1000; ++i) {
    const cx = 0.05 + (i % 32) * 0.029, cy = 0.05 + Math.floor(i / 32) * 0.029;
    const v = [];
    for (let k = 0; k < 256; ++k) v.push([cx + 0.01 * Math.cos(2 * Math.PI * k / 256), cy + 0.01 * Math.sin(2 * Math.PI * k / 256)]);
    polygons.push({ type: 'polygon', vertices: v });
  }
  const heavy = tempScene({ version: 1, obstacles: polygons, start: [0.001, 0.001], goal: [0.999, 0.999] });
  fails(/200 samples with k:10 and grid:1000000 mean about 5\.2e\+14 units of work \(2020 candidate pairs at 2\.6e\+11 units each; one configuration of this scene costs 257001\), more than the 1e\+11 units a run may take \(--max-work\)/,
        'plan', heavy, '--checker', 'grid:1000000');
  fails(/--checker grid:1000000: this edge means about 2\.6e\+11 units of work in this scene, more than the 1e\+11 units a check may take/,
        'check', heavy, '--checker', 'grid:1000000');
  fails(/experiment's runs mean about .* more than the .* an experiment may take \(--max-total-work/,
        'experiment', heavy, '--samples-list', '1000,2000', '--trials', '100');
  fails(/--max-work: must be at least 1/, 'plan', heavy, '--max-work', '0');
});

test('one number syntax everywhere: spaces, hexadecimal and + are refused in --checker and --k as in --from', () => {
  const p12 = tempScene({ version: 1 });
  fails(/--checker: checker 'grid: 3': N must be an integer/, 'check', p12, '--checker', 'grid: 3');
  fails(/--checker: checker 'step:0x1p-3': D must be a number > 0/, 'check', p12, '--checker', 'step:0x1p-3');
  fails(/--checker: checker 'grid:\+5'/, 'check', p12, '--checker', 'grid:+5');
  fails(/--k: k must be an integer in \[1, 1000\]/, 'plan', p12, '--k', ' 5');
  fails(/--k: k must be an integer in \[1, 1000\]/, 'plan', p12, '--k', '0x10');
  fails(/--radius: neighbour rule 'radius: 0\.1': not a number/, 'plan', p12, '--radius', ' 0.1');
  fails(/--from: ' 0,0' is not a finite number|--from: '0x0' is not a finite number/, 'check', p12, '--from', '0x0,0');
  fails(/--seed: '\+3' is not an integer/, 'plan', p12, '--seed', '+3');
});

test('errors stay one printable line: newlines and escape sequences in arguments and keys are escaped', () => {
  for (const [args, echo] of [[['validate', 'bad\x1b[31mname\n'], /bad\\x1b\[31mname\\n: cannot read file/],
                              [['nosuch\rcommand'], /unknown command 'nosuch\\rcommand'/],
                              [['plan', tempScene({ version: 1 }), '--seed', '1\n2'], /--seed: '1\\n2' is not an integer/],
                              [['check', tempScene({ version: 1 }), '--checker', 'grid:\x1b]0;title\x07'], /grid:\\x1b\]0;title\\x07/]]) {
    const r = run(...args);
    assert.equal(r.status, 2, args.join(' '));
    const line = r.stderr.replace(/\n$/, '');
    assert.ok(!/[\x00-\x1f\x7f]/.test(line), `no control character in ${JSON.stringify(r.stderr)}`);
    assert.match(line, echo);
  }
  const key = tempScene('{"version": 1, "bad\\u001b[2Jkey\\nx": 1}');
  fails(/bad\\x1b\[2Jkey\\nx: unknown field/, 'validate', key);
});

test('a scene file is JSON, all of it: a NUL byte and garbage after the value are refused', () => {
  fails(/scene: not valid JSON \(a NUL byte at byte 13\)/, 'validate', tempScene('{"version":1}\0garbage'));
  fails(/scene: not valid JSON/, 'validate', tempScene('{"version":1} trailing'));
  fails(/scene: nested more than 64 levels deep/, 'validate',
        tempScene('{"version":1,"name":' + '['.repeat(100000) + ']'.repeat(100000) + '}'));
});
