// The Embed dialog's script-tag snippet on a course page of another origin (the usual case of
// an LMS): the lab's files come from origin A, the page from origin B (another port and another
// host name). lab.js loads its scripts with <script> tags, which need no permission, but it
// fetches cspacelab.wasm, which a page of origin B may read only when A's server sends
// Access-Control-Allow-Origin. With the header (static-server.mjs --cors) the lab starts and
// takes clicks; without it the lab's place says which header is missing, not "Failed to fetch".
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { serve } from '../../scripts/static-server.mjs';
import { DIST, launchBrowser, collectErrors, openLab, click, pageButton, waitFrames, screenshot,
         expectView, sceneProbes } from './lib/harness.mjs';

/** The script-tag snippet of the Embed dialog of the lab at `labUrl`, as an instructor copies it. */
async function scriptSnippet(browser, labUrl) {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  await page.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
  await openLab(page, labUrl + 'index.html?lesson=collision&scene=p12&grid_n=5');
  await click(page, await pageButton(page, 'embed'));
  await page.waitForSelector('.lab-dialog textarea');
  const [, script] = await page.$$eval('.lab-dialog .lab-dialog-field textarea', (a) => a.map((t) => t.value));
  await page.close();
  return script;
}

/** A course page (prose, then the snippet) with the Content-Security-Policy docs/web.md gives a host page. */
function coursePage(labOrigin, snippet) {
  return `<!doctype html><html lang="en"><head><meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="default-src 'self'; script-src 'self' ${labOrigin} 'wasm-unsafe-eval'; style-src 'self' ${labOrigin} 'unsafe-inline'; connect-src ${labOrigin}; img-src 'self' data:">
<title>Week 6</title><link rel="icon" href="data:,"></head><body style="margin:0;font:16px serif">
<h1>Week 6: one edge</h1><p>Read the section, then try the lab.</p>
${snippet}
<p>More course text.</p></body></html>`;
}

test('the script-tag snippet works from another origin when the lab\'s server sends CORS, and says what is missing when not',
  async () => {
  const withCors = await serve(DIST, 0, '127.0.0.1', { cors: '*' });
  const without = await serve(DIST, 0, '127.0.0.1');
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'csl-course-'));
  fs.writeFileSync(path.join(dir, 'index.html'), '<!doctype html><title>course</title>');
  const course = await serve(dir, 0, '127.0.0.1');
  // Origin B by another host name too: localhost, where the lab is on 127.0.0.1.
  const courseUrl = course.url.replace('127.0.0.1', 'localhost');
  const browser = await launchBrowser();
  try {
    const originA = withCors.url.replace(/\/$/, '');
    const snippet = await scriptSnippet(browser, withCors.url);
    assert.match(snippet, new RegExp(`^<div id="lab-[0-9a-f]{6}" data-lab="lesson=collision&amp;scene=p12&amp;grid_n=5&amp;[^"]*ui=minimal"`));
    assert.ok(snippet.includes(`<script src="${withCors.url}lab.js" defer></script>`), snippet);
    fs.writeFileSync(path.join(dir, 'week6.html'), coursePage(originA, snippet));

    const page = await browser.newPage({ viewport: { width: 1100, height: 900 } });
    const errors = collectErrors(page);
    const wasm = [];
    page.on('response', (r) => { if (r.url().endsWith('.wasm')) wasm.push({ status: r.status(), cors: r.headers()['access-control-allow-origin'] }); });
    await page.goto(courseUrl + 'week6.html');
    assert.notEqual(new URL(page.url()).origin, originA, 'two origins');
    await page.waitForFunction(() => {
      const el = document.querySelector('[data-lab]');
      return el.cspacelab && el.cspacelab.status().frames >= 2;
    }, null, { timeout: 30000 });
    assert.deepEqual(wasm, [{ status: 200, cors: '*' }], 'the wasm came from A, with the header');
    const lab = '[data-lab]';
    const st = await page.evaluate(() => document.querySelector('[data-lab]').cspacelab.status());
    assert.equal(st.lesson, 'collision', 'element.cspacelab.status() answers');
    assert.equal(await page.evaluate(() => document.querySelector('[data-lab]').cspacelab.state().grid_n), 5);
    // Drawn as its scene says, in the course page.
    const scene = await page.evaluate(() => document.querySelector('[data-lab]').cspacelab.getScene());
    await expectView(page, browser, 'cross-origin-course.png', sceneProbes(scene, { free: 6, avoid: [[scene.start, scene.goal]] })
      .filter((p) => p.why !== 'inside a disk'), 'workspace', { lab });
    // A real click on the app's Step button steps the bisection.
    const steps = (await page.evaluate(() => document.querySelector('[data-lab]').cspacelab.status())).stepping.steps;
    await click(page, await pageButton(page, 'step', lab));
    await waitFrames(page, 2);
    assert.equal((await page.evaluate(() => document.querySelector('[data-lab]').cspacelab.status())).stepping.steps, steps + 1, 'the click stepped');
    // Share from the course page points at the lab's own site (origin A), not at the course page.
    await click(page, await pageButton(page, 'share', lab));
    const link = await page.waitForFunction(() => {
      const t = document.querySelector('.lab-dialog textarea');
      return t && t.value;
    });
    assert.ok((await link.jsonValue()).startsWith(withCors.url + 'index.html?lesson=collision&'), 'a link to the lab on A');
    await screenshot(page, 'cross-origin-share.png');
    assert.deepEqual(errors, [], 'no console errors');
    await page.close();

    // The same, from a server that does not send the header.
    const plain = await scriptSnippet(browser, without.url);
    fs.writeFileSync(path.join(dir, 'week7.html'), coursePage(without.url.replace(/\/$/, ''), plain));
    const page2 = await browser.newPage({ viewport: { width: 1100, height: 900 } });
    await page2.goto(courseUrl + 'week7.html');
    const message = await (await page2.waitForFunction(() => {
      const s = document.querySelector('[data-lab] .lab-status.error');
      return s && !s.hidden && s.textContent;
    }, null, { timeout: 30000 })).jsonValue();
    await screenshot(page2, 'cross-origin-no-cors.png');
    assert.doesNotMatch(message, /Failed to fetch/);
    assert.match(message, /^C-Space Lab could not start: /);
    assert.ok(message.includes(`the lab's server (${without.url.replace(/\/$/, '')}) does not let this page (${new URL(courseUrl).origin}) read cspacelab.wasm`), message);
    assert.ok(message.includes('"Access-Control-Allow-Origin: *"'), 'names the header to add');
    // What the reader sees: the message in the lab's place, with its text visible.
    const box = await page2.locator('[data-lab] .lab-status').boundingBox();
    assert.ok(box && box.width > 300 && box.height > 100, 'shown in the lab\'s place');
    await page2.close();
  } finally {
    await browser.close();
    withCors.server.close();
    without.server.close();
    course.server.close();
    fs.rmSync(dir, { recursive: true, force: true });
  }
});
