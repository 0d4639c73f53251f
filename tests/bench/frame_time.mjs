// Frame time in the browser (a benchmark, not a test).
//   node tests/bench/frame_time.mjs roadmap [samples=5000]   Step PRM with a large roadmap on screen
//   node tests/bench/frame_time.mjs torus-drag                 the torus lesson while an obstacle is dragged
//   node tests/bench/frame_time.mjs potential                  P13's rectangle descending (its slice's heat
//                                                              map, 97 x 97 potentials, redone every step)
//   node tests/bench/frame_time.mjs phone [samples=2000]       a phone upright (390 x 844 CSS px, pixel ratio 3,
//                                                              touch, the compact layout): Step PRM's roadmap
//                                                              and the torus lesson (3.4 M device pixels)
//   node tests/bench/frame_time.mjs cspace-3d [robot=polygon|arm]  C-spaces in 3-D: the block idle, turned by a
//                                                              drag, and its cut plane scrubbed (PRM's roadmap drawn)
//   node tests/bench/frame_time.mjs heavy-link                 links that start long runs (issue 27): every
//                                                              frame from the first until the run is done
// Headless Chromium renders WebGL with SwiftShader, on the CPU: the browser's frame interval
// here is far above what a GPU gives. The app's own CPU time per frame (building the UI and
// its geometry, before GL) is the figure that carries over to students' machines.
import zlib from 'node:zlib';
import { startServer, launchBrowser, openLab, api, worldToPage, waitFrames } from '../e2e/lib/harness.mjs';

const scenario = process.argv[2] || 'roadmap';
const { server, url } = await startServer();
const browser = await launchBrowser();

async function measure(page, during) {
  const rafPromise = page.evaluate(() => new Promise((resolve) => {
    const times = [];
    const tick = (t) => {
      times.push(t);
      if (t - times[0] < 3000) requestAnimationFrame(tick);
      else resolve(times.slice(1).map((x, i) => x - times[i]));
    };
    requestAnimationFrame(tick);
  }));
  if (during) await during();
  const intervals = (await rafPromise).sort((a, b) => a - b);
  const status = await api(page, 'status');
  const mean = intervals.reduce((a, b) => a + b, 0) / intervals.length;
  console.log(`browser frames: ${intervals.length} in 3 s, mean ${mean.toFixed(2)} ms (${(1000 / mean).toFixed(1)} fps), ` +
              `p95 ${intervals[Math.floor(intervals.length * 0.95)].toFixed(2)} ms`);
  console.log(`app CPU per frame (UI + GL submission): mean ${status.cpu_ms.mean.toFixed(2)} ms, p95 ${status.cpu_ms.p95.toFixed(2)} ms`);
  console.log(`  of which building the UI: mean ${status.ui_ms.mean.toFixed(2)} ms, p95 ${status.ui_ms.p95.toFixed(2)} ms, ` +
              `max ${status.ui_ms.max.toFixed(2)} ms; ${status.vertices} vertices`);
}

