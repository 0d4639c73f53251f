// The single-file build (dist/cspacelab-single.html) runs opened from disk (file://): no
// server, nothing fetched, its hash-based Content-Security-Policy enforced, links work there too.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { DIST, launchBrowser, collectErrors, openLab, api, keys, waitFrames, screenshot,
         inspectPng, expectView, sceneProbes } from './lib/harness.mjs';

test('the single-file build runs from file://', async () => {
  const built = path.join(DIST, 'cspacelab-single.html');
  assert.ok(fs.existsSync(built), 'cmake --build builds cspacelab-single.html (target cspacelab_single_file)');
  // Alone in a folder of its own: nothing beside it to load by accident.
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'csl-single-'));
  const file = path.join(dir, 'lab.html');
  fs.copyFileSync(built, file);
  const html = fs.readFileSync(file, 'utf8');
  assert.match(html, /script-src ('sha256-[A-Za-z0-9+/=]+' )+'wasm-unsafe-eval'/, 'scripts allowed by hash only');
  assert.ok(html.length < 1.5 * 1024 * 1024, `one file of ${(html.length / 1024).toFixed(0)} KB`);

  const browser = await launchBrowser();
  try {
    const page = await browser.newPage({ viewport: { width: 1200, height: 760 } });
    const errors = collectErrors(page);
    const requests = [];
    page.on('request', (r) => requests.push(r.url()));
    await page.addInitScript(() => {
      window.__csp = [];
      document.addEventListener('securitypolicyviolation', (e) => window.__csp.push(e.violatedDirective));
    });
    const url = pathToFileURL(file).href;
    await openLab(page, url + '?lesson=step-prm&scene=narrow-passage&samples=60&seed=4&steps=25');
    assert.equal(await page.evaluate(() => location.protocol), 'file:');
    assert.deepEqual(await page.evaluate(() => ({
      scripts: Array.from(document.scripts).filter((s) => s.src).length,
      styles: document.querySelectorAll('link[rel~="stylesheet"]').length,
    })), { scripts: 0, styles: 0 }, 'no external script or stylesheet');
    assert.equal((await api(page, 'status')).notice, '');
    const state = await api(page, 'state');
    assert.equal(state.steps, 25);
    assert.equal(state.params.seed, 4);
    assert.equal((await api(page, 'get_scene')).name, 'A narrow passage');
    await page.mouse.click(700, 400);
    await keys(page, '.', '.', '.');
    assert.equal((await api(page, 'state')).steps, 28, 'keys work');
    // It draws the narrow passage as its geometry says (28 steps: samples, so only the obstacles and
    // the markers are certain).
    await expectView(page, browser, 'single-file.png', sceneProbes(await api(page, 'get_scene'), { free: 0 }));
    assert.deepEqual(requests.filter((u) => !u.startsWith('file:') && !u.startsWith('data:')), [], 'nothing fetched from anywhere');
    assert.deepEqual(requests.filter((u) => u.startsWith('file:')).map((u) => u.split('?')[0]), [url], 'only the page itself');
    // A link made here points at this file.
    const link = (await page.evaluate(() => window.cspacelab.shell.shareLink())).url;
    assert.ok(link.startsWith(url + '?lesson=step-prm&scene=narrow-passage&'), link);
    assert.deepEqual(await page.evaluate(() => window.__csp), [], 'no CSP violation');
    assert.deepEqual(errors, [], 'no console errors');
  } finally {
    await browser.close();
    fs.rmSync(dir, { recursive: true, force: true });
  }
});
