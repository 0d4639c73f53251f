// Lesson "PRM analysis" and "C-space notation" in the browser: a small experiment run to the
// end, a P9 point chosen with the mouse (its probability equal to the CLI's), and a student's
// answer typed and checked.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, chord, worldToPage, click, waitFrames, screenshot, inspectPng, api, cli, refusal,
         expectView, expectGolden } from './lib/harness.mjs';
import { boundProbes, p9Probes } from './lib/probes.mjs';
import { p9RightArea } from '../lib/p9.mjs';

test('PRM analysis: an experiment, and P9 by clicking', () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'analysis' });
  let s = await api(page, 'state');
  assert.equal(s.path_exists, true);
  assert.ok(s.length > 0.7 && s.clearance > 0 && s.clearance < 0.05, `L ${s.length}, r ${s.clearance}`);

  // A small experiment, run in the background of the frame loop, watched until it ends.
  await api(page, 'set_params', { params: { sample_counts: [10, 300], trials: 12, run: true } });
  await page.waitForFunction(() => !window.cspacelab.state().experiment.running, null, { timeout: 60000 });
  s = await api(page, 'state');
  assert.equal(s.experiment.rows.length, 2);
  for (const row of s.experiment.rows) {
    assert.equal(row.trials, 12);
    assert.ok(row.ci_low <= row.failure_rate && row.failure_rate <= row.ci_high);
  }
  assert.ok(s.experiment.rows[0].failures >= s.experiment.rows[1].failures);
  // The plot: each bound drawn where its formula, written here, puts it.
  await expectView(page, browser, 'analysis-bound.png', boundProbes(s), 'bound');

  // P9: click a point in the square; the exact probability is the CLI's.
  await api(page, 'set_params', { params: { tab: 'visibility' } });
  await waitFrames(page, 3);
  const [at] = await worldToPage(page, [[0.3, 0.2]], 'p9');
  await click(page, at);
  s = await api(page, 'state');
  const { scale } = await page.evaluate(() => window.cspacelab.view([], 'p9'));
  assert.ok(Math.abs(s.visibility.x - 0.3) <= 2 / scale && Math.abs(s.visibility.y - 0.2) <= 2 / scale);
  const v = cli('visibility', '--x', String(s.visibility.x), '--y', String(s.visibility.y), '--gap', String(s.visibility.gap));
  assert.equal(s.visibility.exact, v.exact);
  assert.ok(Math.abs(s.visibility.monte_carlo - v.exact) < 5 * Math.sqrt(v.exact * (1 - v.exact) / s.visibility.trials));
  await expectView(page, browser, 'analysis-p9.png', p9Probes(s.visibility), 'p9', { misses: 5 });

  // Each point, gap and sample count gets its own samples (a function of them and mc_seed).
  const here = (await api(page, 'state')).visibility;
  await api(page, 'set_params', { params: { mc_seed: here.mc_seed + 1 } });
  assert.notEqual((await api(page, 'state')).visibility.monte_carlo, here.monte_carlo, 'new samples');
  await api(page, 'set_params', { params: { mc_seed: here.mc_seed } });
  assert.equal((await api(page, 'state')).visibility.monte_carlo, here.monte_carlo, 'the same seed, the same samples');
}));

// The shaded region is exactly what (x1, y1) sees, also where the cone's clipped outline is not
// convex: both rays through the opening leave the square through its bottom edge.
test('PRM analysis: the P9 picture shades exactly the visible part of the right half',
  () => withPage({ viewport: { width: 1280, height: 800 } }, async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'analysis' });
  const [x1, y1, gap] = [0.45, 0.95, 0.1];
  await api(page, 'set_params', { params: { tab: 'visibility', point: [x1, y1], gap, mc_trials: 100 } });
  await page.mouse.move(5, 5);
  await waitFrames(page, 3);
  const lo = 0.5 - gap / 2, hi = 0.5 + gap / 2;
  const rayY = (end, x) => end + (end - y1) / (0.5 - x1) * (x - 0.5);
  const probes = [], expected = [];
  for (let x = 0.5025; x < 1; x += 0.01)
    for (let y = 0.0025; y < 1; y += 0.01) {
      // Away from the rays (the lines drawn over the shade), a grid line or the border.
      const near = (a, b) => Math.abs(a - b) < 0.004;
      if ([rayY(lo, x), rayY(hi, x), 0, 1].some((v) => near(v, y)) || near(x, 1)) continue;
      if (near(x % 0.05, 0) || near(x % 0.05, 0.05) || near(y % 0.05, 0) || near(y % 0.05, 0.05)) continue;
      probes.push([x, y]);
      expected.push(y >= rayY(lo, x) && y <= rayY(hi, x));
    }
  const at = await worldToPage(page, probes, 'p9');
  const dpr = await page.evaluate(() => window.devicePixelRatio);
  const { png } = await screenshot(page, 'analysis-p9-cone.png');
  const rgb = (await inspectPng(browser, png, at.map((p) => [p.x * dpr, p.y * dpr]))).at;
  // Shaded: the sky-blue tint (blue well above red); a sample's dot may cover a probe or two.
  const wrong = rgb.filter(([r, , b], i) => (b - r > 20) !== expected[i]).length;
  assert.ok(expected.filter(Boolean).length > 5 && expected.some((e) => !e), 'probes on both sides');
  assert.ok(wrong <= probes.length / 50, `${wrong} of ${probes.length} probes shaded wrongly`);
}));

