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
  const { open = '', welcome = false, ...pageOptions } = options;
  return withBrowser(async ({ browser, url }) => {
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 }, ...pageOptions });
    // The first-visit welcome moves the side panel down: only the tests about it see it.
    if (!welcome) await page.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
    const errors = collectErrors(page);
    await openLab(page, url + open);
    await fn({ page, errors, browser, url });
    assert.deepEqual(errors, [], 'no console errors or uncaught exceptions');
  });
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
