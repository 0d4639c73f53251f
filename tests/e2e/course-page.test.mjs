// The example course page: prose and two labs (Collision checking and Step PRM), each its own
// wasm instance with its own canvas. Driven with real input: keys go only to the lab that was
// clicked, a drawing lands only in its lab, the wheel scrolls the page over an unfocused lab and
// zooms a focused one, and each keeps its own autosave across a reload.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, collectErrors, openLabs, drag, click, keys, waitFrames, screenshot, expectView,
         sceneProbes } from './lib/harness.mjs';

const A = '#lab-collision';
const B = '#lab-prm';
const call = (page, lab, fn, ...args) =>
  page.evaluate(([sel, f, a]) => document.querySelector(sel).cspacelab[f](...a), [lab, fn, args]);

async function toPage(page, lab, points) {
  const { points: local } = await call(page, lab, 'view', points);
  const box = await page.locator(`${lab} canvas`).boundingBox();
  return local.map(([x, y]) => ({ x: box.x + x, y: box.y + y }));
}

test('two labs on a course page work and do not interfere', () => withBrowser(async ({ browser, url }) => {
  const page = await browser.newPage({ viewport: { width: 1100, height: 800 } });
  const errors = collectErrors(page);
  await openLabs(page, url + 'examples/course-page.html', [A, B]);
  assert.ok(await page.evaluate(() => document.querySelector('main').innerText.split(/\s+/).length > 450), 'a page of prose');
  assert.equal(await page.evaluate(() => document.querySelectorAll('canvas').length), 2);
  assert.equal(await page.evaluate(() => window.cspacelab === document.querySelector('#lab-collision').cspacelab), true,
               'window.cspacelab is the first lab');

  // Each lab as its data-lab attribute says.
  assert.equal((await call(page, A, 'status')).lesson, 'collision');
  assert.equal((await call(page, A, 'state')).grid_n, 4);
  assert.equal((await call(page, B, 'status')).lesson, 'step-prm');
  assert.deepEqual((await call(page, B, 'state')).params, { checker: 'bisection', neighbors: 'k:8', sampler: 'uniform', samples: 80, seed: 3 });
  assert.equal((await call(page, B, 'getScene')).name, 'P9: a wall with a gap');
  assert.equal((await call(page, A, 'status')).notice, '');
  assert.equal((await call(page, B, 'status')).notice, '');
  assert.equal(await page.evaluate(() => document.activeElement === document.body), true, 'no lab takes focus on its own');

  // The wheel over an unfocused lab scrolls the page, and the lab's view stays put. (First, lab A
  // is drawn as its scene says, at its place on the page: before the wheel brings the page's
  // hint "Click the lab first" over it.)
  await page.evaluate(() => window.scrollTo(0, document.querySelector('#lab-collision').offsetTop - 120));
  const sceneA = await call(page, A, 'getScene');
  await expectView(page, browser, 'course-page-lab.png',
                   sceneProbes(sceneA, { free: 8, avoid: [[sceneA.start, sceneA.goal]] }), 'workspace', { lab: A });
  const scaleA = (await call(page, A, 'view')).scale;
  let [over] = await toPage(page, A, [[0.5, 0.3]]);
  const y0 = await page.evaluate(() => window.scrollY);
  await page.mouse.move(over.x, over.y);
  await page.mouse.wheel(0, 300);
  await page.waitForFunction((y) => window.scrollY > y + 100, y0);
  await waitFrames(page, 3);
  assert.equal((await call(page, A, 'view')).scale, scaleA, 'no zoom while unfocused');
  await screenshot(page, 'course-page-scrolled.png');

  // Clicked, the lab has the keyboard and the wheel: it zooms and the page stays.
  await page.evaluate(() => window.scrollTo(0, document.querySelector('#lab-collision').offsetTop - 120));
  await waitFrames(page, 2);
  [over] = await toPage(page, A, [[0.5, 0.3]]);
  await click(page, over);
  assert.equal(await page.evaluate(() => document.activeElement === document.querySelector('#lab-collision canvas')), true);
  const y1 = await page.evaluate(() => window.scrollY);
  await page.mouse.wheel(0, -200);
  await waitFrames(page, 4);
  assert.ok((await call(page, A, 'view')).scale > scaleA * 1.05, 'the focused lab zooms');
  assert.equal(await page.evaluate(() => window.scrollY), y1, 'and the page does not scroll');
  await keys(page, '.', '.');
  assert.equal((await call(page, A, 'state')).shown, 2, 'keys reach the focused lab');
  assert.equal((await call(page, B, 'state')).steps, 0, 'and not the other');

  // The other lab: a click moves the keyboard there; draw a disk with the mouse; step it.
  await page.evaluate(() => window.scrollTo(0, document.querySelector('#lab-prm').offsetTop - 60));
  await waitFrames(page, 3);
  const [empty] = await toPage(page, B, [[0.2, 0.15]]);
  await click(page, empty);
  await keys(page, 'd');
  const [c, r] = await toPage(page, B, [[0.25, 0.45], [0.33, 0.45]]);
  await drag(page, c, r);
  await keys(page, 'Escape');
  for (let i = 0; i < 5; ++i) await keys(page, '.');
  const sceneB = await call(page, B, 'getScene');
  assert.equal(sceneB.obstacles.length, 3, 'the disk is in the lab it was drawn in');
  assert.equal(sceneB.obstacles[2].type, 'disk');
  assert.equal((await call(page, B, 'state')).steps, 5);
  assert.equal((await call(page, A, 'getScene')).obstacles.length, 1, 'the other scene is untouched');
  assert.equal((await call(page, A, 'state')).shown, 2, 'and its step too');
  assert.equal((await call(page, B, 'view')).scale > 0, true);
  // Lab B with the disk drawn into it (and its P9 walls; 5 steps: the endpoints and 3 samples).
  const vertices = (await call(page, B, 'state', { roadmap: true })).vertices;
  await expectView(page, browser, 'course-page-prm.png',
                   sceneProbes(sceneB, { free: 6, avoid: vertices.map((v) => [v, v]) }), 'workspace', { lab: B });

  // Each lab saves under its own id, and a reload brings both back.
  await page.evaluate(() => { for (const a of window.CSpaceLab.instances) a.shell.saveNow(); });
  const keysSaved = await page.evaluate(() => Object.keys(localStorage).filter((k) => k.endsWith(':work')).sort());
  assert.deepEqual(keysSaved, ['cspacelab:v1:/examples/course-page.html:lab-collision:work',
                               'cspacelab:v1:/examples/course-page.html:lab-prm:work']);
  await page.reload();
  await page.waitForFunction((sels) => sels.every((s) => document.querySelector(s).cspacelab), [A, B], { timeout: 30000 });
  assert.equal((await call(page, A, 'state')).shown, 2);
  assert.equal((await call(page, B, 'getScene')).obstacles.length, 3);
  assert.equal((await call(page, B, 'state')).steps, 5);
  assert.equal((await call(page, B, 'status')).notice, '', 'its own config, already applied once: the work wins quietly');
  assert.deepEqual(errors, [], 'no console errors');
}));