// mu(B_1) in R^d: pi^(d/2) / Gamma(d/2 + 1), by the half-integer values of Gamma.
function unitBall(d) {
  // From Gamma(1) = 1 or Gamma(1/2) = sqrt(pi) up by Gamma(x + 1) = x Gamma(x).
  let [x, gamma] = d % 2 === 0 ? [1, 1] : [0.5, Math.sqrt(Math.PI)];
  for (; x < d / 2 + 1; x += 1) gamma *= x;
  return Math.PI ** (d / 2) / gamma;
}
const close = (a, b, rel = 1e-9) => Math.abs(a - b) <= rel * Math.max(1, Math.abs(b));

test('PRM analysis: P8 as the handout has it, then refined, against the path bound', () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'analysis' });
  assert.ok(close(unitBall(2), Math.PI, 1e-15) && close(unitBall(3), 4 / 3 * Math.PI, 1e-15) && close(unitBall(4), Math.PI ** 2 / 2, 1e-15));
  await api(page, 'set_params', { params: { tab: 'tiling' } });
  let s = await api(page, 'state');
  assert.equal(s.tab, 'tiling');
  assert.equal(s.target, 0.01, 'the default target');
  const check = (st) => {
    const { clearance: r, dimension: d, target: p } = st;
    // The handout's count: N per axis, N = ceil(max(2, sqrt d) / r), m = N^d.
    const N = Math.ceil(Math.max(2, Math.sqrt(d)) / r), m = N ** d;
    const sigma = unitBall(d) / 2 ** d, rate = sigma * r ** d;
    assert.equal(st.handout.per_axis, N);
    assert.equal(st.handout.m, m);
    assert.ok(close(st.handout.sigma, sigma, 1e-14), `sigma ${st.handout.sigma}`);
    assert.ok(close(st.handout.rate, rate, 1e-13));
    assert.equal(st.handout.target, p);
    assert.ok(close(st.handout.n_for_target, Math.log(m / p) / rate, 1e-12), `n ${st.handout.n_for_target}`);
    assert.ok(close(st.handout.bound_at_1000, m * Math.exp(-rate * 1000), 1e-12));
    // Refined: of the N centres (i + 1/2)/N per axis, E lie within min(r,1)/2 of a face; a ball
    // sticking out along j axes is hit at rate / 2^j. Solved for p by bisection here.
    let E = 0;
    for (let i = 0; i < N; ++i) if (Math.min((i + 0.5) / N, 1 - (i + 0.5) / N) <= Math.min(r, 1) / 2) ++E;
    assert.equal(st.refined.edge_per_axis, E);
    assert.equal(st.refined.boundary_balls, N ** d - (N - E) ** d);
    const hit = sigma * Math.min(r, 1) ** d;
    const refinedAt = (n) => {
      let sum = 0, choose = 1;
      for (let j = 0; j <= d; ++j) {
        if (j > 0) choose = choose * (d - j + 1) / j;
        sum += choose * E ** j * (N - E) ** (d - j) * Math.exp(-hit * n / 2 ** j);
      }
      return sum;
    };
    let [lo, hi] = [0, 1e9];
    for (let k = 0; k < 200; ++k) { const mid = (lo + hi) / 2; if (refinedAt(mid) > p) lo = mid; else hi = mid; }
    assert.ok(close(st.refined.n_for_target, hi, 1e-6), `refined n ${st.refined.n_for_target} against ${hi}`);
    assert.ok(close(st.refined.bound_at_1000, refinedAt(1000), 1e-9));
    assert.ok(close(st.tiling_bound_at_1000, refinedAt(1000), 1e-9));
    assert.ok(st.refined.n_for_target > st.handout.n_for_target, 'the faces cost samples');
    // The path bound beside them: m = ceil(L / (r/2)), sigma over mu(F).
    const mPath = Math.ceil(st.length / (r / 2)), ratePath = unitBall(d) / (2 ** d * st.free_volume) * r ** d;
    assert.equal(st.path.m, mPath);
    assert.ok(close(st.path.n_for_target, Math.log(mPath / p) / ratePath, 1e-12));
    assert.ok(st.path.n_for_target < st.handout.n_for_target, 'one path needs fewer samples than the whole cube');
    // The CLI agrees.
    const c = cli('bound', '--tiling', '--clearance', String(r), '--dim', String(d), '--samples', '1000', '--target', String(p));
    assert.equal(c.balls, m);
    assert.equal(c.interior_samples_for_target, st.handout.n_for_target);
    assert.equal(c.samples_for_target, st.refined.n_for_target);
  };
  check(s);
  // The wall-gap scene's numbers: about 2304 balls, p = 1% at about 8900 samples (17600 refined).
  assert.equal(s.handout.m, 2304);
  assert.ok(s.handout.n_for_target > 8800 && s.handout.n_for_target < 9000, `${s.handout.n_for_target}`);
  await expectView(page, browser, 'analysis-p8.png', boundProbes(s), 'bound');

  // Another target, another clearance: the numbers follow. A bad target changes nothing.
  await api(page, 'set_params', { params: { target: 0.001, clearance: 0.1 } });
  s = await api(page, 'state');
  assert.equal(s.target, 0.001);
  assert.equal(s.handout.m, 400);
  check(s);
  assert.equal((await api(page, 'snapshot')).params.target, 0.001, 'params() carries the target');
  for (const bad of [0, 1, -0.5, 1.5, 'x', null]) {
    assert.match(await refusal(page, 'setParams', { target: bad }), /target: a failure probability p with 0 < p < 1/);
  }
  assert.match(await refusal(page, 'setParams', { target: 0.05, tab: 'nope' }), /tab:/);
  assert.equal((await api(page, 'state')).target, 0.001, 'refused: unchanged');
}));

