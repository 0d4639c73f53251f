// Issue 27's hostile links and imports against the real page: workspaces too small to draw, heavy
// parameter sets, deep JSON. Before the fix the tiny workspaces crashed the wasm ("memory access
// out of bounds", 24 of 36 width/lesson combinations) and the heavy links froze or crashed it;
// now each is a notice, the lab keeps drawing, and long work runs in slices with a Cancel.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import zlib from 'node:zlib';
import { withBrowser, collectErrors, openLab, api, waitFrames, cli, tempJson, screenshot, refusal, pageButton } from './lib/harness.mjs';

const b64url = (data) => Buffer.from(data).toString('base64').replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
const sceneLink = (scene) => 'j.' + b64url(JSON.stringify(scene));

// 50 nested C-shaped bands of 256 vertices, open to the right, around a free middle: every
// band's box holds the whole workspace, so each configuration really costs its 12851 units (most
// scenes' boxes prune). A roadmap of 2000 samples takes 0.7 s natively, many frames' slices in
// the browser, within the lab's budgets (7.7e8 units expected).
function band(i, per = 32) {
  const o = 0.01 + i * 0.004, w = 0.002;
  const corners = [[1 - o, o], [o, o], [o, 1 - o], [1 - o, 1 - o], [1 - o, 1 - o - w], [o + w, 1 - o - w], [o + w, o + w], [1 - o, o + w]];
  const vertices = [];
  for (let k = 0; k < 8; ++k)
    for (let j = 0; j < per; ++j) {
      const [a, b] = [corners[k], corners[(k + 1) % 8]];
      vertices.push([a[0] + (b[0] - a[0]) * j / per, a[1] + (b[1] - a[1]) * j / per].map((v) => Math.round(v * 1e6) / 1e6));
    }
  return { type: 'polygon', vertices };
}
const BANDS = { version: 1, name: '50 nested bands', start: [0.3, 0.3], goal: [0.7, 0.7],
                obstacles: Array.from({ length: 50 }, (_, i) => band(i)) };
// For a link (64 KB at most, compressed): 128 vertices a band.
const LINK_BANDS = { ...BANDS, obstacles: Array.from({ length: 50 }, (_, i) => band(i, 16)) };
const zipped = (scene) => 'z.' + b64url(zlib.deflateRawSync(Buffer.from(JSON.stringify(scene)), { level: 9 }));

/** A fresh context (its own storage) and page at `path`; the lab must come up and keep drawing. */
async function open(browser, url, path) {
  const ctx = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await ctx.newPage();
  const errors = collectErrors(page);
  await openLab(page, url + path);
  await waitFrames(page, 5);
  return { ctx, page, errors };
}

test('workspaces 1e-15 to 5e-324 wide, by link in every lesson with a scene: a notice, never a crash',
  () => withBrowser(async ({ browser, url }) => {
  const lessons = { 'step-prm': 'point', collision: 'point', potential: 'point', analysis: 'point', torus: 'arm2' };
  let opened = 0;
  for (const width of [1e-15, 1e-100, 5e-324]) {
    for (const [lesson, robot] of Object.entries(lessons)) {
      const scene = { version: 1, workspace: { min: [0, 0], max: [width, width] } };
      if (robot === 'arm2') scene.robot = { type: 'arm2', base: [0, 0], lengths: [width / 4, width / 4] };
      const { ctx, page, errors } = await open(browser, url, `?lesson=${lesson}&scene=${sceneLink(scene)}`);
      const status = await api(page, 'status');
      assert.equal(status.lesson, lesson);
      assert.match(status.notice, /scene: workspace: each side must be at least 0\.001 long/, `${lesson} at ${width}`);
      // The lesson's own scene stands in, and a plain start of the same page is fine too.
      assert.ok((await api(page, 'get_scene')).workspace.max[0] >= 0.001);
      await page.goto(url);
      await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 3, null, { timeout: 30000 });
      assert.deepEqual(errors, [], `${lesson} at ${width}: no console error, no trap`);
      await ctx.close();
      ++opened;
    }
  }
  assert.equal(opened, 15);
}));

