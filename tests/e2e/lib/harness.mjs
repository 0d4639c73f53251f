// Shared pieces of the browser end-to-end tests: serve the built site, launch Debian's
// Chromium through playwright-core (headless, WebGL2 on the CPU via SwiftShader), open the lab,
// and read pictures back.
import assert from 'node:assert/strict';
import path from 'node:path';
import fs from 'node:fs';
import { fileURLToPath } from 'node:url';
import os from 'node:os';
import { spawnSync } from 'node:child_process';
import { chromium } from 'playwright-core';
import { serve } from '../../../scripts/static-server.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
export const DIST = process.env.CSPACELAB_DIST || path.resolve(here, '../../../build/wasm/dist');
export const CLI = process.env.CSPACELAB_CLI || path.resolve(here, '../../../build/native/src/cli/cspacelab');
export const ARTIFACTS = process.env.CSPACELAB_ARTIFACTS || path.resolve(here, '../../../build/test-artifacts');

const CHROMIUM_ARGS = [
  '--headless', '--no-sandbox', '--disable-quic', '--no-first-run', '--disable-background-networking',
  '--disable-component-update', '--disable-sync', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
];

/** Serves DIST on a free port of 127.0.0.1. */
export async function startServer() {
  if (!fs.existsSync(path.join(DIST, 'cspacelab.wasm')))
    throw new Error(`no wasm build in ${DIST}: run 'cmake --build --preset wasm' first`);
  return serve(DIST, 0);
}

export async function launchBrowser() {
  return chromium.launch({ executablePath: '/usr/bin/chromium', args: CHROMIUM_ARGS });
}

/** Collects console errors and page errors (uncaught exceptions, wasm aborts) of a page. */
export function collectErrors(page) {
  const errors = [];
  page.on('console', (msg) => { if (msg.type() === 'error') errors.push(msg.text()); });
  page.on('pageerror', (err) => errors.push(String(err)));
  return errors;
}

/**
 * Serves the site and launches Chromium for fn({ browser, url }), then closes both, whatever fn
 * did. The frame of every test: it opens what pages it needs.
 */
export async function withBrowser(fn) {
  const { server, url } = await startServer();
  const browser = await launchBrowser();
  try {
    return await fn({ browser, url });
  } finally {
    await browser.close();
    server.close();
  }
}

/**
 * withBrowser() with one page that has opened the lab: fn({ page, errors, browser, url }). The
 * page must end without console errors or uncaught exceptions (`errors`, which fn may also
 * check on the way). Options: the page's own (default viewport 1280 x 800), and `open`, where
 * to open the lab relative to the site (default: its front page).
 */
export async function withPage(options, fn) {
  if (typeof options === 'function') [options, fn] = [{}, options];
  const { open = '', ...pageOptions } = options;
  return withBrowser(async ({ browser, url }) => {
    const { page, errors } = await openPage(browser, url + open, pageOptions);
    await fn({ page, errors, browser, url });
    assert.deepEqual(errors, [], 'no console errors or uncaught exceptions');
  });
}

/**
 * A new page of `browser` (in a context of its own) that has opened the lab at `at`: { page,
 * errors } (collectErrors). Options: browser.newPage's (default viewport 1280 x 800; hasTouch,
 * isMobile, deviceScaleFactor for a phone or a tablet), and `welcome` to keep the first-visit
 * welcome, which moves the side panel down: only the tests about it see it.
 */
export async function openPage(browser, at, { welcome = false, ...pageOptions } = {}) {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 }, ...pageOptions });
  if (!welcome) await page.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
  const errors = collectErrors(page);
  await openLab(page, at);
  return { page, errors };
}

/** The focused element's text (a button's label, a heading). */
export const focused = (page) => page.evaluate(() => document.activeElement.textContent);

/** Presses Tab until `is(activeElement)` holds, at most `max` times; returns how many it took. */
export async function tabTo(page, is, max, what) {
  for (let n = 1; n <= max; ++n) {
    await page.keyboard.press('Tab');
    if (await page.evaluate(is)) return n;
  }
  const at = await page.evaluate(() => document.activeElement.outerHTML.slice(0, 120));
  throw new Error(`${what} not reached in ${max} presses of Tab; the focus is on ${at}`);
}

