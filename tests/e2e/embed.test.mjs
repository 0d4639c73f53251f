// Embedding: embed.html in an iframe fills it and follows its size, shows the minimal UI, and
// lets the wheel scroll the host page until it is clicked; the "Embed" button's snippets (iframe
// and script tag), pasted into a page, show the lab as it was.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, collectErrors, openLab, click, waitFrames, api, pageButton, screenshot, expectView,
         sceneProbes } from './lib/harness.mjs';

// A page of the same site made up on the spot (playwright answers the request).
async function hostPage(page, url, body) {
  const host = url + 'test-host.html';
  await page.route(host, (route) => route.fulfill({
    contentType: 'text/html',
    body: `<!doctype html><html><head><meta charset="utf-8"><title>host</title>
      <style>body{margin:0;font:16px serif} .pad{height:700px;background:#eef} .after{height:1500px}</style></head>
      <body><div class="pad">Course text above the lab.</div>${body}<div class="after">More text.</div></body></html>`,
  }));
  await page.goto(host);
}

async function labFrame(page) {
  const handle = await page.waitForSelector('iframe');
  const frame = await handle.contentFrame();
  await frame.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2, null, { timeout: 30000 });
  return frame;
}

test('embed.html in an iframe: fits, follows resizes, no scroll hijack, minimal UI',
  () => withBrowser(async ({ browser, url }) => {
  const page = await browser.newPage({ viewport: { width: 1000, height: 700 } });
  const errors = collectErrors(page);
  await hostPage(page, url, `<iframe id="f" src="embed.html?lesson=collision&amp;scene=p12&amp;grid_n=6"
    style="border:0;width:600px;height:380px;display:block;margin:0 auto" title="lab"></iframe>`);
  const frame = await labFrame(page);
  const st = await frame.evaluate(() => ({ ps: window.cspacelab.pageState(), s: window.cspacelab.state(),
                                           n: window.cspacelab.status().notice }));
  assert.equal(st.ps.minimal, true, 'minimal UI');
  assert.equal(st.s.grid_n, 6);
  assert.equal(st.n, '');
  const size = () => frame.evaluate(() => [window.cspacelab.module.canvas.width, window.cspacelab.module.canvas.height]);
  assert.deepEqual(await size(), [600, 380], 'the canvas fills the iframe');
  await page.evaluate(() => window.scrollTo(0, 400));
  // The P12 scene in the iframe, as its geometry says: the disk, p and q, free space off the line.
  const p12 = await frame.evaluate(() => window.cspacelab.getScene());
  await expectView(page, browser, 'embed-iframe.png', [
    // (the disk above the line: across its centre lies the grid's tick at t = 0.2, in collision)
    ...sceneProbes(p12, { free: 8, avoid: [[p12.start, p12.goal]] }).filter((p) => p.why !== 'inside a disk'),
    { at: [0.2, 0.12], look: 'obstacle', why: 'the disk above the line' },
  ], 'workspace', { frame });

  // The container grows: the lab follows.
  await page.evaluate(() => Object.assign(document.getElementById('f').style, { width: '820px', height: '460px' }));
  await frame.waitForFunction(() => window.cspacelab.module.canvas.width === 820 && window.cspacelab.module.canvas.height === 460);
  await waitFrames(frame, 3);
  const view = await frame.evaluate(() => window.cspacelab.view());
  assert.ok(view.canvas_max[0] > 700, 'the views use the new width');

  // The wheel over the unfocused lab scrolls the host page...
  await page.evaluate(() => window.scrollTo(0, 300));
  const box = await page.locator('#f').boundingBox();
  const over = { x: box.x + box.width * 0.75, y: box.y + box.height * 0.35 };
  const scale = view.scale;
  await page.mouse.move(over.x, over.y);
  await page.mouse.wheel(0, 250);
  await page.waitForFunction(() => window.scrollY > 400);
  assert.equal((await frame.evaluate(() => window.cspacelab.view())).scale, scale, 'and does not zoom');
  // ...and once clicked it zooms the lab instead.
  const box2 = await page.locator('#f').boundingBox();
  const at = { x: box2.x + box2.width * 0.75, y: box2.y + box2.height * 0.35 };
  await page.mouse.click(at.x, at.y);
  await waitFrames(frame, 2);
  const y = await page.evaluate(() => window.scrollY);
  await page.mouse.wheel(0, -200);
  await waitFrames(frame, 4);
  assert.ok((await frame.evaluate(() => window.cspacelab.view())).scale > scale * 1.05, 'zooms when focused');
  assert.equal(await page.evaluate(() => window.scrollY), y, 'the page stays');
  await screenshot(page, 'embed-iframe-resized.png');
  assert.deepEqual(errors, []);
}));

test('the Embed button\'s snippets reproduce the lab in another page', () => withBrowser(async ({ browser, url }) => {
  const ctx = await browser.newContext({ viewport: { width: 1200, height: 760 } });
  const page = await ctx.newPage();
  const errors = collectErrors(page);
  await openLab(page, url);
  await api(page, 'select_lesson', { id: 'step-prm' });
  await api(page, 'set_scene', { scene: { version: 1, obstacles: [{ type: 'disk', center: [0.5, 0.5], radius: 0.2 }],
                                          start: [0.1, 0.1], goal: [0.9, 0.9] } });
  await api(page, 'set_params', { params: { samples: 70, seed: 11 } });
  await api(page, 'run_to', { steps: 33 });
  const want = await api(page, 'state');
  await click(page, await pageButton(page, 'embed'));
  await page.waitForSelector('.lab-dialog textarea');
  const [iframe, script] = await page.$$eval('.lab-dialog textarea', (a) => a.map((t) => t.value));
  await screenshot(page, 'embed-dialog.png');
  assert.match(iframe, /^<iframe src="http:\/\/127\.0\.0\.1:\d+\/embed\.html\?lesson=step-prm&amp;scene=z\./);
  assert.match(script, /<script src="http:\/\/127\.0\.0\.1:\d+\/lab\.js" defer><\/script>$/);

  for (const snippet of [iframe, script]) {
    const other = await ctx.newPage();
    const otherErrors = collectErrors(other);
    await hostPage(other, url, snippet);
    let state;
    if (snippet.startsWith('<iframe')) {
      const frame = await labFrame(other);
      state = await frame.evaluate(() => window.cspacelab.state());
      assert.equal(await frame.evaluate(() => window.cspacelab.pageState().minimal), true);
    } else {
      await other.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2, null, { timeout: 30000 });
      state = await other.evaluate(() => window.cspacelab.state());
      assert.equal(await other.evaluate(() => window.cspacelab.pageState().minimal), true);
    }
    assert.equal(state.roadmap_hash, want.roadmap_hash, 'the same roadmap');
    assert.equal(state.steps, 33, 'at the same step');
    // The scene drawn in the other page: the disk and the markers (33 steps in: samples, no edges
    // yet, so free space may hold vertices; only the disk and markers are certain).
    const frame = snippet.startsWith('<iframe') ? await (await other.$('iframe')).contentFrame() : null;
    await (frame ? other.locator('iframe') : other.locator('[data-lab]')).scrollIntoViewIfNeeded();
    const shown = await (frame || other).evaluate(() => window.cspacelab.getScene());
    await expectView(other, browser, snippet.startsWith('<iframe') ? 'embed-snippet-iframe.png' : 'embed-snippet-script.png',
                     sceneProbes(shown, { free: 0 }), 'workspace', { frame });
    assert.deepEqual(otherErrors, []);
    await other.close();
  }
  assert.deepEqual(errors, []);
}));
