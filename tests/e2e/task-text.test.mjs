// Task text: a link's task=, a data-lab's task= or data-lab-task, and the Embed dialog's field
// show the instructor's task in the page's DOM above the canvas, as plain text (HTML in it is
// literal text), each line a paragraph, at most 1000 characters. The canvas takes the rest of the
// lab's height and the app's views fit in it, on a laptop and on a phone; Share keeps the task;
// a new task keeps a student's saved work.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, collectErrors, openLab, click, pageButton, waitFrames, screenshot, inspectPng } from './lib/harness.mjs';

const LINES = ['Move q so that the segment only grazes the disk.',
               'How many bisection steps does the exact check need now? Answer with <b>one</b> number & explain <img src=x onerror="window.pwned=1">.'];
const TASK = LINES[0] + '\n\n' + LINES[1];  // (the blank line is dropped)

async function newPage(browser, viewport = { width: 1280, height: 800 }, context = browser) {
  const page = await context.newPage({ viewport });
  await page.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
  return page;
}

// A page of the same site made up on the spot (playwright answers the request).
async function hostPage(page, url, name, body) {
  await page.route(url + name, (route) => route.fulfill({
    contentType: 'text/html',
    body: `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>course</title><link rel="icon" href="data:,"></head>
      <body style="margin:0;font:16px serif"><h1>Week 6</h1>${body}<p>More text.</p></body></html>`,
  }));
  await page.goto(url + name);
}

/**
 * The task of a lab as the DOM has it, and the lab's height accounting: the task above the
 * canvas, the canvas the rest of the element (its drawing buffer at device resolution), every
 * view the app lays out inside the canvas.
 */
async function taskLayout(target, selector = '[data-lab]') {
  return target.evaluate((sel) => {
    const root = document.querySelector(sel);
    const section = root.querySelector(':scope > .lab-task');
    const canvas = root.querySelector('canvas');
    const api = root.cspacelab;
    const r = root.getBoundingClientRect(), t = section && section.getBoundingClientRect(), c = canvas.getBoundingClientRect();
    const layout = api.status().layout;
    return {
      present: !!section,
      paragraphs: section ? Array.from(section.querySelectorAll('p'), (p) => p.textContent) : [],
      tags: section ? Array.from(section.querySelectorAll('*'), (e) => e.tagName) : [],
      beforeCanvas: !!section && section.nextElementSibling === canvas,
      root: { top: r.top, height: r.height }, task: t && { top: t.top, bottom: t.bottom, left: t.left, height: t.height, width: t.width },
      canvas: { top: c.top, height: c.height, width: c.width, buffer: [canvas.width, canvas.height] },
      dpr: window.devicePixelRatio,
      layout,
      pwned: !!window.pwned,
      notice: api.status().notice,
    };
  }, selector);
}

function checkLayout(l, name) {
  assert.ok(l.present && l.beforeCanvas, `${name}: the task is in the lab's element, right before the canvas`);
  assert.ok(Math.abs(l.task.top - l.root.top) <= 1, `${name}: at the top of the lab`);
  assert.ok(Math.abs(l.canvas.top - l.task.bottom) <= 0.5, `${name}: the canvas starts under it (${l.canvas.top} against ${l.task.bottom})`);
  assert.ok(Math.abs(l.task.height + l.canvas.height - l.root.height) <= 1,
            `${name}: task ${l.task.height} + canvas ${l.canvas.height} = the lab's ${l.root.height}`);
  assert.ok(l.task.height <= 0.34 * l.root.height, `${name}: the task takes at most a third of the lab (${l.task.height} of ${l.root.height})`);
  assert.equal(l.canvas.height, Math.round(l.canvas.height), `${name}: a whole number of CSS px (${l.canvas.height})`);
  assert.deepEqual(l.canvas.buffer, [Math.round(l.canvas.width * l.dpr), Math.round(l.canvas.height * l.dpr)], `${name}: the buffer at device resolution`);
  assert.ok(l.layout.views.length >= 1, `${name}: views laid out`);
  for (const v of l.layout.views)
    assert.ok(v.x >= 0 && v.y >= 0 && v.x + v.w <= l.canvas.width + 0.5 && v.y + v.h <= l.canvas.height + 0.5 && v.h >= 100,
              `${name}: view ${v.name} (${v.x}, ${v.y}, ${v.w} x ${v.h}) inside the ${l.canvas.width} x ${l.canvas.height} canvas and usable`);
}

/** The task as drawn: its blue rule at the left, and text (many shades) inside its box. */
async function checkPixels(page, browser, l, name) {
  const shot = await screenshot(page, name);
  const dpr = l.dpr;
  const rule = await inspectPng(browser, shot.png, [[(l.task.left + 2) * dpr, (l.task.top + l.task.height / 2) * dpr]]);
  const [r, g, b] = rule.at[0];
  assert.ok(Math.abs(r - 0) <= 24 && Math.abs(g - 114) <= 24 && Math.abs(b - 178) <= 24, `${name}: the task's rule, rgb(${rule.at[0]})`);
  const box = await page.screenshot({ clip: { x: l.task.left + 6, y: l.task.top + 2, width: l.task.width - 12, height: l.task.height - 4 } });
  const inside = await inspectPng(browser, box);
  assert.ok(inside.colours >= 12, `${name}: text drawn in the task's box (${inside.colours} shades)`);
  return shot;
}