/** tabTo() the control whose text is `label`. */
export const tabToButton = (page, label, max = 12) =>
  tabTo(page, new Function(`return document.activeElement.textContent === ${JSON.stringify(label)}`), max, label);

/**
 * Records every text the live region `selector` gets, in order, in the page's window.__said (a
 * region emptied and set again, for a repeat, is heard twice).
 */
export async function recordLive(page, selector) {
  await page.evaluate((sel) => {
    window.__said = [];
    const live = document.querySelector(sel);
    new MutationObserver(() => { if (live.textContent) window.__said.push(live.textContent); })
      .observe(live, { childList: true, characterData: true, subtree: true });
  }, selector);
}

/** Waits until the app has drawn at least `count` more frames. */
export async function waitFrames(page, count = 2) {
  const start = await page.evaluate(() => window.cspacelab.status().frames);
  await page.waitForFunction((n) => window.cspacelab.status().frames >= n, start + count);
}

/** Opens the lab at `url` and waits for its API and its first frames. */
export async function openLab(page, url) {
  await page.goto(url);
  await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2,
                             null, { timeout: 30000 });
}

/** Page coordinates (CSS px) of world points, through the app's own world->canvas mapping. */
export async function worldToPage(page, points, view = 'workspace') {
  const { points: local } = await page.evaluate(([p, v]) => window.cspacelab.view(p, v), [points, view]);
  const box = await page.locator('canvas').boundingBox();
  return local.map(([x, y]) => ({ x: box.x + x, y: box.y + y }));
}

/**
 * Drags the mouse with real events from one page point to another. ImGui samples the mouse once
 * a frame, so frames pass between the press, the moves and the release.
 */
export async function drag(page, from, to, steps = 8) {
  await hold(page, from, to, { steps });
  await waitFrames(page, 1);
  await page.mouse.up();
  await waitFrames(page, 2);
}

/**
 * The first part of drag(): presses at `from` and moves to `to` in `steps`, `frames` frames after
 * each, and keeps the button down (the caller releases). `each(i)` runs after step i: a look at
 * the app in the middle of the drag.
 */
export async function hold(page, from, to, { steps = 8, frames = 1, each = async () => {} } = {}) {
  await page.mouse.move(from.x, from.y);
  await waitFrames(page, 2);
  await page.mouse.down();
  await waitFrames(page, 2);
  for (let i = 1; i <= steps; ++i) {
    await page.mouse.move(from.x + (to.x - from.x) * i / steps, from.y + (to.y - from.y) * i / steps);
    await waitFrames(page, frames);
    await each(i);
  }
}

/** Draws a disk as a student does: with the D tool, a drag from its centre to its rim (world points). */
export async function drawDisk(page, centre, rim) {
  await keys(page, 'd');
  const [a, b] = await worldToPage(page, [centre, rim]);
  await drag(page, a, b);
}

/** A real click at a page point, with frames around it. */
export async function click(page, at) {
  await page.mouse.move(at.x, at.y);
  await waitFrames(page, 2);
  await page.mouse.down();
  await waitFrames(page, 1);
  await page.mouse.up();
  await waitFrames(page, 2);
}

/** Types keys one at a time with a frame after each (ImGui reads them per frame). */
export async function keys(page, ...names) {
  for (const k of names) {
    await page.keyboard.press(k);
    await waitFrames(page, 1);
  }
}

/**
 * A key pressed with a modifier held, chord(page, 'Control', 'z'), frames in between, as a
 * person types it. (The app also takes a chord that lands within one frame: see the draw-disk
 * test that dispatches one, and Platform::frame_once.)
 */
export async function chord(page, modifier, key) {
  await page.keyboard.down(modifier);
  await waitFrames(page, 1);
  await page.keyboard.press(key);
  await waitFrames(page, 1);
  await page.keyboard.up(modifier);
  await waitFrames(page, 2);
}

/**
 * Calls window.cspacelab[method](...args) in the page and returns the message it was refused
 * with, or null if it was taken: refusal(page, 'setParams', {samples: 20001}).
 */
export async function refusal(page, method, ...args) {
  return page.evaluate(([m, a]) => {
    try { window.cspacelab[m](...a); } catch (e) { return e.message; }
    return null;
  }, [method, args]);
}

