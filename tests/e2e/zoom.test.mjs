// 200% browser zoom (WCAG 2.1 1.4.4 resize text, 1.4.10 reflow): a 1280 x 800 window at zoom 2
// is a 640 x 400 CSS viewport at 2 device pixels per CSS pixel. The page must not scroll
// sideways or cut the lab, the lab must draw at the device's resolution, every control of the
// page's dialogs must be reachable, and axe must still pass. The app takes its compact layout
// there (a lesson menu, tabs, the playback strip over a view the width of the window).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, collectErrors, openLab, waitFrames, api, screenshot } from './lib/harness.mjs';
import { newAxeContext, runAxe } from './lib/axe.mjs';

const ZOOMED = { viewport: { width: 640, height: 400 }, deviceScaleFactor: 2 };

test('200% zoom: the lab fills the window, nothing scrolls sideways, dialogs fit and pass axe',
  () => withBrowser(async ({ browser, url }) => {
  const context = await newAxeContext(browser, ZOOMED);
  await context.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
  const page = await context.newPage();
  const errors = collectErrors(page);
  await openLab(page, url + '?lesson=step-prm&scene=wall-gap&samples=120&seed=7&steps=200');
  const layout = await page.evaluate(() => {
    const c = document.querySelector('canvas');
    const r = c.getBoundingClientRect();
    return { scrollW: document.documentElement.scrollWidth, scrollH: document.documentElement.scrollHeight,
             w: innerWidth, h: innerHeight, canvas: [r.left, r.top, r.width, r.height], px: [c.width, c.height] };
  });
  assert.ok(layout.scrollW <= layout.w && layout.scrollH <= layout.h, `no page scrolling: ${JSON.stringify(layout)}`);
  assert.deepEqual(layout.canvas, [0, 0, 640, 400], 'the lab fills the window');
  assert.deepEqual(layout.px, [1280, 800], 'drawn at the device\'s resolution');
  const status = await api(page, 'status');
  assert.equal(status.pixel_ratio, 2);
  const { buttons } = await api(page, 'page_state');
  const shown = Object.entries(buttons).filter(([, r]) => r[0] >= 0 && r[2] <= 640 && r[1] >= 0 && r[3] <= 400)
    .map(([n]) => n);
  console.log(`# at 200%: layout ${JSON.stringify(status.layout)}; page controls on screen: ${shown.join(', ')}`);
  // 640 x 400 CSS px takes the compact layout: the workspace gets the width, not a corner.
  assert.equal(status.layout.mode, 'compact');
  const ws = status.layout.views.find((v) => v.name === 'workspace');
  assert.ok(ws && ws.w >= 600 && ws.h >= 150, `the workspace view at 200%: ${JSON.stringify(ws)}`);
  for (const name of ['lesson-menu', 'tab:view', 'tab:controls', 'step', 'run-all', 'share'])
    assert.ok(shown.includes(name), `${name} is on screen at 200%`);
  await page.mouse.move(1, 1);
  await waitFrames(page, 3);
  await screenshot(page, 'zoom-200.png');

  // The dialogs: the box within the window, each control reachable (the box scrolls) and visible.
  for (const action of ['share', 'embed']) {
    await page.evaluate((a) => window.cspacelab.module.cslPageAction(a), action);
    await page.waitForSelector('.lab-dialog[role=dialog]');
    await screenshot(page, `zoom-200-${action}.png`);
    const box = await page.locator('.lab-dialog-box').boundingBox();
    assert.ok(box.x >= 0 && box.y >= 0 && box.x + box.width <= 640 && box.y + box.height <= 400,
              `${action}: the dialog within the window: ${JSON.stringify(box)}`);
    const controls = page.locator('.lab-dialog-box button, .lab-dialog-box textarea');
    for (let i = 0; i < await controls.count(); ++i) {
      const control = controls.nth(i);
      await control.scrollIntoViewIfNeeded();
      const r = await control.boundingBox();
      assert.ok(r && r.width >= 24 && r.height >= 20 && r.x >= box.x && r.x + r.width <= box.x + box.width + 0.5 &&
                r.y >= box.y - 0.5 && r.y + r.height <= box.y + box.height + 0.5,
                `${action}: control ${i} reachable and whole: ${JSON.stringify(r)} in ${JSON.stringify(box)}`);
    }
    const { blocking } = await runAxe(page);
    assert.deepEqual(blocking, [], `${action} dialog at 200%`);
    await page.keyboard.press('Escape');
    await page.waitForSelector('.lab-dialog', { state: 'detached' });
  }
  assert.deepEqual((await runAxe(page)).blocking, [], 'the lab at 200%');
  assert.deepEqual(errors, []);
}));