// P9's exact value: the left half and the right half's part seen through the gap, by polygon
// clipping apart from the lab (tests/lib/p9.mjs).
const p9Exact = (x1, y1, gap) => 0.5 + p9RightArea(x1, y1, gap);

test('PRM analysis: P9 by cases, and the default draw holds the exact value', () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'analysis' });
  await api(page, 'set_params', { params: { tab: 'visibility' } });
  let v = (await api(page, 'state')).visibility;
  // The first view: its Monte Carlo interval holds the exact value (a miss looked like an error).
  assert.deepEqual([v.x, v.y, v.gap], [0.25, 0.3, 0.1]);
  assert.ok(Math.abs(v.exact - p9Exact(0.25, 0.3, 0.1)) < 1e-12);
  assert.ok(v.ci_low <= v.exact && v.exact <= v.ci_high, `default draw [${v.ci_low}, ${v.ci_high}] against ${v.exact}`);
  assert.equal(v.within_ci, true);
  assert.equal(v.case, 'top/right edge');
  await expectView(page, browser, 'analysis-p9-cases.png', p9Probes(v), 'p9', { misses: 5 });

  // Every case, clicked with the mouse: the breakdown's rays, areas and probability against
  // what is computed here.
  const cases = [[0.3, 0.2, 0.2, 'top/right edge'], [0.45, 0.5, 0.2, 'top/bottom'], [0.45, 0.95, 0.1, 'bottom/bottom'],
                 [0.1, 0.5, 0.1, 'right edge/right edge'], [0.4, 0.1, 0.2, 'top/top'], [0.2, 0.9, 0.4, 'right edge/bottom']];
  const exitOf = (a, slope) => (a + slope / 2 > 1 ? 'top' : a + slope / 2 < 0 ? 'bottom' : 'right edge');
  for (const [x, y, gap, name] of cases) {
    await api(page, 'set_params', { params: { gap } });
    await waitFrames(page, 2);
    const [at] = await worldToPage(page, [[x, y]], 'p9');
    await click(page, at);
    v = (await api(page, 'state')).visibility;
    const { x: x1, y: y1 } = v;
    assert.ok(Math.abs(x1 - x) < 0.01 && Math.abs(y1 - y) < 0.01, `clicked (${x1}, ${y1})`);
    const up = (0.5 + gap / 2 - y1) / (0.5 - x1), low = (0.5 - gap / 2 - y1) / (0.5 - x1);
    assert.equal(v.case, name, `(${x1}, ${y1}) gap ${gap}`);
    assert.equal(v.upper.exit, exitOf(0.5 + gap / 2, up));
    assert.equal(v.lower.exit, exitOf(0.5 - gap / 2, low));
    assert.ok(Math.abs(v.upper.slope - up) < 1e-9 * Math.max(1, Math.abs(up)));
    assert.ok(Math.abs(v.lower.slope - low) < 1e-9 * Math.max(1, Math.abs(low)));
    const exact = p9Exact(x1, y1, gap);
    assert.ok(Math.abs(v.probability - exact) < 1e-12, `${v.probability} against ${exact}`);
    assert.ok(Math.abs(v.exact - exact) < 1e-12);
    assert.ok(Math.abs(v.left_area + v.upper.area_under - v.lower.area_under - exact) < 1e-12);
    assert.equal(v.within_ci, v.ci_low <= v.exact && v.exact <= v.ci_high);
  }
  // A fine count of the right half seen from the last point, as a second opinion.
  let seen = 0;
  const k = 400;
  for (let i = 0; i < k; ++i)
    for (let j = 0; j < k; ++j) {
      const x2 = 0.5 + (i + 0.5) / (2 * k), y2 = (j + 0.5) / k;
      const yw = v.y + (y2 - v.y) * (0.5 - v.x) / (x2 - v.x);
      if (Math.abs(yw - 0.5) <= v.gap / 2) ++seen;
    }
  assert.ok(Math.abs(0.5 + seen / (2 * k * k) - v.exact) < 3e-3);
}));

