// The look (WCAG 2.1 1.4.3, 1.4.11; issue 12 item 5, issue 19's dark theme): light or dark, normal
// or high contrast, chosen in File > Display with the mouse, in the parallel DOM by keyboard, by a
// link (scheme=, contrast=) for one visit, or left to the browser (prefers-color-scheme,
// prefers-contrast). The choice is kept for later visits; a link's is not. Each is checked
// where a student sees it: the canvas's pixels, the page's own parts, and the app's `theme`.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, collectErrors, openLab, waitFrames, api, pageButton, screenshot } from './lib/harness.mjs';
import { contrast } from './lib/colour.mjs';

/** The colour of the canvas at a CSS point of the page (a real screenshot, as a student sees it). */
async function pixel(page, x, y) {
  const png = await page.screenshot({ clip: { x, y, width: 1, height: 1 } });
  const rgba = await page.evaluate(async (b64) => {
    const img = new Image();
    img.src = 'data:image/png;base64,' + b64;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = c.height = 1;
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0);
    return Array.from(g.getImageData(0, 0, 1, 1).data);
  }, png.toString('base64'));
  return rgba.slice(0, 3);
}

/** A free spot of the Step PRM workspace (its canvas colour), in page pixels. */
async function canvasSpot(page) {
  const scene = await api(page, 'get_scene');
  // Between grid lines (minor lines every 0.05 here), away from obstacles and roadmap.
  const { points } = await api(page, 'view', { points: [[scene.workspace.min[0] + 0.037, scene.workspace.max[1] - 0.313]] });
  const box = await page.evaluate(() => window.cspacelab.module.canvas.getBoundingClientRect().toJSON());
  return [box.x + points[0][0], box.y + points[0][1]];
}

const luminous = ([r, g, b]) => (r + g + b) / 3;

async function newLab(browser, url, link = '', media = {}) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  await context.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
  const page = await context.newPage();
  if (Object.keys(media).length) await page.emulateMedia(media);
  const errors = collectErrors(page);
  await openLab(page, url + link);
  return { context, page, errors };
}

test('File > Display by mouse: dark, then high contrast; the canvas and the page follow, and a reload keeps it',
  () => withBrowser(async ({ browser, url }) => {
  const { context, page, errors } = await newLab(browser, url, '?lesson=step-prm&scene=prm-demo');
  const spot = await canvasSpot(page);
  const light = await pixel(page, ...spot);
  assert.ok(luminous(light) > 200, `a light canvas first: rgb(${light})`);
  assert.equal(await page.evaluate(() => document.querySelector('.lab').dataset.look), 'light');

  const choose = async (item) => {
    const file = await pageButton(page, 'file');
    await page.mouse.click(file.x, file.y);
    await waitFrames(page, 2);
    const display = await pageButton(page, 'display');
    assert.ok(display, 'File lists Display');
    await page.mouse.move(display.x, display.y);
    await waitFrames(page, 4);  // the submenu opens on hover
    const at = await pageButton(page, item);
    assert.ok(at, `Display lists ${item}`);
    await page.mouse.click(at.x, at.y);
    await waitFrames(page, 3);
  };
  await choose('scheme-dark');
  assert.deepEqual((await api(page, 'page_state')).look, { dark: true, high_contrast: false });
  const dark = await pixel(page, ...spot);
  assert.ok(luminous(dark) < 50, `the canvas is dark: rgb(${dark})`);
  assert.equal(await page.evaluate(() => document.querySelector('.lab').dataset.look), 'dark');
  // The page's parts follow: its background and a dialog.
  const bg = await page.evaluate(() => getComputedStyle(document.querySelector('.lab')).backgroundColor);
  assert.equal(bg, 'rgb(32, 34, 38)');
  await screenshot(page, 'look-dark.png');

  await choose('contrast-high');
  const theme = await api(page, 'theme');
  assert.deepEqual(theme.look, { dark: true, high_contrast: true });
  // High contrast is higher: the panel's text on the panel reaches 7:1 (AAA), and the
  // secondary text 4.5:1 at least (it is 2.6:1 in ImGui's own light style).
  const pair = (name) => theme.text.find((t) => t.name === name);
  assert.ok(contrast(pair('text on the panel').fg, pair('text on the panel').bg) >= 7);
  assert.ok(contrast(pair('secondary text on the panel').fg, pair('secondary text on the panel').bg) >= 7);
  await screenshot(page, 'look-dark-high.png');
  assert.deepEqual(JSON.parse(await page.evaluate(() => localStorage.getItem('cspacelab:v1:look'))),
                   { scheme: 'dark', contrast: 'high' }, 'the choice is kept');

  // A later visit (a new page, the same browser) opens in the chosen look.
  const again = await context.newPage();
  await openLab(again, url + '?lesson=step-prm&scene=prm-demo');
  assert.deepEqual((await api(again, 'page_state')).look, { dark: true, high_contrast: true });
  const kept = await pixel(again, ...(await canvasSpot(again)));
  assert.ok(luminous(kept) < 20, `the reload is dark, high contrast (black): rgb(${kept})`);
  assert.deepEqual(errors, []);
  await context.close();
}));