test('task= in index.html: plain text above the canvas, on a laptop and a phone; Share keeps it',
  () => withBrowser(async ({ browser, url }) => {
  const link = 'index.html?lesson=collision&scene=p12&grid_n=6&task=' + encodeURIComponent(TASK);
  const page = await newPage(browser);
  const errors = collectErrors(page);
  await openLab(page, url + link);
  await waitFrames(page, 3);
  let l = await taskLayout(page);
  assert.deepEqual(l.paragraphs, LINES, 'each line a paragraph, the blank one dropped');
  assert.deepEqual(l.tags, ['H2', 'P', 'P'], 'HTML in the task is text, not elements');
  assert.equal(l.pwned, false);
  assert.equal(l.notice, '', 'nothing to report');
  assert.equal(await page.getByRole('region', { name: 'Task' }).count(), 1, 'a region named "Task" for screen readers');
  checkLayout(l, 'index 1280x800');
  await checkPixels(page, browser, l, 'task-index-1280x800.png');

  // Share (the app's button): the link carries the task, and opens with it.
  await click(page, await pageButton(page, 'share'));
  const shared = await (await page.waitForFunction(() => {
    const t = document.querySelector('.lab-dialog textarea');
    return t && t.value;
  })).jsonValue();
  assert.equal(new URL(shared).searchParams.get('task'), LINES.join('\n'), 'the Share link keeps the task');
  const other = await newPage(browser);
  await openLab(other, shared);
  const o = await taskLayout(other);
  assert.deepEqual(o.paragraphs, LINES);
  assert.equal(await other.evaluate(() => window.cspacelab.state().grid_n), 6);
  await other.close();

  // The phone: compact layout below 700 px, the task still above a canvas that holds the views.
  for (const page2 of ['index.html', 'embed.html']) {
    const phone = await newPage(browser, { width: 390, height: 844 });
    const phoneErrors = collectErrors(phone);
    await openLab(phone, url + page2 + link.slice('index.html'.length));
    await waitFrames(phone, 3);
    l = await taskLayout(phone);
    assert.equal(l.layout.mode, 'compact');
    assert.deepEqual(l.paragraphs, LINES);
    checkLayout(l, `${page2} 390x844`);
    await checkPixels(phone, browser, l, `task-${page2.replace('.html', '')}-390x844.png`);
    assert.deepEqual(phoneErrors, []);
    await phone.close();
  }
  assert.deepEqual(errors, []);
}));

test('a course page: data-lab-task, or task= in data-lab', () => withBrowser(async ({ browser, url }) => {
  const page = await newPage(browser, { width: 1100, height: 900 });
  const errors = collectErrors(page);
  await hostPage(page, url, 'task-course.html', `
    <div id="a" data-lab="lesson=collision&amp;scene=p12" data-lab-task="Find the smallest N.&#10;Is it <i>odd</i>?" style="height:520px"></div>
    <div id="b" data-lab="lesson=step-prm&amp;scene=wall-gap&amp;task=From%20the%20link" data-lab-task="not this one" style="height:520px"></div>
    <div id="c" data-lab="lesson=collision" style="height:400px"></div>
    <script src="lab.js"></script>`);
  await page.waitForFunction(() => ['#a', '#b', '#c'].every((s) => {
    const el = document.querySelector(s);
    return el.cspacelab && el.cspacelab.status().frames >= 2;
  }), null, { timeout: 30000 });
  const a = await taskLayout(page, '#a');
  assert.deepEqual(a.paragraphs, ['Find the smallest N.', 'Is it <i>odd</i>?']);
  assert.deepEqual(a.tags, ['H2', 'P', 'P']);
  checkLayout(a, '#a');
  assert.deepEqual((await taskLayout(page, '#b')).paragraphs, ['From the link'], 'task= in data-lab wins');
  const c = await taskLayout(page, '#c');
  assert.equal(c.present, false, 'no task, no section');
  assert.equal(c.canvas.height, 400, 'and the canvas is the whole lab');
  await page.locator('#a').scrollIntoViewIfNeeded();
  await checkPixels(page, browser, await taskLayout(page, '#a'), 'task-course-page.png');
  assert.deepEqual(errors, []);
}));

