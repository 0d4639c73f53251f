// Helpers of the tests of saved work (autosave, history of previous work, restores that fail,
// tabs, storage): read the lab's storage, wait for a save, inject a failing restore, read a
// download, press the File menu's history entries.
import fs from 'node:fs';
import { click, pageButton, waitFrames, api } from './harness.mjs';

export const WORK_KEY = 'cspacelab:v1:/:main:work';

/** Scenes of the Step PRM lesson that tell each other apart by their obstacles. */
export function sceneWith(n, name = `work with ${n} disks`) {
  const obstacles = [];
  for (let i = 0; i < n; ++i) obstacles.push({ type: 'disk', center: [0.15 + 0.7 * (i + 0.5) / n, 0.5], radius: 0.03 });
  return { version: 1, name, workspace: { min: [0, 0], max: [1, 1] }, robot: { type: 'point' }, obstacles,
           start: [0.05, 0.05], goal: [0.95, 0.95] };
}

/** The saved work of a lab (default: index.html's), parsed, or null. */
export async function savedWork(page, key = WORK_KEY) {
  return page.evaluate((k) => JSON.parse(localStorage.getItem(k) || 'null'), key);
}

/** Waits until the saved work's Step PRM scene is named `name` (the autosave ran). */
export async function waitSavedScene(page, name, key = WORK_KEY) {
  await page.waitForFunction(([k, n]) => {
    const w = JSON.parse(localStorage.getItem(k) || 'null');
    const l = w && w.lessons && w.lessons['step-prm'];
    return !!(l && l.scene && l.scene.name === n);
  }, [key, name], { timeout: 15000 });
}

/** Opens Step PRM with a scene through the API. */
export async function setWork(page, scene) {
  await api(page, 'select_lesson', { id: 'step-prm' });
  await api(page, 'set_scene', { scene });
  await waitFrames(page, 2);
}

/** The File menu's history labels, newest first. */
export async function historyLabels(page) {
  return (await api(page, 'page_state')).history.map((h) => h.label);
}

/** Restores the i-th entry of the File menu's history with real clicks: File, then the entry. */
export async function restoreFromMenu(page, i) {
  await click(page, await pageButton(page, 'file'));
  const at = await pageButton(page, `history-${i}`);
  if (!at) throw new Error(`the File menu shows no history-${i}`);
  await click(page, at);
  await waitFrames(page, 2);
}

/** Waits for a notice matching `re` and returns it. */
export async function noticeMatching(page, re) {
  await page.waitForFunction((src) => new RegExp(src).test(window.cspacelab.status().notice), re.source, { timeout: 15000 });
  return (await api(page, 'status')).notice;
}

/**
 * Makes the first restore of the lab in this tab fail, once per tab (sessionStorage survives
 * the reloads of the crash panel's buttons). `mode`: 'trap' (the call throws the wasm's
 * RuntimeError), 'hang' (it never returns: the page freezes), 'frame' (the restore works, and
 * the next frame traps inside the wasm, where glClear is called).
 */
export async function failFirstRestore(page, mode) {
  await page.addInitScript((how) => {
    const used = () => sessionStorage.getItem('csl-test-failed-restore') === '1';
    const use = () => sessionStorage.setItem('csl-test-failed-restore', '1');
    let frameTrap = false;
    const clear = WebGL2RenderingContext.prototype.clear;
    WebGL2RenderingContext.prototype.clear = function (...args) {
      if (frameTrap) {
        frameTrap = false;
        throw new WebAssembly.RuntimeError('table index is out of bounds');
      }
      return clear.apply(this, args);
    };
    let cls;
    Object.defineProperty(window, 'CSpaceLabApi', {
      configurable: true,
      get() { return cls; },
      set(value) {
        cls = value;
        const restore = value.prototype.restore;
        value.prototype.restore = function (...args) {
          if (!used()) {
            use();
            if (how === 'hang') for (;;) { /* the page freezes */ }
            if (how === 'trap') throw new WebAssembly.RuntimeError('memory access out of bounds');
            const r = restore.apply(this, args);
            frameTrap = true;
            return r;
          }
          return restore.apply(this, args);
        };
      },
    });
  }, mode);
}