test('a link sets the look for one visit; the browser\'s preference applies otherwise', () => withBrowser(async ({ browser, url }) => {
  // scheme=dark in a link: dark now, nothing stored.
  const linked = await newLab(browser, url, '?lesson=torus&scheme=dark');
  assert.deepEqual((await api(linked.page, 'page_state')).look, { dark: true, high_contrast: false });
  assert.equal(await linked.page.evaluate(() => localStorage.getItem('cspacelab:v1:look')), null);
  assert.equal((await api(linked.page, 'status')).notice || '', '', 'no complaint about the key');
  assert.deepEqual(linked.errors, []);
  await linked.context.close();
  // A wrong value is reported and ignored.
  const wrong = await newLab(browser, url, '?lesson=torus&contrast=max');
  const notice = await wrong.page.evaluate(() => window.cspacelab.status().notice || '');
  assert.match(notice, /contrast "max" \(system, normal, high\)/);
  assert.deepEqual((await api(wrong.page, 'page_state')).look, { dark: false, high_contrast: false });
  await wrong.context.close();
  // The system asks for dark and more contrast; the student has chosen nothing.
  const system = await newLab(browser, url, '?lesson=collision', { colorScheme: 'dark', contrast: 'more' });
  assert.deepEqual((await api(system.page, 'page_state')).look, { dark: true, high_contrast: true });
  // ... and changes its mind while the lab is open.
  await system.page.emulateMedia({ colorScheme: 'light', contrast: 'no-preference' });
  await system.page.waitForFunction(() => !window.cspacelab.pageState().look.dark && !window.cspacelab.pageState().look.high_contrast);
  // The student's choice beats the system's.
  await api(system.page, 'page_state', { scheme: 'dark' });
  await system.page.emulateMedia({ colorScheme: 'light' });
  await waitFrames(system.page, 2);
  assert.equal((await api(system.page, 'page_state')).look.dark, true);
  await system.context.close();
}));

test('the parallel DOM: Display by keyboard alone', () => withBrowser(async ({ browser, url }) => {
  const { context, page, errors } = await newLab(browser, url, '?lesson=step-prm');
  await page.focus('.lab-access select[id$="-contrast"]');
  await page.keyboard.press('End');  // the last option: high
  await page.waitForFunction(() => window.cspacelab.pageState().look.high_contrast === true);
  assert.equal(await page.evaluate(() => document.querySelector('.lab').dataset.look), 'light high');
  assert.deepEqual(JSON.parse(await page.evaluate(() => localStorage.getItem('cspacelab:v1:look'))),
                   { scheme: 'system', contrast: 'high' });
  // The app's own change shows in the select.
  await api(page, 'page_state', { scheme: 'dark' });
  await page.waitForFunction(() => document.querySelector('.lab-access select[id$="-scheme"]').value === 'dark');
  assert.deepEqual(errors, []);
  await context.close();
}));
