// Lesson "Compare planners" in the browser: two planners of the planner choice on the same
// scene and seed, stepped together (the keys and the API), stepped back (a replay gives the
// identical state), run to the end (both find a path whose ends are the start and goal, its
// length the sum of its edges), the passage's width as a parameter that rebuilds the scene, and
// the experiment, whose plot is drawn where its success rates put it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, waitFrames, screenshot, api, refusal } from './lib/harness.mjs';

const dist = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1]);

// Pixels of two screenshots (PNG bytes) that differ inside a rectangle of device pixels.
async function changedPixels(browser, before, after, [x0, y0, x1, y1]) {
  const page = await browser.newPage();
  try {
    return await page.evaluate(async ({ a, b, box }) => {
      const decode = async (b64) => {
        const img = new Image();
        img.src = 'data:image/png;base64,' + b64;
        await img.decode();
        const c = new OffscreenCanvas(img.width, img.height);
        const ctx = c.getContext('2d');
        ctx.drawImage(img, 0, 0);
        return { w: img.width, data: ctx.getImageData(0, 0, img.width, img.height).data };
      };
      const [p, q] = [await decode(a), await decode(b)];
      let changed = 0;
      for (let y = Math.max(0, Math.floor(box[1])); y < Math.floor(box[3]); ++y)
        for (let x = Math.max(0, Math.floor(box[0])); x < Math.floor(box[2]); ++x) {
          const i = 4 * (y * p.w + x);
          if (Math.abs(p.data[i] - q.data[i]) + Math.abs(p.data[i + 1] - q.data[i + 1]) +
              Math.abs(p.data[i + 2] - q.data[i + 2]) > 24) ++changed;
        }
      return changed;
    }, { a: before.toString('base64'), b: after.toString('base64'), box: [x0, y0, x1, y1] });
  } finally {
    await page.close();
  }
}

