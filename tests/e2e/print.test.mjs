// Printing: a lab prints as a worksheet (lab-print.js): the lesson's name, the task text, a
// picture of its views, its parameters with their values and what the view shows, and none of
// the canvas's or the page's controls. Checked under Chromium's print media emulation (which
// switches the print media query, as print preview does) with a screenshot, and with page.pdf(),
// which fires beforeprint and afterprint as printing does.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { withBrowser, collectErrors, openLab, openLabs, waitFrames, screenshot, inspectPng, ARTIFACTS } from './lib/harness.mjs';

const TASK = ['Find the gap in the wall.', 'How many samples does seed 3 need to connect S and G?'];

/** Waits until the lab has settled and its printable picture was copied after that. */
async function settled(page, selector = '[data-lab]') {
  await page.waitForFunction((s) => !document.querySelector(s).cspacelab.status().busy, selector, { timeout: 30000 });
  const t0 = await page.evaluate(() => performance.now());
  await page.waitForFunction(([s, t]) => document.querySelector(s).cspacelabPrint?.copiedAt > t, [selector, t0], { timeout: 10000 });
}

/** What is laid out (has a box) among the page's controls and canvases, outside the printed sheets. */
function visibleControls(page) {
  return page.evaluate(() => Array.from(document.querySelectorAll('button, input, select, textarea, canvas, [role="button"]'))
    .filter((e) => !e.closest('.lab-print-sheet') && e.getClientRects().length > 0)
    .map((e) => e.tagName + (e.textContent ? ' ' + e.textContent.trim().slice(0, 20) : '')));
}

test('a lab prints its picture, task and parameters, without controls', () => withBrowser(async ({ browser, url }) => {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  await page.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
  const errors = collectErrors(page);
  await openLab(page, url + 'index.html?lesson=step-prm&scene=wall-gap&samples=80&seed=3&steps=200&task=' +
                encodeURIComponent(TASK.join('\n')));
  await settled(page);
  // Where the geometry puts the start and goal in the views (before printing hides the canvas).
  const before = await page.evaluate(() => {
    const api = window.cspacelab;
    const scene = api.getScene();
    const views = api.status().layout.views;
    const union = views.reduce((u, v) => ({ x0: Math.min(u.x0, v.x), y0: Math.min(u.y0, v.y), x1: Math.max(u.x1, v.x + v.w), y1: Math.max(u.y1, v.y + v.h) }),
                               { x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity });
    return { union, markers: api.view([scene.start, scene.goal]).points, params: api.snapshot().params,
             describe: api.describe(), steps: api.snapshot().steps };
  });
  assert.equal(before.steps, 200);
  assert.deepEqual([before.params.samples, before.params.seed], [80, 3]);
  assert.deepEqual(await visibleControls(page).then((v) => v.length > 0), true, 'on screen there are controls');

  await page.emulateMedia({ media: 'print' });
  await page.waitForSelector('.lab-print-sheet', { state: 'visible' });
  const sheet = await page.evaluate(() => {
    const s = document.querySelector('.lab-print-sheet');
    const pic = s.querySelector('canvas.lab-print-picture');
    const r = pic.getBoundingClientRect();
    return {
      title: s.querySelector('h2').textContent,
      task: Array.from(s.querySelectorAll('.lab-print-task p'), (p) => p.textContent),
      params: Array.from(s.querySelectorAll('dt'), (dt) => [dt.textContent, dt.nextElementSibling.textContent]),
      text: s.querySelector('.lab-print-description').textContent,
      picture: { x: r.left, y: r.top, w: r.width, h: r.height, buffer: [pic.width, pic.height] },
    };
  });
  assert.equal(sheet.title, 'C-Space Lab: Step PRM');
  assert.deepEqual(sheet.task, TASK);
  // Each of the lesson's parameters (snapshot(), another call than the sheet's), with its value.
  const shown = Object.fromEntries(sheet.params.map(([label, value]) => [label, value]));
  assert.equal(sheet.params.length, Object.keys(before.params).length);
  assert.equal(shown['samples n'], String(before.params.samples));
  assert.equal(shown.seed, String(before.params.seed));
  assert.equal(shown['neighbour rule'], before.params.neighbors);
  assert.equal(shown['edge checker'], before.params.checker);
  assert.equal(sheet.text, before.describe);
  assert.match(sheet.text, /Step 200, phase /);
  assert.deepEqual(await visibleControls(page), [], 'printed: no button, field, or live canvas');
  // The picture: the views at device resolution, drawn where the sheet says, and showing the
  // start and goal where the geometry puts them.
  const u = before.union;
  assert.deepEqual(sheet.picture.buffer, [Math.ceil(u.x1 - u.x0), Math.ceil(u.y1 - u.y0)]);
  assert.ok(sheet.picture.w > 400, `the picture is ${sheet.picture.w} px wide`);
  const shot = await screenshot(page, 'print-sheet.png');
  const scale = sheet.picture.w / sheet.picture.buffer[0];
  const at = (p, dx = 0) => [sheet.picture.x + (p[0] - u.x0 + dx) * scale, sheet.picture.y + (p[1] - u.y0) * scale];
  const probes = [at(before.markers[0], -6), at(before.markers[1], -6)];
  const { at: colours } = await inspectPng(browser, shot.png, probes);
  const near = (c, rgb) => c.every((v, k) => Math.abs(v - rgb[k]) <= 30);
  assert.ok(near(colours[0], [0, 158, 115]), `the start marker in the printed picture: rgb(${colours[0]})`);
  assert.ok(near(colours[1], [213, 94, 0]), `the goal marker in the printed picture: rgb(${colours[1]})`);
  const pictureOnly = await page.screenshot({ clip: { x: sheet.picture.x, y: sheet.picture.y, width: sheet.picture.w, height: sheet.picture.h } });
  const { colours: shades } = await inspectPng(browser, pictureOnly);
  assert.ok(shades >= 40, `a picture, not a blank box (${shades} colours)`);

  // Back on screen: the sheet goes, the lab draws and works again.
  await page.emulateMedia({ media: 'screen' });
  await page.waitForSelector('.lab-print-sheet', { state: 'detached' });
  await waitFrames(page, 3);
  assert.ok((await visibleControls(page)).length > 0);
  assert.equal(await page.evaluate(() => window.cspacelab.module.canvas.getBoundingClientRect().height > 500), true);

  // page.pdf() prints for real: beforeprint builds the sheet, afterprint removes it; the PDF
  // holds the picture as an image.
  await page.evaluate(() => {
    window.__print = [];
    for (const e of ['beforeprint', 'afterprint'])
      window.addEventListener(e, () => window.__print.push([e, document.querySelectorAll('.lab-print-sheet').length]));
  });
  const pdf = await page.pdf({ format: 'A4', printBackground: true });
  fs.mkdirSync(ARTIFACTS, { recursive: true });
  fs.writeFileSync(path.join(ARTIFACTS, 'print.pdf'), pdf);
  assert.deepEqual(await page.evaluate(() => window.__print), [['beforeprint', 1], ['afterprint', 0]],
                   'the sheet is there while printing, gone after');
  assert.ok(pdf.subarray(0, 5).toString() === '%PDF-', 'a PDF');
  assert.equal((pdf.toString('latin1').match(/\/Subtype\s*\/Image/g) || []).length, 1, 'one image in it: the picture');
  await page.evaluate(() => window.cspacelab.step());
  assert.equal(await page.evaluate(() => window.cspacelab.snapshot().steps), 201, 'the lab works after printing');
  assert.deepEqual(errors, []);
}));