/** Calls the app's API in the page: api(page, 'state', {roadmap: true}). */
export async function api(page, cmd, args = {}) {
  return page.evaluate(([c, a]) => window.cspacelab.call(c, a), [cmd, args]);
}

/** Saves a screenshot under ARTIFACTS and returns its bytes. */
export async function screenshot(page, name) {
  fs.mkdirSync(ARTIFACTS, { recursive: true });
  const file = path.join(ARTIFACTS, name);
  const png = await page.screenshot({ path: file });
  return { file, png };
}

/** Runs the CLI and parses its JSON (throws with its stderr on failure). */
export function cli(...args) {
  const r = spawnSync(CLI, args, { encoding: 'utf8', maxBuffer: 256 << 20 });
  if (r.status !== 0) throw new Error(`cspacelab ${args.join(' ')}: ${r.stderr}`);
  return JSON.parse(r.stdout);
}

/** Writes JSON to a fresh temporary file and returns its path. */
export function tempJson(value) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'csl-e2e-'));
  const file = path.join(dir, 'scene.json');
  fs.writeFileSync(file, JSON.stringify(value));
  return file;
}

/**
 * Decodes a PNG in a blank page of the same browser and reports on it: the number of distinct
 * colours (quantised to 5 bits per channel) and the RGB at given device-pixel positions.
 */
export async function inspectPng(browser, png, probes = []) {
  const page = await browser.newPage();
  try {
    return await page.evaluate(async ({ b64, probes }) => {
      const img = new Image();
      img.src = 'data:image/png;base64,' + b64;
      await img.decode();
      const canvas = new OffscreenCanvas(img.width, img.height);
      const ctx = canvas.getContext('2d');
      ctx.drawImage(img, 0, 0);
      const { data } = ctx.getImageData(0, 0, img.width, img.height);
      const colours = new Set();
      for (let i = 0; i < data.length; i += 4)
        colours.add(((data[i] >> 3) << 10) | ((data[i + 1] >> 3) << 5) | (data[i + 2] >> 3));
      const at = probes.map(([x, y]) => {
        const i = 4 * (Math.round(y) * img.width + Math.round(x));
        return [data[i], data[i + 1], data[i + 2]];
      });
      return { width: img.width, height: img.height, colours: colours.size, at };
    }, { b64: png.toString('base64'), probes });
  } finally {
    await page.close();
  }
}

/**
 * Page coordinates of the centre of one of the app's page controls, by the name page_state
 * reports (share, embed, file, import, export-scene, export-png, export-state, reset,
 * reset-confirm, reset-cancel, restore-previous). `lab`: CSS selector of a [data-lab] element
 * (default: window.cspacelab's). Null when the control is not on screen this frame.
 */
export async function pageButton(page, name, lab = null) {
  const r = await page.evaluate(([n, sel]) => {
    const a = sel ? document.querySelector(sel).cspacelab : window.cspacelab;
    const rect = a.pageState().buttons[n];
    const box = a.module.canvas.getBoundingClientRect();
    return rect ? { x: box.left + (rect[0] + rect[2]) / 2, y: box.top + (rect[1] + rect[3]) / 2 } : null;
  }, [name, lab]);
  return r;
}

/** Waits for an instance on a page with several labs (`selector` of its [data-lab] element). */
export async function openLabs(page, url, selectors) {
  await page.goto(url);
  await page.waitForFunction((sels) => sels.every((s) => {
    const el = document.querySelector(s);
    return el && el.cspacelab && el.cspacelab.status().frames >= 2;
  }), selectors, { timeout: 30000 });
}

// ---- pictures checked against the geometry ------------------------------------------------

/**
 * The colours a view's pixels take (src/app/shell/theme.hpp, as they land on the white canvas), each
 * a test of one [r, g, b]: a probe names one of these, or gives [r, g, b] (within 24 a channel).
 */