test('Compare planners: step both, step back, run to the end, the passage, the experiment\'s plot',
  () => withPage({ open: '?lesson=compare' }, async ({ page, browser }) => {
  assert.equal((await api(page, 'status')).lesson, 'compare');
  // The planners offered are the planner choice's table (the CLI's --planner lists the same).
  const specs = await api(page, 'param_specs');
  const planners = specs.find((s) => s.name === 'planner_a');
  assert.equal(planners.kind, 'choice');
  for (const name of ['prm', 'prm-star', 'rrt', 'rrt-connect']) assert.ok(planners.choices.includes(name), name);
  assert.deepEqual(specs.find((s) => s.name === 'planner_b').choices, planners.choices);

  // The default scene (the narrow passage, w = 0.08) and parameters (300 samples each, seed 1).
  await api(page, 'set_params', { params: { planner_a: 'prm', planner_b: 'rrt-connect' } });
  assert.equal((await api(page, 'state')).params.passage, 0.08);
  const s0 = await api(page, 'state');
  assert.equal(s0.steps, 0);
  assert.deepEqual(s0.planners.map((p) => p.planner), ['prm', 'rrt-connect']);
  assert.deepEqual(s0.planners.map((p) => p.steps), [0, 0]);

  // Step both with the key '.' (one step each a press), then with the API.
  await page.mouse.move(700, 400);
  for (let i = 0; i < 5; ++i) await page.keyboard.press('.');
  await page.waitForFunction(() => window.cspacelab.state().steps >= 5, null, { timeout: 30000 });
  const s5 = await api(page, 'state');
  assert.equal(s5.steps, 5);
  assert.deepEqual(s5.planners.map((p) => p.steps), [5, 5], 'both planners advanced in sync');
  await api(page, 'step', { count: 25 });
  const s30 = await api(page, 'state');
  assert.deepEqual(s30.planners.map((p) => p.steps), [30, 30]);
  for (const p of s30.planners) assert.ok(p.samples > 0, `${p.planner}: samples drawn`);
  assert.ok(s30.planners[1].evaluations > 0, "rrt-connect checked its extensions");
  // PRM's first steps draw samples: each is a vertex (after the two endpoints) or rejected.
  const prm = s30.planners[0];
  assert.equal(prm.samples, prm.nodes - 2 + prm.rejected);
  // Its collision checks so far, counted by hand from what it drew: the two endpoints' tests,
  // one test per uniform sample, and each kept sample's clearance (the exact checker keeps
  // every vertex's). Its own "evaluations" (the CLI's) leave all of these out.
  assert.equal(prm.configurations_tested, 2 + prm.samples + (prm.nodes - 2));
  assert.equal(prm.evaluations, 0);
  assert.ok(s30.planners[1].configurations_tested >= s30.planners[1].evaluations);
  // More steps, then back: the state at 30 exactly, for both.
  await api(page, 'step', { count: 12 });
  assert.equal((await api(page, 'state')).steps, 42);
  await api(page, 'run_to', { steps: 31 });
  await api(page, 'step_back');
  const back = await api(page, 'state');
  assert.deepEqual(back, s30, 'stepping back gives the identical state');

  // Run to the end: both find a path from start to goal in the default narrow passage.
  await api(page, 'run');
  const end = await api(page, 'state', { roadmap: true });
  assert.equal(end.done, true);
  const scene = await api(page, 'get_scene');
  for (const p of end.planners) {
    assert.equal(p.done, true, p.planner);
    assert.equal(p.solved, true, `${p.planner} found a path`);
    const q = p.path;  // the path's configurations
    assert.ok(q.length >= 2 && q.every((v) => p.vertices.some((w) => w[0] === v[0] && w[1] === v[1])), 'through vertices');
    assert.deepEqual(q[0], scene.start, `${p.planner}: the path starts at the start`);
    assert.deepEqual(q.at(-1), scene.goal, `${p.planner}: and ends at the goal`);
    let length = 0;
    for (let i = 1; i < q.length; ++i) length += dist(q[i - 1], q[i]);
    assert.ok(p.path_length > dist(scene.start, scene.goal) - 1e-12, 'no shorter than the straight line');
    assert.ok(Math.abs(p.path_length - length) < 1e-9, `${p.planner}: its length is the sum of its edges`);
  }
  await waitFrames(page, 3);
  // The table's "collision checks" column shows configurations_tested (compare-run.png).
  await screenshot(page, 'compare-run.png');
  // PRM's counts its samples' tests beside its edge checks'; RRT-Connect's evaluations count
  // each new end already.
  assert.ok(end.planners[0].configurations_tested >= end.planners[0].evaluations + end.planners[0].samples);
  assert.ok(end.planners[1].configurations_tested >= end.planners[1].evaluations);
  // The two ran on the same scene with the same seed: a second run gives the same numbers.
  await api(page, 'reset');
  await api(page, 'run');
  const again = await api(page, 'state');
  assert.deepEqual(again.planners.map((p) => [p.steps, p.roadmap_hash, p.path_length]),
                   end.planners.map((p) => [p.steps, p.roadmap_hash, p.path_length]));
  const log = await api(page, 'log');
  assert.ok(log.length > 0);

  // The passage's width rebuilds the scene: the wall's two pieces leave a gap of exactly w.
  const gap = (sc) => {
    const [lower, upper] = sc.obstacles.map((o) => o.vertices.map((v) => v[1]));
    return Math.min(...upper) - Math.max(...lower);
  };
  assert.ok(Math.abs(gap(scene) - 0.08) < 1e-12);
  await api(page, 'set_params', { params: { passage: 0.03 } });
  const narrow = await api(page, 'get_scene');
  assert.ok(Math.abs(gap(narrow) - 0.03) < 1e-12, 'the gap follows the parameter');
  assert.equal((await api(page, 'state')).steps, 0, 'a new scene starts both planners again');
  assert.match(await refusal(page, 'setParams', { passage: 0.9 }), /passage/);
  assert.ok(Math.abs(gap(await api(page, 'get_scene')) - 0.03) < 1e-12, 'a refused width changes nothing');
  assert.match(await api(page, 'describe'), /Planner A, prm: .*Planner B, rrt-connect: /);
  // A scene of the student's, restored with its parameters (as a link or a snapshot does: the
  // scene first), stays: the passage is then the slider's value alone.
  const own = { version: 1, name: 'my maze', workspace: { min: [0, 0], max: [1, 1] }, robot: { type: 'point' },
                obstacles: [{ type: 'disk', center: [0.5, 0.5], radius: 0.2 }], start: [0.1, 0.1], goal: [0.9, 0.9] };
  const snap = await api(page, 'snapshot');
  await api(page, 'restore', { ...snap, scene: own, params: { ...snap.params, passage: 0.05 } });
  const kept = await api(page, 'get_scene');
  assert.deepEqual(kept.obstacles, own.obstacles, 'the restored scene is not replaced by the passage');
  assert.equal((await api(page, 'state')).params.passage, 0.05);
  await api(page, 'set_params', { params: { passage: 0.03 } });
  assert.deepEqual((await api(page, 'get_scene')).obstacles, own.obstacles, 'nor by a later passage from the API');
  // The passage's own scene back (its width is the slider's, 0.03): the passage rebuilds it again.
  await api(page, 'set_scene', { scene: narrow });

  // The experiment: the plot before, run, the plot after.
  await api(page, 'set_params', { params: { mode: 'experiment', passage: 0.12, trials: 6, budgets: [20, 60, 200] } });
  await waitFrames(page, 3);
  const plotBox = async () => {
    const layout = (await api(page, 'status')).layout;
    const v = layout.views.find((x) => x.name === 'success');
    assert.ok(v, 'the plot is on screen');
    return v;
  };
  const { png: before } = await screenshot(page, 'compare-plot-empty.png');
  // Over frames, with progress, so the page goes on drawing (Cancel would stop it).
  // (Asked and looked at in one task of the page: no frame runs between.)
  const busy = await page.evaluate(() => {
    window.cspacelab.call('set_params', { params: { run: true }, background: true });
    return window.cspacelab.status().busy;
  });
  assert.ok(busy && busy.lesson === 'compare' && busy.progress < 1, 'the experiment runs over frames');
  await page.waitForFunction(() => !window.cspacelab.status().busy, null, { timeout: 120000 });
  await waitFrames(page, 3);
  const st = await api(page, 'state');
  assert.equal(st.experiment.done, true);
  assert.equal(st.experiment.planners.length, 2);
  for (const p of st.experiment.planners) {
    assert.deepEqual(p.rates.map((r) => r.samples), [20, 60, 200]);
    for (const r of p.rates) {
      assert.equal(r.trials, 6);
      // The mean collision checks per run: at least one test per sample drawn.
      assert.ok(r.configurations_tested >= 1, `${p.planner} at ${r.samples}: checks counted`);
      assert.ok(r.success_rate >= 0 && r.success_rate <= 1, `${p.planner} at ${r.samples}: a rate`);
      assert.ok(Math.abs(r.success_rate - r.successes / r.trials) < 1e-12);
    }
  }
  // An experiment past the lab's bound is refused before anything changes: 100 x 3 x 20000 samples.
  assert.match(await refusal(page, 'setParams', { budgets: [20000, 20000, 20000], trials: 100, run: true }),
               /would draw 6000000 samples for each planner .* at most 400000/);
  assert.equal((await api(page, 'state')).params.trials, 6);
  const { png: after } = await screenshot(page, 'compare-plot.png');
  const box = await plotBox();
  const canvas = await page.locator('canvas').boundingBox();
  const dpr = await page.evaluate(() => window.devicePixelRatio);
  const rect = [(canvas.x + box.x) * dpr, (canvas.y + box.y) * dpr, (canvas.x + box.x + box.w) * dpr,
                (canvas.y + box.y + box.h) * dpr];
  const changed = await changedPixels(browser, before, after, rect);
  assert.ok(changed > 200, `the plot drew its lines and points (${changed} pixels changed)`);
  // Each measured point is drawn where the plot maps it: the pixels around it changed.
  for (const p of st.experiment.planners)
    for (const r of p.rates) {
      const { points: [[x, y]] } = await api(page, 'view', { view: 'success', points: [[r.samples, r.success_rate]] });
      const around = [(canvas.x + x - 4) * dpr, (canvas.y + y - 4) * dpr, (canvas.x + x + 4) * dpr, (canvas.y + y + 4) * dpr];
      assert.ok(await changedPixels(browser, before, after, around) > 0, `${p.planner} at ${r.samples}: drawn`);
    }
  // Against collision checks: each point moves to its runs' mean configurations_tested.
  assert.equal((await api(page, 'state')).params.axis, 'samples');
  assert.match(await refusal(page, 'setParams', { axis: 'time' }), /axis: "samples" or "checks"/);
  await api(page, 'set_params', { params: { axis: 'checks' } });
  assert.equal((await api(page, 'state')).params.axis, 'checks');
  await waitFrames(page, 3);
  const { png: checks } = await screenshot(page, 'compare-plot-checks.png');
  for (const p of st.experiment.planners)
    for (const r of p.rates) {
      const { points: [[x, y]] } =
        await api(page, 'view', { view: 'success', points: [[r.configurations_tested, r.success_rate]] });
      assert.ok(x >= box.x && x <= box.x + box.w, `${p.planner} at ${r.samples}: on the plot's x range`);
      const around = [(canvas.x + x - 4) * dpr, (canvas.y + y - 4) * dpr, (canvas.x + x + 4) * dpr, (canvas.y + y + 4) * dpr];
      assert.ok(await changedPixels(browser, before, checks, around) > 0,
                `${p.planner} at ${r.configurations_tested.toFixed(0)} checks: drawn`);
    }
}));