test('the same scenes through setScene and import-like API calls: refused with the reason, nothing changes',
  () => withBrowser(async ({ browser, url }) => {
  const { page, errors } = await open(browser, url, '?lesson=step-prm');
  const before = await api(page, 'get_scene');
  for (const max of [[1e-15, 1e-15], [1, 5e-324], [1000, 1]]) {
    const why = await refusal(page, 'setScene', { version: 1, workspace: { min: [0, 0], max }, goal: max });
    assert.match(why, /workspace: (each side must be at least 0\.001|one side may be at most 100 times)/);
  }
  assert.deepEqual(await api(page, 'get_scene'), before);
  // Parameters priced in a light scene do not carry over to a dense one: 20000 samples among 50
  // bands of 256 vertices (7.7e9 units) is refused as a scene, the parameters stay.
  await api(page, 'set_params', { params: { samples: 20000 } });
  assert.match(await refusal(page, 'setScene', BANDS), /^with these parameters this scene is too much for the lab: 20000 samples .* 4e\+09 units/);
  assert.deepEqual(await api(page, 'get_scene'), before);
  // A request nested 100000 deep, written by hand (JSON.stringify would not): refused, no trap.
  const deep = await page.evaluate(() => {
    const m = window.cspacelab.module;
    const text = '{"cmd":"set_scene","args":{"scene":' + '['.repeat(100000) + ']'.repeat(100000) + '}}';
    const size = m.lengthBytesUTF8(text) + 1;
    const ptr = m._malloc(size);
    m.stringToUTF8(text, ptr, size);
    const out = JSON.parse(m.UTF8ToString(m._csl_call(ptr)));
    m._free(ptr);
    return out;
  });
  assert.deepEqual(deep, { ok: false, error: 'request: nested more than 64 levels deep' });
  await waitFrames(page, 3);
  assert.deepEqual(errors, []);
}));

test('heavy links: refused by the budgets with the reason, or run in slices the page stays responsive through',
  () => withBrowser(async ({ browser, url }) => {
  // k = 1000 with 20000 samples: 2e7 pairs (the wasm ran out of memory). Refused; the rest applies.
  {
    const { ctx, page, errors } = await open(browser, url, '?lesson=step-prm&samples=20000&neighbors=k:1000&steps=99999999');
    const s = await api(page, 'status');
    assert.match(s.notice, /neighbors "k:1000" \(neighbors: k:1000 with 20000 samples means about 20002000 candidate pairs; the lab checks at most 1000000/);
    await page.waitForFunction(() => window.cspacelab.status().busy === null, null, { timeout: 60000 });
    const state = await api(page, 'state');
    assert.equal(state.done, true);
    assert.deepEqual(state.params, { samples: 20000, neighbors: 'k:10', checker: 'bisection', seed: 1, sampler: 'uniform' });
    assert.deepEqual(errors, []);
    await ctx.close();
  }
  // grid:1000000 with 2000 samples (no load event in 150 s): the work budget refuses the checker.
  {
    const { ctx, page, errors } = await open(browser, url, '?lesson=step-prm&samples=2000&checker=grid:1000000');
    assert.match((await api(page, 'status')).notice,
                 /checker "grid:1000000" \((2000 samples with k:10 and grid:1000000 mean about .* of work in this scene .* the lab takes at most 4e\+09 units|checker: one edge check with grid:1000000 means about .* the lab does at most 2e\+07 units at once)/);
    assert.equal((await api(page, 'state')).params.checker, 'bisection');
    assert.deepEqual(errors, []);
    await ctx.close();
  }
  // 4000 samples to the end among 50 bands of 128 vertices: allowed, so it runs over frames. The page loads at
  // once, shows its progress while frames keep coming, and ends with the roadmap the CLI builds.
  {
    const ctx = await browser.newContext({ viewport: { width: 1280, height: 800 } });
    const page = await ctx.newPage();
    const errors = collectErrors(page);
    const link = `?lesson=step-prm&scene=${zipped(LINK_BANDS)}&samples=4000&steps=99999999`;
    await page.goto(url + link);
    await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().busy, null, { polling: 'raf', timeout: 30000 });
    const busy = (await api(page, 'status')).busy;
    assert.equal(busy.lesson, 'step-prm');
    assert.match(busy.text, /to step 99999999/);
    await screenshot(page, 'hostile-heavy-link-running.png');
    // Frames go on while it runs (each does a slice of it): counted in the page, frame by frame.
    const run = await page.evaluate(async () => {
      const api = window.cspacelab;
      const first = api.status().frames;
      let worst = 0;
      while (api.status().busy) {
        await new Promise((r) => requestAnimationFrame(r));
        worst = Math.max(worst, api.status().cpu_ms.max);
      }
      return { frames: api.status().frames - first, worst };
    });
    assert.ok(run.frames >= 3, `${run.frames} frames were drawn while it ran`);
    const state = await api(page, 'state');
    assert.equal(state.done, true);
    const plan = cli('plan', tempJson(await api(page, 'get_scene')), '--samples', '4000');
    assert.equal(state.roadmap_hash, plan.roadmap_hash, 'the roadmap of cspacelab plan, bit for bit');
    console.log(`heavy link: ${run.frames} frames while it ran; the worst frame's CPU time so far: ${run.worst.toFixed(1)} ms`);
    // The state is saved at its target step, and a reload comes back to it (in slices again).
    await page.reload();
    await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2, null, { timeout: 30000 });
    await page.waitForFunction(() => window.cspacelab.status().busy === null, null, { timeout: 120000 });
    assert.equal((await api(page, 'state')).roadmap_hash, plan.roadmap_hash);
    assert.deepEqual(errors, []);
    await ctx.close();
  }
}));