export const LOOKS = {
  // The canvas, or a grid line over it: light and grey.
  canvas: ([r, g, b]) => Math.min(r, g, b) >= 190 && Math.max(r, g, b) - Math.min(r, g, b) <= 12,
  // An obstacle's fill, rgba(96, 96, 104, 200) over white (130, 130, 136) or a grid line, or
  // opaque over a heat map (the potential lesson): a blue-grey between (90, 90, 98) and (150, ...).
  obstacle: ([r, g, b]) => r >= 90 && r <= 150 && Math.abs(r - g) <= 6 && b >= r && b - r <= 14,
  // The torus's C-obstacles, rgba(96, 96, 104, 210) over white.
  cobstacle: ([r, g, b]) => r >= 105 && r <= 145 && Math.abs(r - g) <= 6 && b >= r && b - r <= 14,
  // A roadmap under the white veil of a pending replay: light, but tinted.
  faded: ([r, g, b]) => Math.min(r, g, b) >= 140 && Math.max(r, g, b) - Math.min(r, g, b) >= 20,
  start: near([0, 158, 115]),
  goal: near([213, 94, 0]),
  dark: ([r, g, b]) => Math.max(r, g, b) <= 110,
};
function near(rgb, tolerance = 24) {
  return (c) => c.every((v, k) => Math.abs(v - rgb[k]) <= tolerance);
}

/**
 * A look for a thin anti-aliased line of colour `rgb` over the white canvas: at a point on the
 * line the pixel is at least half the colour (each channel the same mix of the colour and white,
 * within 0.2), whatever fraction of the pixel the line covers.
 */
export function stroke(rgb) {
  return (c) => {
    const mixes = [0, 1, 2].filter((k) => 255 - rgb[k] > 40).map((k) => (255 - c[k]) / (255 - rgb[k]));
    const mean = mixes.reduce((a, b) => a + b, 0) / mixes.length;
    return mean >= 0.5 && mixes.every((m) => Math.abs(m - mean) <= 0.2) &&
      [0, 1, 2].every((k) => 255 - rgb[k] > 40 || c[k] >= 200);
  };
}

/**
 * Looks at a view as the geometry says it must be. `probes`: [{at: [x, y] (world units of the
 * view), look: a name in LOOKS, [r, g, b] or a test of one, dx, dy (CSS px, optional), why}]. Takes a screenshot
 * (under `name`), maps every point through the app's own world->canvas mapping and fails naming
 * each probe that shows something else. Returns the screenshot. Options: `keepMouse`, leave the
 * mouse where it is (a drag held down; else it moves off the canvas first); `frame`, the lab is in
 * this iframe of the page; `lab`, the CSS selector of its [data-lab] element on a page of several;
 * `misses`, how many probes may show something else (where small marks, a Monte Carlo run's
 * dots, lie scattered over the picture: say why at the call).
 */
export async function expectView(page, browser, name, probes, view = 'workspace',
                                 { keepMouse = false, frame = null, lab = null, misses = 0 } = {}) {
  // No hover highlight or ghost in the picture (unless the mouse is in the middle of a drag).
  if (!keepMouse) await page.mouse.move(2, 2);
  await waitFrames(frame || page, 3);
  // The lab's own world->canvas mapping, to page coordinates (through its iframe, if any).
  const inLab = await (frame || page).evaluate(([pts, v, sel]) => {
    const api = sel ? document.querySelector(sel).cspacelab : window.cspacelab;
    const box = api.module.canvas.getBoundingClientRect();
    return api.view(pts, v).points.map(([x, y]) => ({ x: box.left + x, y: box.top + y }));
  }, [probes.map((p) => p.at), view, lab]);
  const offset = frame ? await (await frame.frameElement()).boundingBox() : { x: 0, y: 0 };
  const points = inLab.map((p) => ({ x: p.x + offset.x, y: p.y + offset.y }));
  const viewport = page.viewportSize();
  const off = points.filter((p) => p.x < 0 || p.y < 0 || p.x >= viewport.width || p.y >= viewport.height);
  assert.equal(off.length, 0, `${name}: ${off.length} probes off the screen (scroll the lab into view)`);
  const shot = await screenshot(page, name);
  const scale = await page.evaluate(() => window.devicePixelRatio);
  const { at } = await inspectPng(browser, shot.png,
    points.map((p, i) => [(p.x + (probes[i].dx || 0)) * scale, (p.y + (probes[i].dy || 0)) * scale]));
  const wrong = [];
  probes.forEach((p, i) => {
    const test = Array.isArray(p.look) ? near(p.look) : typeof p.look === 'function' ? p.look : LOOKS[p.look];
    if (!test) throw new Error(`no look "${p.look}"`);
    const want = Array.isArray(p.look) ? `rgb(${p.look})` : typeof p.look === 'function' ? 'what it should' : p.look;
    if (!test(at[i])) wrong.push(`${p.why || p.look} at (${p.at}) shows rgb(${at[i]}), not ${want}`);
  });
  if (wrong.length > misses) assert.deepEqual(wrong, [], `${name}: ${wrong.length} of ${probes.length} probes (${misses} may miss)`);
  return shot;
}