// The same panels in a 900 px wide embed: the key numbers in view without scrolling.
test('PRM analysis: P8 and P9 in a 900 px embed', () => withPage({ viewport: { width: 900, height: 640 },
  open: 'embed.html?lesson=analysis&tab=tiling' }, async ({ page, browser }) => {
  let s = await api(page, 'state');
  assert.equal(s.tab, 'tiling');
  await expectView(page, browser, 'analysis-p8-embed.png', boundProbes(s), 'bound');
  await api(page, 'set_params', { params: { tab: 'visibility' } });
  s = await api(page, 'state');
  await expectView(page, browser, 'analysis-p9-embed.png', p9Probes(s.visibility), 'p9', { misses: 5 });
  assert.equal(s.visibility.within_ci, true);
}));

// Types an answer into the field that has the keyboard, submits it with Enter: the state after.
async function answer(page, text) {
  await page.keyboard.type(text, { delay: 30 });
  await page.keyboard.press('Enter');
  await waitFrames(page, 3);
  return api(page, 'state');
}

test('C-space notation: build a robot, then answer an exercise with the keyboard',
  () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'notation' });
  await api(page, 'set_params', { params: { description: 'base=planar joints=RRR wrist=spherical' } });
  let s = await api(page, 'state');
  assert.equal(s.notation, 'SE(2) x T^6');
  assert.equal(s.dimension, 9);
  const fromCli = cli('cspace-of', 'base=planar joints=RRR wrist=spherical');
  assert.equal(s.notation, fromCli.notation);

  // Practice: exercise 2 (a 3R arm). The answer field has the keyboard: type a wrong answer
  // and Enter, then a right one.
  await api(page, 'set_params', { params: { mode: 'practice', exercise: 1 } });
  await waitFrames(page, 3);
  s = await answer(page, 'S^2 x S^1');
  assert.equal(s.answer, 'S^2 x S^1');
  assert.equal(s.check.correct, false);
  assert.match(s.check.explanation, /S\^2/);
  await waitFrames(page, 2);
  await chord(page, 'Control', 'a');  // select all: the next keys replace the answer
  s = await answer(page, 'T^3');
  assert.equal(s.answer, 'T^3');
  assert.equal(s.check.correct, true);
  // The 3R arm of the exercise, and the surfaces beside it, against references.
  await expectGolden(page, browser, 'notation-practice-3r', 'notation-picture');
  await expectGolden(page, browser, 'notation-surfaces', 'notation-surfaces');
}));