test('a long run can be cancelled from the API, with Esc and with the panel\'s Cancel; it stays where it got to',
  () => withBrowser(async ({ browser, url }) => {
  const { page, errors } = await open(browser, url, '?lesson=step-prm');
  await api(page, 'set_scene', { scene: BANDS });
  await api(page, 'set_params', { params: { samples: 2000 } });
  // The API: started and stopped within one task, so no frame runs in between.
  const stopped = await page.evaluate(() => {
    const api = window.cspacelab;
    api.call('run', { background: true });
    const busy = api.status().busy;
    api.call('cancel');
    return { busy, after: api.status().busy, state: api.state() };
  });
  assert.ok(stopped.busy, 'running after the first slice');
  assert.equal(stopped.after, null);
  assert.equal(stopped.state.done, false, 'it stopped short of the end');
  assert.ok(stopped.state.steps > 0);
  // A step back replays in a second planner: cancelling it keeps the planner where it was. (From
  // well into the run, so that the replay takes more than its first slice.)
  stopped.state.steps = await api(page, 'run_to', { steps: 4000 });
  const back = await page.evaluate((steps) => {
    const api = window.cspacelab;
    api.call('step_back', { count: 5, background: true });
    const during = { busy: api.status().busy, steps: api.state().steps };
    api.call('cancel');
    return { during, steps: api.state().steps };
  }, stopped.state.steps);
  assert.ok(back.during.busy && /replaying to step/.test(back.during.busy.text), JSON.stringify(back.during));
  assert.equal(back.during.steps, stopped.state.steps, 'the planner on screen is still the one from before');
  assert.equal(back.steps, stopped.state.steps);
  // Esc, and the Cancel button under the progress bar, with real key and mouse events.
  for (const how of ['Escape', 'button']) {
    await page.evaluate(() => window.cspacelab.call('run', { background: true }));
    if (how === 'Escape') {
      await page.keyboard.press('Escape');
    } else {
      await waitFrames(page, 1);
      await screenshot(page, 'hostile-cancel-button.png');
      const at = await pageButton(page, 'cancel');
      assert.ok(at, 'the Cancel button is on screen while it runs');
      await page.mouse.click(at.x, at.y);
    }
    await waitFrames(page, 2);
    const s = await api(page, 'status');
    assert.equal(s.busy, null, `${how} stopped the run`);
    assert.equal((await api(page, 'state')).done, false);
  }
  assert.deepEqual(errors, []);
}));
