// Lesson "PRM analysis" and "C-space notation" in the browser: a small experiment run to the
// end, a P9 point chosen with the mouse (its probability equal to the CLI's), and a student's
// answer typed and checked.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, chord, worldToPage, click, waitFrames, screenshot, inspectPng, api, cli } from './lib/harness.mjs';

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
  const shot1 = await screenshot(page, 'analysis-bound.png');
  assert.ok((await inspectPng(browser, shot1.png)).colours > 30);

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
  await page.mouse.move(5, 5);
  const shot2 = await screenshot(page, 'analysis-p9.png');
  assert.ok((await inspectPng(browser, shot2.png)).colours > 20);

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
  const shot = await screenshot(page, 'notation.png');
  assert.ok((await inspectPng(browser, shot.png)).colours > 30);
}));
