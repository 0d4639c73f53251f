// A browser without what the lab needs (WebGL2, WebAssembly SIMD) gets a sentence in the lab's
// place that names what is missing and which browsers have it, and the lab does not start (every
// other browser test starts it where both are there). The feature is taken away before the
// page's scripts run.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, collectErrors, screenshot } from './lib/harness.mjs';

// Opens the front page with `remove` run first, and returns the lab's status line once the
// loader has given up. "Does not start" is not a matter of waiting a while and looking once: the
// factory of the wasm module (createCSpaceLab) and WebAssembly.instantiate are watched from
// before the page's scripts run; the page runs on Playwright's fake clock, which, once the
// loader has settled (lab.js's `ready` resolves when every start() has returned), is moved ten
// minutes on, firing every timer a late start could hide in; only then is the watch read.
async function statusWithout(browser, url, remove) {
  const page = await browser.newPage({ viewport: { width: 900, height: 600 } });
  const errors = collectErrors(page);
  await page.clock.install();
  await page.addInitScript(() => {
    window.__factoryCalls = 0;
    const instantiate = WebAssembly.instantiate;
    WebAssembly.instantiate = (...args) => { window.__factoryCalls += 1; return instantiate(...args); };
    let factory;
    Object.defineProperty(window, 'createCSpaceLab', {
      configurable: true,
      get: () => factory && ((...args) => { window.__factoryCalls += 1; return factory(...args); }),
      set: (f) => { factory = f; },
    });
  });
  await page.addInitScript(remove);
  await page.goto(url);
  await page.waitForSelector('.lab-status.error', { timeout: 30000 });
  await page.waitForFunction(() => window.CSpaceLab && window.CSpaceLab.ready, null, { timeout: 30000 });
  const settled = await page.evaluate(async () => (await window.CSpaceLab.ready).filter(Boolean).length);
  await page.clock.runFor(10 * 60 * 1000);
  const result = await page.evaluate(() => ({
    text: document.querySelector('.lab-status').textContent,
    visible: !document.querySelector('.lab-status').hidden,
    started: typeof window.cspacelab !== 'undefined' || window.CSpaceLab.instances.length > 0 || window.__factoryCalls > 0,
  }));
  assert.equal(settled, 0, 'no lab started');
  return { page, errors, ...result };
}

test('without WebAssembly SIMD: the lab says so, and does not start', () => withBrowser(async ({ browser, url }) => {
  const { page, errors, text, visible, started } = await statusWithout(browser, url, () => {
    // What a browser without SIMD answers for any module that uses v128 (the wasm and the check).
    const validate = WebAssembly.validate;
    WebAssembly.validate = (bytes) => !new Uint8Array(bytes).includes(0xfd) && validate(bytes);
  });
  await screenshot(page, 'no-wasm-simd.png');
  assert.ok(visible);
  assert.match(text, /needs WebAssembly with SIMD/);
  assert.match(text, /Safari 16\.4\+/);
  assert.equal(started, false);
  assert.deepEqual(errors, []);
}));

test('without WebGL2: the lab says so, and does not start', () => withBrowser(async ({ browser, url }) => {
  const { errors, text, visible, started } = await statusWithout(browser, url, () => { delete window.WebGL2RenderingContext; });
  assert.ok(visible);
  assert.match(text, /needs WebGL2/);
  assert.equal(started, false);
  assert.deepEqual(errors, []);
}));