/**
 * Probes a scene's picture must pass, computed from its JSON: a point well inside every disk
 * and polygon (obstacle), the start and goal markers (beside their letter), and `free` points of
 * the workspace at least `margin` from every obstacle, marker and `avoid` segment (canvas).
 * `markers: false` leaves the markers out (a lesson that draws the robot there instead); a robot
 * other than a point has none in the workspace (its start and goal are configurations).
 */
export function sceneProbes(scene, { free = 12, margin = 0.04, markers = true, avoid = [] } = {}) {
  const [x0, y0] = scene.workspace.min, [x1, y1] = scene.workspace.max;
  const span = Math.max(x1 - x0, y1 - y0);
  const probes = [];
  const segDist = (p, a, b) => {
    const dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
    const t = len2 ? Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2)) : 0;
    return Math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
  };
  const inside = (p, poly) => {
    let inn = false;
    for (let i = 0, j = poly.length - 1; i < poly.length; j = i++)
      if ((poly[i][1] > p[1]) !== (poly[j][1] > p[1]) &&
          p[0] < (poly[j][0] - poly[i][0]) * (p[1] - poly[i][1]) / (poly[j][1] - poly[i][1]) + poly[i][0]) inn = !inn;
    return inn;
  };
  const edges = (poly) => poly.map((a, i) => [a, poly[(i + 1) % poly.length]]);
  // The distance from p to an obstacle's outline (0 inside a filled one).
  const distance = (p, o) => {
    if (o.type === 'disk') return Math.max(0, Math.hypot(p[0] - o.center[0], p[1] - o.center[1]) - o.radius);
    if (o.type === 'segment' || o.type === 'wall') return segDist(p, o.a, o.b);
    return inside(p, o.vertices) ? 0 : Math.min(...edges(o.vertices).map(([a, b]) => segDist(p, a, b)));
  };
  for (const o of scene.obstacles) {
    if (o.type === 'disk') {
      if (o.radius >= 0.02 * span) probes.push({ at: o.center, look: 'obstacle', why: 'inside a disk' });
    } else if (o.type === 'polygon') {
      // The point of a grid over its box deepest inside it (away from its outline's dark edge).
      const xs = o.vertices.map((v) => v[0]), ys = o.vertices.map((v) => v[1]);
      let best = null, depth = 0;
      for (let i = 1; i < 20; ++i) for (let j = 1; j < 20; ++j) {
        const p = [Math.min(...xs) + (Math.max(...xs) - Math.min(...xs)) * i / 20, Math.min(...ys) + (Math.max(...ys) - Math.min(...ys)) * j / 20];
        if (!inside(p, o.vertices)) continue;
        const d = Math.min(...edges(o.vertices).map(([a, b]) => segDist(p, a, b)));
        if (d > depth) [best, depth] = [p, d];
      }
      if (best && depth >= 0.01 * span) probes.push({ at: best, look: 'obstacle', why: 'inside a polygon' });
    }
  }
  const ends = [];
  if (markers && (!scene.robot || scene.robot.type === 'point')) {  // (an arm's start is two angles)
    // Left of centre, off the white letter: the marker is 9 px in radius.
    probes.push({ at: scene.start, look: 'start', dx: -6, why: 'the start marker' });
    probes.push({ at: scene.goal, look: 'goal', dx: -6, why: 'the goal marker' });
    ends.push(scene.start, scene.goal);
  }
  const n = Math.ceil(Math.sqrt(free * 4));
  const candidates = [];
  for (let i = 0; i < n; ++i) for (let j = 0; j < n; ++j) {
    const p = [x0 + (x1 - x0) * (i + 0.5) / n, y0 + (y1 - y0) * (j + 0.5) / n];
    const clear = scene.obstacles.every((o) => distance(p, o) > margin * span) &&
      ends.every((e) => Math.hypot(p[0] - e[0], p[1] - e[1]) > 2 * margin * span) &&
      avoid.every(([a, b]) => segDist(p, a, b) > margin * span);
    if (clear) candidates.push(p);
  }
  const every = Math.max(1, Math.floor(candidates.length / free));
  candidates.filter((_, k) => k % every === 0).slice(0, free)
    .forEach((p) => probes.push({ at: p, look: 'canvas', why: 'free space' }));
  return probes;
}

