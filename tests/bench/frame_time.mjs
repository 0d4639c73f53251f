// Frame time in the browser while a large roadmap is on screen (a benchmark, not a test).
//   node tests/bench/frame_time.mjs [samples=5000]
// Opens the built site in headless Chromium (SwiftShader: WebGL on the CPU, slower than any
// GPU), runs PRM to the end with n samples in the Step PRM lesson, then measures for 3 seconds:
// the intervals between requestAnimationFrame callbacks (what a student sees), and the app's
// own CPU time per frame (building the UI and the draw lists).
import { startServer, launchBrowser, openLab, api } from '../e2e/lib/harness.mjs';

const samples = Number(process.argv[2] || 5000);
const { server, url } = await startServer();
const browser = await launchBrowser();
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  await openLab(page, url);
  await api(page, 'select_lesson', { id: 'step-prm' });
  await api(page, 'set_params', { params: { samples, neighbors: 'k:10', seed: 1 } });
  await api(page, 'run');
  const s = await api(page, 'state');
  await page.waitForTimeout(1000);
  const intervals = await page.evaluate(() => new Promise((resolve) => {
    const times = [];
    const tick = (t) => {
      times.push(t);
      if (t - times[0] < 3000) requestAnimationFrame(tick);
      else resolve(times.slice(1).map((x, i) => x - times[i]));
    };
    requestAnimationFrame(tick);
  }));
  const status = await api(page, 'status');
  intervals.sort((a, b) => a - b);
  const mean = intervals.reduce((a, b) => a + b, 0) / intervals.length;
  const p95 = intervals[Math.floor(intervals.length * 0.95)];
  console.log(`roadmap: ${s.nodes} vertices, ${s.edges} edges (n = ${samples})`);
  console.log(`browser frames: ${intervals.length} in 3 s, mean ${mean.toFixed(2)} ms (${(1000 / mean).toFixed(1)} fps), p95 ${p95.toFixed(2)} ms`);
  console.log(`app CPU per frame: mean ${status.cpu_ms.mean.toFixed(2)} ms, p95 ${status.cpu_ms.p95.toFixed(2)} ms, max ${status.cpu_ms.max.toFixed(2)} ms`);
  console.log(`  of which building the UI: mean ${status.ui_ms.mean.toFixed(2)} ms, p95 ${status.ui_ms.p95.toFixed(2)} ms; ` +
              `${status.vertices} vertices drawn`);
} finally {
  await browser.close();
  server.close();
}