test('a course page prints its prose and each lab as a worksheet', () => withBrowser(async ({ browser, url }) => {
  const page = await browser.newPage({ viewport: { width: 1100, height: 900 } });
  const errors = collectErrors(page);
  await openLabs(page, url + 'examples/course-page.html', ['#lab-collision', '#lab-prm']);
  await settled(page, '#lab-collision');
  await settled(page, '#lab-prm');
  await page.emulateMedia({ media: 'print' });
  await page.waitForFunction(() => document.querySelectorAll('.lab-print-sheet').length === 2);
  const r = await page.evaluate(() => Array.from(document.querySelectorAll('.lab-print-sheet'), (s) => ({
    lab: s.parentElement.id, title: s.querySelector('h2').textContent, pictures: s.querySelectorAll('canvas.lab-print-picture').length,
  })));
  assert.deepEqual(r, [{ lab: 'lab-collision', title: 'C-Space Lab: Collision checking', pictures: 1 },
                       { lab: 'lab-prm', title: 'C-Space Lab: Step PRM', pictures: 1 }]);
  assert.deepEqual(await visibleControls(page), []);
  assert.ok(await page.getByText('Probabilistic roadmaps, one step at a time').isVisible(), 'the prose prints');
  await page.locator('#lab-prm').scrollIntoViewIfNeeded();
  await screenshot(page, 'print-course-page.png');
  await page.emulateMedia({ media: 'screen' });
  await page.waitForFunction(() => document.querySelectorAll('.lab-print-sheet').length === 0);
  assert.deepEqual(errors, []);
}));

test('an embed in an iframe prints as a worksheet when its host page prints', () => withBrowser(async ({ browser, url }) => {
  const page = await browser.newPage({ viewport: { width: 1000, height: 900 } });
  const errors = collectErrors(page);
  await page.route(url + 'print-host.html', (route) => route.fulfill({
    contentType: 'text/html',
    body: `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>host</title><link rel="icon" href="data:,"></head>
      <body><p>Worksheet 6.</p><iframe src="embed.html?lesson=collision&amp;scene=p12&amp;task=Find%20N" width="800" height="600" title="lab"></iframe></body></html>`,
  }));
  await page.goto(url + 'print-host.html');
  const frame = await (await page.waitForSelector('iframe')).contentFrame();
  await frame.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2, null, { timeout: 30000 });
  await settled(frame);
  await frame.evaluate(() => {
    window.__print = [];
    for (const e of ['beforeprint', 'afterprint'])
      window.addEventListener(e, () => window.__print.push([e, Array.from(document.querySelectorAll('.lab-print-sheet .lab-print-task p'), (p) => p.textContent)]));
  });
  const pdf = await page.pdf({ format: 'A4' });
  assert.deepEqual(await frame.evaluate(() => window.__print), [['beforeprint', ['Find N']], ['afterprint', []]]);
  assert.equal((pdf.toString('latin1').match(/\/Subtype\s*\/Image/g) || []).length, 1, 'the iframe\'s picture in the PDF');
  assert.deepEqual(errors, []);
}));
