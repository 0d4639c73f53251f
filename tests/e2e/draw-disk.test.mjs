// The chain works end to end: the wasm app loads in real Chromium, renders, and a mouse drag on
// the workspace creates a disk (centre = press point, radius = drag distance) that the app's
// JS API reports and the screenshot shows.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { startServer, launchBrowser, collectErrors, openLab, worldToPage, drag, waitFrames,
         screenshot, inspectPng } from './lib/harness.mjs';

test('dragging on the workspace canvas creates a disk obstacle', async () => {
  const { server, url } = await startServer();
  const browser = await launchBrowser();
  try {
    // A HiDPI screen: the app must render at 2 device pixels per CSS pixel.
    const page = await browser.newPage({ viewport: { width: 1100, height: 720 }, deviceScaleFactor: 2 });
    const errors = collectErrors(page);
    await openLab(page, url);

    const status = await page.evaluate(() => window.cspacelab.status());
    assert.equal(status.pixel_ratio, 2, 'renders at the device pixel ratio');
    assert.equal((await page.evaluate(() => window.cspacelab.getScene())).obstacles.length, 0);

    const [from, to] = await worldToPage(page, [[0.5, 0.6], [0.65, 0.6]]);
    await drag(page, from, to);
    await waitFrames(page, 3);

    const scene = await page.evaluate(() => window.cspacelab.getScene());
    assert.equal(scene.obstacles.length, 1, 'one disk after one drag');
    const disk = scene.obstacles[0];
    const { scale } = await page.evaluate(() => window.cspacelab.view());
    const pixel = 1 / scale;  // one CSS pixel in world units
    assert.equal(disk.type, 'disk');
    assert.ok(Math.abs(disk.center[0] - 0.5) <= 1.5 * pixel, `centre x ${disk.center[0]}`);
    assert.ok(Math.abs(disk.center[1] - 0.6) <= 1.5 * pixel, `centre y ${disk.center[1]}`);
    assert.ok(Math.abs(disk.radius - 0.15) <= 2.5 * pixel, `radius ${disk.radius}`);

    // A click without a drag makes no disk.
    const [click] = await worldToPage(page, [[0.2, 0.2]]);
    await page.mouse.click(click.x, click.y);
    await waitFrames(page, 3);
    assert.equal((await page.evaluate(() => window.cspacelab.getScene())).obstacles.length, 1);

    // Bad input through the API is refused and loses nothing.
    const refused = await page.evaluate(() => {
      try { window.cspacelab.setScene({ version: 1, obstacles: [{ type: 'disk', center: [0, 0], radius: -1 }] }); }
      catch (e) { return e.message; }
      return null;
    });
    assert.equal(refused, 'obstacles[0].radius: must be >= 0');
    assert.equal((await page.evaluate(() => window.cspacelab.getScene())).obstacles.length, 1);

    // The picture: not blank, the disk's centre is obstacle grey, the free workspace is white.
    const { png } = await screenshot(page, 'draw-disk.png');
    const [centre] = await worldToPage(page, [[0.5, 0.6]]);
    const [free] = await worldToPage(page, [[0.93, 0.13]]);
    const shot = await inspectPng(browser, png, [[centre.x * 2, centre.y * 2], [free.x * 2, free.y * 2]]);
    assert.equal(shot.width, 2200, 'screenshot at device resolution');
    assert.ok(shot.colours > 30, `a rendered UI has many colours, got ${shot.colours}`);
    const [r, g, b] = shot.at[0];
    assert.ok(r < 170 && g < 170 && b < 175 && Math.abs(r - g) < 12, `disk centre pixel ${shot.at[0]}`);
    assert.deepEqual(shot.at[1], [255, 255, 255], 'free workspace is white');

    assert.deepEqual(errors, [], 'no console errors');
  } finally {
    await browser.close();
    server.close();
  }
});
