// cspacelab homework / exercise: the contract (fields, no answer before --check, exit statuses)
// and the answers checked against numbers computed here from the handout's definitions.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';

const CLI = process.env.CSPACELAB_CLI;
const run = (...args) => spawnSync(CLI, args, { encoding: 'utf8' });
const json = (...args) => {
  const r = run(...args);
  assert.equal(r.status, 0, `${args.join(' ')}: ${r.stderr}`);
  return JSON.parse(r.stdout);
};

// P9: the left half, plus the right half's part inside the cone from (x, y) through the gap,
// clipped to the square (a midpoint rule over x2 in [1/2, 1]).
function visibility(x, y, d) {
  const lo = 0.5 - d / 2, hi = 0.5 + d / 2, steps = 20000;
  let area = 0;
  for (let i = 0; i < steps; ++i) {
    const x2 = 0.5 + (i + 0.5) / steps / 2;
    const s = (x2 - x) / (0.5 - x);
    const a = Math.max(0, y + (lo - y) * s), b = Math.min(1, y + (hi - y) * s);
    area += Math.max(0, b - a) / steps / 2;
  }
  return 0.5 + area;
}
function segmentDisk(p1, p2, q, r) {
  let best = Infinity;
  for (let i = 0; i <= 100000; ++i) {
    const t = i / 100000;
    best = Math.min(best, Math.hypot(p1[0] + t * (p2[0] - p1[0]) - q[0], p1[1] + t * (p2[1] - p1[1]) - q[1]));
  }
  return Math.max(0, best - r);
}
function s1(q1, q2) {
  let best = Infinity;
  for (let k = -4; k <= 4; ++k) best = Math.min(best, Math.abs(q2 - q1 + 2 * Math.PI * k));
  return best;
}
function minGrid(p, q, c, r) {
  for (let n = 2; n < 100000; ++n)
    for (let i = 0; i < n; ++i) {
      const t = i / (n - 1);
      if (Math.hypot(p[0] + t * (q[0] - p[0]) - c[0], p[1] + t * (q[1] - p[1]) - c[1]) <= r) return n;
    }
  return null;
}

test('homework lists P1-P13 with their lessons', () => {
  const list = json('homework');
  assert.deepEqual(list.map((p) => p.id), Array.from({ length: 13 }, (_, i) => 'P' + (i + 1)));
  for (const p of list) {
    assert.ok(p.title.length > 10 && p.task.length > 20, p.id);
    assert.match(p.lesson, /^[a-z0-9-]+$/);
  }
  assert.equal(list[9].lesson, 'distances');
  assert.equal(list[11].lesson, 'collision');
});

test('exercise: the contract\'s fields, no answer until --check, the same for the same seed', () => {
  for (let i = 1; i <= 13; ++i) {
    const e = json('exercise', 'P' + i, '--seed', '42');
    assert.deepEqual(Object.keys(e).sort(), ['answer_format', 'format_hint', 'given', 'id', 'prompt', 'seed']);
    assert.equal(e.id, 'P' + i);
    assert.equal(e.seed, 42);
    assert.ok(['number', 'integer', 'notation'].includes(e.answer_format));
    assert.deepEqual(json('exercise', 'p' + i, '--seed', '42'), e, 'p10 and P10 alike');
  }
  assert.deepEqual(Object.keys(json('exercise', 'P9', '--seed', '5').given).sort(), ['d', 'x', 'y']);
  assert.deepEqual(Object.keys(json('exercise', 'P10', '--seed', '5').given).sort(), ['q1', 'q2']);
  assert.deepEqual(Object.keys(json('exercise', 'P11', '--seed', '5').given).sort(), ['p1', 'p2', 'q', 'r']);
  assert.deepEqual(Object.keys(json('exercise', 'P12', '--seed', '5').given).sort(), ['center', 'p', 'q', 'radius']);
  assert.notDeepEqual(json('exercise', 'P10', '--seed', '1').given, json('exercise', 'P10', '--seed', '2').given);
  assert.equal(json('exercise', 'P10').seed, 1, 'seed 1 by default');
});

test('exercise --check: right and wrong answers, against numbers computed here', () => {
  for (let seed = 0; seed < 12; ++seed) {
    let e = json('exercise', 'P9', '--seed', String(seed));
    const v = visibility(e.given.x, e.given.y, e.given.d);
    let c = json('exercise', 'P9', '--seed', String(seed), '--check', v.toFixed(4));
    assert.equal(c.correct, true, `P9 seed ${seed}: ${v} vs ${c.expected}`);
    assert.ok(Math.abs(c.expected - v) < 1e-4);
    assert.equal(json('exercise', 'P9', '--seed', String(seed), '--check', (v + 0.01).toFixed(4)).correct, false);

    e = json('exercise', 'P10', '--seed', String(seed));
    const d = s1(e.given.q1, e.given.q2);
    assert.equal(json('exercise', 'P10', '--seed', String(seed), '--check', d.toFixed(4)).correct, true);
    assert.equal(json('exercise', 'P10', '--seed', String(seed), '--check', (d + 0.02).toFixed(4)).correct, false);

    e = json('exercise', 'P11', '--seed', String(seed));
    const g = e.given;
    const dist = segmentDisk(g.p1, g.p2, g.q, g.r);
    c = json('exercise', 'P11', '--seed', String(seed), '--check', dist.toFixed(4));
    assert.equal(c.correct, true, `P11 seed ${seed}: ${dist} vs ${c.expected}`);

    e = json('exercise', 'P12', '--seed', String(seed));
    const n = minGrid(e.given.p, e.given.q, e.given.center, e.given.radius);
    assert.equal(json('exercise', 'P12', '--seed', String(seed), '--check', String(n)).correct, true);
    c = json('exercise', 'P12', '--seed', String(seed), '--check', String(n - 1));
    assert.equal(c.correct, false);
    assert.equal(c.expected, n);
  }
  // pi forms, and notation with the course's spellings.
  const e = json('exercise', 'P10', '--seed', '3');
  const d = s1(e.given.q1, e.given.q2);
  assert.equal(json('exercise', 'P10', '--seed', '3', '--check', `${(d / Math.PI).toFixed(5)}pi`).correct, true);
  const p7 = json('exercise', 'P7', '--check', 'SE(2) × T⁶');
  assert.equal(p7.correct, true, p7.explanation);
  assert.equal(p7.expected, 'SE(2) x T^6');
  const p6 = json('exercise', 'P6', '--check', 'SO(3) x SO(3)');
  assert.equal(p6.correct, false);
});

test('exercise: bad input is a one-line error (exit 2); a wrong or unreadable answer is not', () => {
  for (const args of [['exercise'], ['exercise', 'P14'], ['exercise', 'P0'], ['exercise', 'x'],
                      ['exercise', 'P1', '--seed', '-1'], ['exercise', 'P1', '--seed', '9007199254740992'],
                      ['exercise', 'P1', '--seed', '1.5'], ['exercise', 'P1', '--bogus'], ['homework', 'x']]) {
    const r = run(...args);
    assert.equal(r.status, 2, args.join(' '));
    assert.equal(r.stdout, '');
    assert.equal(r.stderr.trim().split('\n').length, 1, args.join(' '));
  }
  for (const answer of ['', 'abc', '1e999', 'nan', '1/0', 'x'.repeat(5000)]) {
    const c = json('exercise', 'P10', '--check', answer);
    assert.equal(c.correct, false, answer.slice(0, 10));
    assert.ok(c.explanation.length > 10);
  }
  assert.match(run('exercise', '--help').stdout, /--check ANSWER/);
  assert.match(run('--help').stdout, /homework/);
});