export const GOLDEN = path.resolve(here, '../golden');

/**
 * Compares the part of the page under one of the app's controls (page_state's name for it, e.g.
 * 'notation-picture') with a reference picture, tests/e2e/golden/<name>.png, for pictures whose
 * every pixel matters and that no geometry describes as well (a robot drawn in parts). At most
 * `share` of the pixels may differ, and by no more than `levels` in any channel: what a change of
 * anti-aliasing may do, not a part moved or missing. CSPACELAB_UPDATE_GOLDEN=1 writes the reference
 * instead (look at it before committing it). The picture taken is saved under ARTIFACTS as always.
 */
export async function expectGolden(page, browser, name, control, { share = 0.01, levels = 48 } = {}) {
  await page.mouse.move(2, 2);
  await waitFrames(page, 3);
  const rect = await page.evaluate((c) => {
    const r = window.cspacelab.pageState().buttons[c];
    const box = window.cspacelab.module.canvas.getBoundingClientRect();
    return r && { x: box.left + r[0], y: box.top + r[1], width: r[2] - r[0], height: r[3] - r[1] };
  }, control);
  assert.ok(rect && rect.width > 50 && rect.height > 50, `${control} is on screen`);
  fs.mkdirSync(ARTIFACTS, { recursive: true });
  const png = await page.screenshot({ path: path.join(ARTIFACTS, `${name}.png`), clip: rect });
  const reference = path.join(GOLDEN, `${name}.png`);
  if (process.env.CSPACELAB_UPDATE_GOLDEN) {
    fs.mkdirSync(GOLDEN, { recursive: true });
    fs.writeFileSync(reference, png);
    return;
  }
  assert.ok(fs.existsSync(reference), `no reference ${reference} (CSPACELAB_UPDATE_GOLDEN=1 writes one)`);
  const result = await pixelDifference(browser, png, fs.readFileSync(reference), levels);
  assert.ok(!result.size, `${name}: ${result.size}`);
  assert.ok(result.differ <= share, `${name}: ${(100 * result.differ).toFixed(2)} % of the pixels differ by more than ${levels} ` +
            `(at most ${100 * share} %); see ${path.join(ARTIFACTS, name + '.png')} against ${reference}`);
}

/**
 * How two PNG pictures differ, decoded in a page of `browser`: {differ, worst} with differ the
 * share of pixels off by more than `levels` in a channel and worst the largest channel
 * difference, or {size: "W x H against W x H"} when their sizes differ.
 */
export async function pixelDifference(browser, a, b, levels = 48) {
  const compare = await browser.newPage();
  try {
    return await compare.evaluate(async ({ a, b, levels }) => {
      const pixels = async (b64) => {
        const img = new Image();
        img.src = 'data:image/png;base64,' + b64;
        await img.decode();
        const c = new OffscreenCanvas(img.width, img.height).getContext('2d');
        c.drawImage(img, 0, 0);
        return { w: img.width, h: img.height, data: c.getImageData(0, 0, img.width, img.height).data };
      };
      const [x, y] = [await pixels(a), await pixels(b)];
      if (x.w !== y.w || x.h !== y.h) return { size: `${x.w} x ${x.h} against ${y.w} x ${y.h}` };
      let differ = 0, worst = 0;
      for (let i = 0; i < x.data.length; i += 4) {
        const d = Math.max(Math.abs(x.data[i] - y.data[i]), Math.abs(x.data[i + 1] - y.data[i + 1]), Math.abs(x.data[i + 2] - y.data[i + 2]));
        worst = Math.max(worst, d);
        if (d > levels) ++differ;
      }
      return { differ: differ / (x.w * x.h), worst };
    }, { a: a.toString('base64'), b: b.toString('base64'), levels });
  } finally {
    await compare.close();
  }
}