test('the Embed dialog: a task field whose text goes into both snippets, and they show it',
  () => withBrowser(async ({ browser, url }) => {
  const ctx = await browser.newContext();
  const page = await newPage(browser, { width: 1280, height: 800 }, ctx);
  const errors = collectErrors(page);
  await openLab(page, url + 'index.html?lesson=collision&scene=p12&task=Old%20task');
  await click(page, await pageButton(page, 'embed'));
  const field = page.locator('.lab-dialog-task textarea');
  await field.waitFor();
  assert.equal(await field.inputValue(), 'Old task', 'the field starts with the lab\'s task');
  const snippets = () => page.$$eval('.lab-dialog .lab-dialog-field textarea[readonly]', (a) => a.map((t) => t.value));
  assert.ok((await snippets())[0].includes('&amp;task=Old%20task&amp;'), 'the iframe snippet has it');

  const task = 'Step to the first collision.\nThen answer: "why <here>?" & how sure are you?';
  await field.fill(task);
  const [iframe, script] = await snippets();
  const src = /src="([^"]+)"/.exec(iframe)[1].replace(/&amp;/g, '&');
  assert.equal(new URL(src).searchParams.get('task'), task, 'the iframe\'s link holds the task');
  assert.ok(script.includes(' data-lab-task="Step to the first collision.&#10;Then answer: &quot;why &lt;here&gt;?&quot; &amp; how sure are you?"'), script);
  const iframeHeight = Number(/height="(\d+)"/.exec(iframe)[1]);
  const divHeight = Number(/height:(\d+)px/.exec(script)[1]);
  assert.ok(iframeHeight > 600 && iframeHeight === divHeight, `taller by the task (${iframeHeight})`);
  assert.match(await page.locator('.lab-dialog-task + .lab-dialog-note').textContent(), /^\d+ of 1000 characters$/);
  await screenshot(page, 'task-embed-dialog.png');

  // Pasted into a course page, each snippet shows the task, as text.
  const want = ['Step to the first collision.', 'Then answer: "why <here>?" & how sure are you?'];
  for (const [i, snippet] of [iframe, script].entries()) {
    const host = await newPage(browser, { width: 1000, height: 900 }, ctx);
    const hostErrors = collectErrors(host);
    await hostPage(host, url, `task-host-${i}.html`, snippet);
    let target = host;
    if (i === 0) target = await (await host.waitForSelector('iframe')).contentFrame();
    await target.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2, null, { timeout: 30000 });
    const l = await taskLayout(target);
    assert.deepEqual(l.paragraphs, want, `snippet ${i}`);
    assert.deepEqual(l.tags, ['H2', 'P', 'P']);
    assert.ok(Math.abs(l.canvas.height - 600) <= 30, `snippet ${i}: the canvas keeps about 600 px (${l.canvas.height})`);
    assert.deepEqual(hostErrors, []);
    await host.close();
  }

  // Past 1000 characters: the field says so, the snippets take the first 1000.
  await field.fill('x'.repeat(1200));
  assert.match(await page.locator('.lab-dialog-task + .lab-dialog-note').textContent(), /1200 characters; a task holds at most 1000/);
  assert.equal(await field.getAttribute('aria-invalid'), 'true');
  const [long] = await snippets();
  const longSrc = /src="([^"]+)"/.exec(long)[1].replace(/&amp;/g, '&');
  assert.equal(new URL(longSrc).searchParams.get('task'), 'x'.repeat(1000) + '…');
  assert.deepEqual(errors, []);
}));

test('an over-long task: the first 1000 characters, and a notice', () => withBrowser(async ({ browser, url }) => {
  const page = await newPage(browser, { width: 390, height: 844 });
  const errors = collectErrors(page);
  const words = Array.from({ length: 130 }, (_, i) => `word${String(i).padStart(4, '0')}`).join(' ');
  assert.equal(words.length, 1169);
  await openLab(page, url + 'embed.html?lesson=collision&task=' + encodeURIComponent(words));
  const l = await taskLayout(page);
  assert.match(l.notice, /The task has 1169 characters; a task holds at most 1000, so only the first 1000 are shown\./);
  assert.equal(l.paragraphs.length, 1);
  assert.equal(l.paragraphs[0], words.slice(0, 1000) + '…');
  // On a phone it scrolls within its share of the lab, and the keyboard can reach it for that.
  checkLayout(l, 'long task');
  assert.deepEqual(await page.evaluate(() => {
    const t = document.querySelector('.lab-task');
    return [t.scrollHeight > t.clientHeight + 1, t.tabIndex];
  }), [true, 0]);
  await screenshot(page, 'task-long.png');
  // Too long for a link at all: named, and the lab starts without it.
  await openLab(page, url + 'embed.html?lesson=collision&task=' + 'y'.repeat(13000));
  const m = await taskLayout(page);
  assert.equal(m.present, false);
  assert.match(m.notice, /task: 13 KB is more than a link may carry \(12 KB\)/);
  assert.deepEqual(errors, []);
}));

test('a new task keeps a student\'s saved work (the task is not part of the state)', () => withBrowser(async ({ browser, url }) => {
  const page = await newPage(browser);
  const errors = collectErrors(page);
  await openLab(page, url + 'embed.html?lesson=collision&scene=p12&task=First%20version');
  await page.evaluate(() => window.cspacelab.setParams({ grid_n: 9 }));
  await page.evaluate(() => window.cspacelab.shell.saveNow());
  await openLab(page, url + 'embed.html?lesson=collision&scene=p12&task=Second%20version');
  const l = await taskLayout(page);
  assert.deepEqual(l.paragraphs, ['Second version']);
  assert.equal(await page.evaluate(() => window.cspacelab.state().grid_n), 9, 'the student\'s N stays');
  assert.equal(l.notice, '');
  assert.deepEqual(errors, []);
}));