/** Clicks a dialog's button (by its data-action) and returns the JSON file it downloads. */
export async function downloadFrom(page, selector) {
  const [download] = await Promise.all([page.waitForEvent('download'), page.click(selector)]);
  const file = await download.path();
  return { name: download.suggestedFilename(), value: JSON.parse(fs.readFileSync(file, 'utf8')) };
}

/** The scene named in a downloaded work file (or a scene file). */
export function sceneOf(file) {
  if (file.lessons && file.current && file.lessons[file.current]) return file.lessons[file.current].scene;
  return file.scene || file;
}

/**
 * A scene's JSON text with a value nested `levels` deep: JSON.parse reads it, JSON.stringify
 * overflows the stack (from about 20000 levels in Chromium).
 */
export function deepSceneText(levels, scene = sceneWith(2, 'nested too deep')) {
  return JSON.stringify(scene).replace(/}$/, `,"deep":${'['.repeat(levels)}${']'.repeat(levels)}}`);
}

/** Waits until the lab has started (two frames) or stopped (the crash panel). */
export async function startedOrStopped(page) {
  await page.waitForFunction(() => document.querySelector('.lab-crash') ||
                             (window.cspacelab && window.cspacelab.status().frames >= 2), null, { timeout: 30000 });
}

/** File > Import scene (real clicks), choosing a file `name` with `text`. */
export async function importByPicker(page, name, text) {
  await click(page, await pageButton(page, 'file'));
  const at = await pageButton(page, 'import');
  if (!at) throw new Error('the File menu shows no import');
  const [chooser] = await Promise.all([page.waitForEvent('filechooser'), click(page, at)]);
  await chooser.setFiles({ name, mimeType: 'application/json', buffer: Buffer.from(text) });
}

/**
 * Makes a page behave as a background tab from its start: hidden (document.hidden), no frames
 * (requestAnimationFrame holds its callbacks). window.cslTab.throttle(true) stops its interval
 * timers, as Chrome's throttling of a tab hidden for 5 minutes nearly does (once a minute);
 * window.cslTab.show() brings it to the front: visible, frames again.
 */
export async function backgroundTab(page) {
  await page.addInitScript(() => {
    let hidden = true;
    let paused = false;
    const held = [];
    Object.defineProperty(Document.prototype, 'hidden', { configurable: true, get: () => hidden });
    Object.defineProperty(Document.prototype, 'visibilityState', { configurable: true, get: () => (hidden ? 'hidden' : 'visible') });
    const raf = window.requestAnimationFrame.bind(window);
    window.requestAnimationFrame = (cb) => (hidden ? (held.push(cb), 0) : raf(cb));
    const every = window.setInterval.bind(window);
    window.setInterval = (fn, ms, ...args) => every(() => { if (!paused) fn(...args); }, ms);
    window.cslTab = {
      throttle(on) { paused = on; },
      show() {
        hidden = false;
        document.dispatchEvent(new Event('visibilitychange'));
        for (const cb of held.splice(0)) raf(cb);
      },
    };
  });
}

/** The restore markers in a page's storage, parsed. */
export async function markers(page) {
  return page.evaluate(() => Object.keys(localStorage).filter((k) => k.includes(':restoring:')).map((k) => JSON.parse(localStorage.getItem(k))));
}

/**
 * Makes JSON.stringify throw RangeError past `limit` levels, as it does where it recurses on
 * the stack (Safari, Chrome before V8 made it iterative: about 20000 levels). Chromium 156
 * stringifies 500000 levels, so without this the tests would not meet that engine's failure.
 */
export async function recursiveStringify(page, limit = 20000) {
  await page.addInitScript((max) => {
    const stringify = JSON.stringify;
    JSON.stringify = function (value, ...rest) {
      for (const todo = [[value, 1]]; todo.length;) {
        const [v, depth] = todo.pop();
        if (v === null || typeof v !== 'object') continue;
        if (depth > max) throw new RangeError('Maximum call stack size exceeded');
        for (const k in v) todo.push([v[k], depth + 1]);
      }
      return stringify.call(this, value, ...rest);
    };
  }, limit);
}