try {
  const page = scenario === 'phone'
    ? await (await browser.newContext({ viewport: { width: 390, height: 844 }, deviceScaleFactor: 3, hasTouch: true, isMobile: true })).newPage()
    : await browser.newPage({ viewport: { width: 1280, height: 800 } });
  await openLab(page, url);
  if (scenario === 'phone') {
    const samples = Number(process.argv[3] || 2000);
    await api(page, 'select_lesson', { id: 'step-prm' });
    await api(page, 'set_params', { params: { samples, neighbors: 'k:10', seed: 1 } });
    await api(page, 'run');
    const s = await api(page, 'state');
    const layout = (await api(page, 'status')).layout;
    console.log(`phone, ${layout.mode} layout: Step PRM, ${s.nodes} vertices, ${s.edges} edges (n = ${samples})`);
    await page.waitForTimeout(1000);
    await measure(page);
    await api(page, 'select_lesson', { id: 'torus' });
    await page.waitForTimeout(1000);
    console.log('phone: the torus lesson (arm and C-space square stacked)');
    await measure(page);
  } else if (scenario === 'roadmap') {
    const samples = Number(process.argv[3] || 5000);
    await api(page, 'select_lesson', { id: 'step-prm' });
    await api(page, 'set_params', { params: { samples, neighbors: 'k:10', seed: 1 } });
    await api(page, 'run');
    const s = await api(page, 'state');
    console.log(`Step PRM: roadmap of ${s.nodes} vertices, ${s.edges} edges (n = ${samples})`);
    await page.waitForTimeout(1000);
    await measure(page);
  } else if (scenario === 'torus-drag') {
    await api(page, 'select_lesson', { id: 'torus' });
    // 20 obstacles around the arm, as in the performance target.
    const obstacles = [];
    for (let i = 0; i < 20; ++i) {
      const a = (i / 20) * 2 * Math.PI, r = 0.3 + 0.12 * (i % 3);
      obstacles.push({ type: 'disk', center: [0.5 + r * Math.cos(a), 0.5 + r * Math.sin(a)], radius: 0.02 + 0.01 * (i % 4) });
    }
    await api(page, 'set_scene', { scene: { version: 1, robot: { type: 'arm2', base: [0.5, 0.5], lengths: [0.3, 0.25] },
                                            obstacles, start: [0.3, 0.2], goal: [2.0, -0.5] } });
    await api(page, 'set_params', { params: { view: 'square' } });
    await waitFrames(page, 5);
    const [grab] = await worldToPage(page, [obstacles[0].center], 'workspace');
    await page.mouse.move(grab.x, grab.y);
    await page.keyboard.press('v');
    await page.mouse.down();
    console.log('torus lesson, 20 obstacles, one dragged in circles for 3 s');
    await measure(page, async () => {
      for (let i = 0; i < 150; ++i) {
        await page.mouse.move(grab.x + 30 * Math.sin(i / 8), grab.y + 30 * Math.cos(i / 8) - 30);
        await page.waitForTimeout(16);
      }
    });
    await page.mouse.up();
    const moved = (await api(page, 'get_scene')).obstacles[0].center;
    console.log(`(the disk moved to ${moved.map((v) => v.toFixed(3))})`);
  } else if (scenario === 'heavy-link') {
    // 50 nested C-shaped bands of 128 vertices whose boxes all hold the workspace (every
    // configuration costs its 6451 units), and the bundled wall-gap with the most the lab takes.
    const band = (i) => {
      const o = 0.01 + i * 0.004, w = 0.002;
      const c = [[1 - o, o], [o, o], [o, 1 - o], [1 - o, 1 - o], [1 - o, 1 - o - w], [o + w, 1 - o - w], [o + w, o + w], [1 - o, o + w]];
      const vertices = [];
      for (let k = 0; k < 8; ++k)
        for (let j = 0; j < 16; ++j)
          vertices.push([0, 1].map((a) => Math.round((c[k][a] + (c[(k + 1) % 8][a] - c[k][a]) * j / 16) * 1e6) / 1e6));
      return { type: 'polygon', vertices };
    };
    const bands = { version: 1, start: [0.3, 0.3], goal: [0.7, 0.7], obstacles: Array.from({ length: 50 }, (_, i) => band(i)) };
    const zipped = 'z.' + zlib.deflateRawSync(Buffer.from(JSON.stringify(bands)), { level: 9 }).toString('base64')
      .replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
    for (const [name, query] of [['50 bands, 4000 samples', `scene=${zipped}&samples=4000`],
                                 ['wall-gap, 20000 samples, k = 50', 'scene=wall-gap&samples=20000&neighbors=k:50']]) {
      const t0 = Date.now();
      await page.goto(url + `?lesson=step-prm&${query}&steps=99999999`);
      // Every frame from the first one the page shows until the run is done, counted in the page.
      const run = await page.evaluate(() => new Promise((resolve) => {
        const times = [];
        let seen = false;  // the link's run has started (the shell applies it after the first frames)
        const tick = (t) => {
          times.push(t);
          const api = window.cspacelab;
          const busy = api && api.status().busy;
          seen = seen || !!busy;
          if (api && !busy && (seen || times.length > 600)) {
            const s = api.status();
            resolve({ intervals: times.slice(1).map((x, i) => x - times[i]), cpu_max: s.cpu_ms.max, ui_max: s.ui_ms.max,
                      frames: s.frames, steps: api.state().steps });
          } else requestAnimationFrame(tick);
        };
        requestAnimationFrame(tick);
      }));
      const sorted = run.intervals.slice().sort((a, b) => a - b);
      console.log(`${name}: done in ${Date.now() - t0} ms after navigation, ${run.steps} steps, ${run.frames} frames; ` +
                  `browser frame intervals: median ${sorted[sorted.length >> 1].toFixed(1)} ms, ` +
                  `max ${sorted.at(-1).toFixed(1)} ms; app CPU per frame max ${run.cpu_max.toFixed(1)} ms ` +
                  `(building the UI: max ${run.ui_max.toFixed(1)} ms)`);
    }
  } else if (scenario === 'cspace-3d') {
    await api(page, 'select_lesson', { id: 'cspace-3d' });
    if (/^(robot=)?arm$/.test(process.argv[3] || ''))
      await api(page, 'set_scene', { scene: (await api(page, 'bundled_scenes'))['arm-3link'] });
    await api(page, 'set_params', { params: { samples: 1000, neighbors: 'k:10', seed: 2 } });
    await api(page, 'run');
    const s = await api(page, 'state');
    const box = await page.locator('canvas').boundingBox();
    const { views } = (await api(page, 'status')).layout;
    const area = (name) => (({ x, y, w, h }) => ({ x: box.x + x, y: box.y + y, w, h }))(views.find((v) => v.name === name));
    const vol = area('volume'), strip = area('volume_cut');
    console.log(`C-spaces in 3-D (${s.robot}): ${s.drawn.faces} faces, roadmap of ${s.prm.nodes} vertices, ` +
                `${s.prm.edges} edges`);
    // The app's statistics cover its last 120 frames: each phase runs 3 s before it is measured.
    const phase = async (name, move) => {
      console.log(name);
      if (move) await page.mouse.down();
      const motion = async () => {
        if (!move) return;
        for (let i = 0; i < 180; ++i) {
          await move(i);
          await page.waitForTimeout(16);
        }
      };
      await motion();
      await measure(page, motion);
      if (move) await page.mouse.up();
    };
    await page.mouse.move(5, 5);
    await phase('idle');
    const c = { x: vol.x + vol.w * 0.35, y: vol.y + vol.h * 0.5 };
    await page.mouse.move(c.x, c.y);
    await phase('turning: a drag in circles over the block', (i) => page.mouse.move(c.x + 60 * Math.sin(i / 10), c.y + 40 * Math.cos(i / 10)));
    const sx = strip.x + strip.w / 2;
    await page.mouse.move(sx, strip.y + strip.h / 2);
    await phase('scrubbing: the cut plane dragged up and down the strip',
                (i) => page.mouse.move(sx, strip.y + strip.h / 2 + 0.4 * strip.h * Math.sin(i / 12)));
  } else if (scenario === 'potential') {
    await api(page, 'select_lesson', { id: 'potential' });
    // Slow steps, so the descent (and its turning slice) lasts the whole measurement.
    await api(page, 'set_params', { params: { step: 0.0005 } });
    await waitFrames(page, 5);
    await page.keyboard.press('Space');
    // The app's statistics cover its last 120 frames (10 s at SwiftShader's rate): let the
    // lesson's first frame (all its grids computed at once) leave the window first.
    await page.waitForTimeout(10000);
    console.log('potential fields: the rectangle descending at 20 steps/s, its C-space slice redrawn each step');
    await measure(page);
    console.log(`(descent at step ${(await api(page, 'state')).steps})`);
  }
} finally {
  await browser.close();
  server.close();
}
