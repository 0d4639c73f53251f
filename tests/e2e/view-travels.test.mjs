// The view travels: a view zoomed with the wheel and panned with a right-drag (a 3-D view turned
// with a left-drag) comes back the same in a Share link opened in a fresh browser, in the Embed
// dialog's snippets and after a reload (autosave); a link of an unzoomed lab has no camera; and a
// scene drawn over stops claiming a bundled scene's name (Share then encodes it whole), until an
// undo brings the original back.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, withPage, collectErrors, openLab, click, waitFrames, api, pixelDifference, pageButton, screenshot,
         drawDisk, chord, worldToPage, inspectPng, LOOKS } from './lib/harness.mjs';

const VIEWPORT = { width: 1280, height: 800 };

/** The rectangle (page CSS px) of a view status().layout.views reports. */
async function viewRect(page, name) {
  const { views } = (await api(page, 'status')).layout;
  const v = views.find((x) => x.name === name);
  assert.ok(v, `the view ${name} is on screen (${views.map((x) => x.name).join(', ')})`);
  const box = await page.locator('canvas').boundingBox();
  return { x: box.x + v.x, y: box.y + v.y, width: v.w, height: v.h };
}

/**
 * Pans a view with a real right-drag by (dx, dy) CSS px from its centre, then zooms in with
 * `notches` turns of the wheel (each x1.2) at `at` (a share of the view's width and height).
 */
async function panAndZoom(page, name, { dx = 0, dy = 0, notches = 4, at = [0.5, 0.5] } = {}) {
  const r = await viewRect(page, name);
  const from = { x: r.x + r.width / 2, y: r.y + r.height / 2 };
  await page.mouse.move(from.x, from.y);
  await waitFrames(page, 2);
  await page.mouse.down({ button: 'right' });
  await waitFrames(page, 2);
  for (let i = 1; i <= 6; ++i) {
    await page.mouse.move(from.x + dx * i / 6, from.y + dy * i / 6);
    await waitFrames(page, 1);
  }
  await page.mouse.up({ button: 'right' });
  await waitFrames(page, 2);
  await page.mouse.move(r.x + r.width * at[0], r.y + r.height * at[1]);
  await waitFrames(page, 2);
  for (let i = 0; i < notches; ++i) {  // (SDL makes one notch of each wheel event, whatever its size)
    await page.mouse.wheel(0, -100);
    await waitFrames(page, 2);
  }
  await waitFrames(page, 2);
}

/** Turns the 3-D view with a real left-drag across it. */
async function turn(page, name, dx, dy) {
  const r = await viewRect(page, name);
  const from = { x: r.x + r.width / 2, y: r.y + r.height / 2 };
  await page.mouse.move(from.x, from.y);
  await waitFrames(page, 2);
  await page.mouse.down();
  await waitFrames(page, 2);
  for (let i = 1; i <= 8; ++i) {
    await page.mouse.move(from.x + dx * i / 8, from.y + dy * i / 8);
    await waitFrames(page, 1);
  }
  await page.mouse.up();
  await waitFrames(page, 2);
}

/** A picture of one view (page pixels), the mouse off the canvas first (no hover, no ghost). */
async function viewPicture(page, name) {
  await page.mouse.move(2, 2);
  await waitFrames(page, 3);
  return page.screenshot({ clip: await viewRect(page, name) });
}

/** How two pictures of the same size differ: {size, share} with share the part of the pixels off by more than `levels` in a channel. */
async function difference(browser, a, b, levels = 40) {
  const d = await pixelDifference(browser, a, b, levels);
  return { size: !d.size, share: d.size ? 1 : d.differ };
}

/** The Share button's link (a real click), the dialog closed again. */
async function shareLink(page) {
  await click(page, await pageButton(page, 'share'));
  await page.waitForSelector('.lab-dialog textarea');
  const link = await page.inputValue('.lab-dialog textarea');
  await page.keyboard.press('Escape');
  await page.waitForSelector('.lab-dialog', { state: 'detached' });
  return link;
}

/** Opens `link` in a fresh browser profile of the same window size. */
async function openFresh(browser, link) {
  const ctx = await browser.newContext({ viewport: VIEWPORT });
  const page = await ctx.newPage();
  const errors = collectErrors(page);
  await openLab(page, link);
  await waitFrames(page, 3);
  return { ctx, page, errors };
}

/** World points of a plane view to page pixels: the same in both pages to a hundredth of a pixel. */
async function sameMapping(a, b, name, points) {
  const [pa, pb] = [await worldToPage(a, points, name), await worldToPage(b, points, name)];
  pa.forEach((p, i) => {
    assert.ok(Math.abs(p.x - pb[i].x) < 0.02 && Math.abs(p.y - pb[i].y) < 0.02,
              `${name}: (${points[i]}) at ${p.x},${p.y} and ${pb[i].x},${pb[i].y}`);
  });
}

test('Step PRM: a zoomed and panned view comes back the same through Share, pixel for pixel',
  (t) => withBrowser(async ({ browser, url }) => {
  const ctx = await browser.newContext({ viewport: VIEWPORT, permissions: ['clipboard-read', 'clipboard-write'] });
  const page = await ctx.newPage();
  await page.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
  const errors = collectErrors(page);
  await openLab(page, url + '?lesson=step-prm&scene=wall-gap&samples=150&seed=4&steps=260');
  await page.waitForFunction(() => !window.cspacelab.status().busy);
  const fitted = await viewPicture(page, 'workspace');
  const unzoomed = await shareLink(page);
  assert.doesNotMatch(unzoomed, /camera=/, 'a view as it starts adds nothing to the link');

  // A right-drag 120 px left and 60 px up, then the wheel at a third of the view's width.
  const before = await api(page, 'view', { view: 'workspace', points: [[0.5, 0.5]] });
  await panAndZoom(page, 'workspace', { dx: -120, dy: -60, at: [0.35, 0.4] });
  const [cx, cy, cz] = (await api(page, 'camera')).workspace;
  const after = await api(page, 'view', { view: 'workspace', points: [[0.5, 0.5]] });
  assert.ok(Math.abs(cz - 1.2 ** 4) < 1e-4, `zoomed in 4 notches (zoom ${cz})`);
  assert.ok(after.scale > before.scale * 1.5, 'the view\'s scale grew with it');
  // (wall-gap is the unit square: the drag moved the picture left and up, the view's centre
  // right and down in the world, and the wheel left of centre drew it back part of the way.)
  assert.ok(cx > 0.52 && cy < 0.48, `panned (centre ${cx}, ${cy})`);
  assert.ok(Math.abs(after.center[0] - cx) <= 1 / after.scale && Math.abs(after.center[1] - cy) <= 1 / after.scale,
            'the view\'s middle is the camera\'s centre (to the pixel the canvas snaps it to)');
  assert.equal(after.fit_button, true, 'the Fit button shows');
  const zoomed = await viewPicture(page, 'workspace');
  const changed = (await difference(browser, fitted, zoomed)).share;
  assert.ok(changed > 0.02, `the picture changed (so a comparison can fail): ${(changed * 100).toFixed(1)} % of it`);
  await screenshot(page, 'view-travels-original.png');

  const link = await shareLink(page);
  const u = new URL(link);
  assert.match(u.searchParams.get('camera'), /^workspace:-?[\d.]+,-?[\d.]+,[\d.]+$/);
  assert.ok(link.length < 200, `still a short link (${link.length} characters)`);
  const [x, y, zoom] = u.searchParams.get('camera').slice('workspace:'.length).split(',').map(Number);
  assert.deepEqual([x, y, zoom], (await api(page, 'snapshot')).camera.workspace, 'the snapshot\'s camera');
  assert.deepEqual([x, y, zoom], [cx, cy, cz], 'the numbers on screen, rounded as the link writes them');
  assert.ok(String(x).length <= 8 && String(zoom) === '2.0736', `short numbers (${x}, ${y}, ${zoom})`);

  const other = await openFresh(browser, link);
  assert.equal((await api(other.page, 'status')).notice, '', 'a good link: no complaint');
  assert.deepEqual((await api(other.page, 'camera')).workspace, [x, y, zoom]);
  assert.equal((await api(other.page, 'state')).roadmap_hash, (await api(page, 'state')).roadmap_hash, 'the same roadmap');
  await sameMapping(page, other.page, 'workspace', [[0, 0], [0.5, 0.5], [1, 1], [0.3, 0.8]]);
  const reopened = await viewPicture(other.page, 'workspace');
  await screenshot(other.page, 'view-travels-opened.png');
  const d = await difference(browser, zoomed, reopened);
  assert.ok(d.size && d.share < 0.003, `the same region, the same pixels (${(d.share * 100).toFixed(3)} % differ)`);
  t.diagnostic(`zoom ${cz}: ${(changed * 100).toFixed(1)} % of the view changed; the link's page differs in ${(d.share * 100).toFixed(4)} %`);
  // Opened zoomed, the view shows its way back: the Fit button, drawn over the zoomed scene (it
  // was drawn under the world rectangle once that covered the canvas).
  const fit = await other.page.evaluate(() => {
    const r = window.cspacelab.pageState().buttons['fit##prm-workspace'];
    const box = window.cspacelab.module.canvas.getBoundingClientRect();
    return r && { x: box.left + r[0], y: box.top + r[1], width: r[2] - r[0], height: r[3] - r[1] };
  });
  assert.ok(fit && fit.width > 40, 'the Fit button is on screen');
  const { at } = await inspectPng(browser, await other.page.screenshot({ clip: fit }),
                                  [[3, fit.height / 2], [fit.width - 3, fit.height / 2]]);
  for (const c of at) assert.ok(!LOOKS.canvas(c), `the button's face, not the canvas under it: rgb(${c})`);
  // Its log says what the link restored.
  const note = (await api(other.page, 'log'))[0];
  assert.equal(note.note, true);
  assert.match(note.text, /^Restored from the link at step 260, scene "P9: a wall with a gap"; the workspace zoomed 2\.07x\. Earlier steps are not listed\.$/);
  assert.deepEqual(other.errors, []);
  await other.ctx.close();

  // A link with the camera of a view the lesson has not, or an absurd zoom: named, the rest applies.
  const bad = await openFresh(browser, url + '?lesson=step-prm&scene=wall-gap&steps=5&camera=workspace:0.5,0.5,5000');
  assert.match((await api(bad.page, 'status')).notice,
               /camera "workspace:0\.5,0\.5,5000" \(workspace's zoom 5000 is outside \[0\.5, 200\] \(1: the whole view\)\)/);
  assert.equal((await api(bad.page, 'state')).steps, 5, 'the good parts applied');
  assert.deepEqual((await api(bad.page, 'camera')).workspace, [0.5, 0.5, 1], 'the view as it starts');
  await bad.page.goto(url + '?lesson=step-prm&camera=torus:1,2');
  await bad.page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2);
  assert.match((await api(bad.page, 'status')).notice, /camera "torus:1,2" \(this lesson has no view "torus" \(its views: workspace\)\)/);
  await bad.ctx.close();
  assert.deepEqual(errors, []);
}));

test('the torus lesson: both planes and the 3-D turn travel through Share and Embed',
  (t) => withBrowser(async ({ browser, url }) => {
  const ctx = await browser.newContext({ viewport: VIEWPORT, permissions: ['clipboard-read', 'clipboard-write'] });
  const page = await ctx.newPage();
  await page.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
  const errors = collectErrors(page);
  await openLab(page, url + '?lesson=torus&view=both&samples=200&seed=9&steps=400');
  await page.waitForFunction(() => !window.cspacelab.status().busy);
  await panAndZoom(page, 'cspace', { dx: 50, dy: 40, notches: 3 });
  await panAndZoom(page, 'workspace', { dx: -30, dy: 0, notches: 2, at: [0.6, 0.5] });
  const start = await api(page, 'camera');
  assert.deepEqual(start.torus, [0.6, 0.9], 'the 3-D view as it starts');
  await turn(page, 'torus', 80, -40);
  const camera = await api(page, 'camera');
  assert.ok(Math.abs(camera.torus[0] - (0.6 + 0.8)) < 0.02, `turned by 0.01 rad a pixel across (yaw ${camera.torus[0]})`);
  assert.ok(Math.abs(camera.torus[1] - (0.9 - 0.4)) < 0.02, `and tilted (pitch ${camera.torus[1]})`);
  assert.ok(camera.cspace[2] === 1.728 && camera.workspace[2] === 1.44, JSON.stringify(camera));
  assert.deepEqual(Object.keys((await api(page, 'snapshot')).camera).sort(), ['cspace', 'torus', 'workspace']);
  const pictures = { cspace: await viewPicture(page, 'cspace'), torus: await viewPicture(page, 'torus') };

  // Share: a fresh page shows the same square, the same turn of the torus.
  const link = await shareLink(page);
  const value = new URL(link).searchParams.get('camera');
  assert.deepEqual(value.split('~').map((v) => v.replace(/:.*/, '')).sort(), ['cspace', 'torus', 'workspace']);
  assert.match(value, /(^|~)torus:-?[\d.]+,-?[\d.]+(~|$)/);
  const other = await openFresh(browser, link);
  assert.deepEqual(await api(other.page, 'camera'), (await api(page, 'snapshot')).camera);
  await sameMapping(page, other.page, 'cspace', [[-3, -3], [0, 0], [1, 2.5]]);
  for (const name of ['cspace', 'torus']) {
    const d = await difference(browser, pictures[name], await viewPicture(other.page, name));
    assert.ok(d.size && d.share < 0.005, `${name}: the same picture (${(d.share * 100).toFixed(3)} % differ)`);
    t.diagnostic(`${name}: ${(d.share * 100).toFixed(4)} % of the pixels differ`);
  }
  await screenshot(other.page, 'view-travels-torus-opened.png');
  assert.match((await api(other.page, 'log'))[0].text,
               /^Restored from the link at step 400, scene "2-link arm among disks"; the cspace zoomed 1\.73x, the torus turned, the workspace zoomed 1\.44x\./);
  assert.deepEqual(other.errors, []);
  await other.ctx.close();

  // Embed: both snippets carry the camera; the iframe's lab looks where this one does.
  await click(page, await pageButton(page, 'embed'));
  await page.waitForSelector('.lab-dialog textarea');
  const [iframe, script] = await page.$$eval('.lab-dialog textarea', (a) => a.map((t) => t.value));
  for (const snippet of [iframe, script]) assert.ok(snippet.includes('camera=' + value), snippet);
  const src = /src="([^"]+)"/.exec(iframe)[1].replace(/&amp;/g, '&');
  const embedded = await openFresh(browser, src);
  assert.equal((await api(embedded.page, 'page_state')).minimal, true);
  assert.deepEqual(await api(embedded.page, 'camera'), (await api(page, 'snapshot')).camera);
  // Its square is another size (no side panel's width taken from it): the same centre and zoom.
  const v = await api(embedded.page, 'view', { view: 'cspace' });
  const px = 1 / v.scale;  // one CSS pixel in radians
  assert.ok(Math.abs(v.center[0] - camera.cspace[0]) <= px && Math.abs(v.center[1] - camera.cspace[1]) <= px,
            `the square's centre ${v.center} is the camera's ${camera.cspace.slice(0, 2)}`);
  assert.deepEqual(embedded.errors, []);
  await embedded.ctx.close();
  assert.deepEqual(errors, []);
}));

test('autosave keeps the zoom through a reload, and the log says what came back',
  (t) => withPage({ open: '?lesson=collision&scene=p12' }, async ({ page }) => {
  await panAndZoom(page, 'workspace', { dx: 40, dy: 30, notches: 4 });
  const camera = (await api(page, 'snapshot')).camera;
  assert.equal(camera.workspace[2], 2.0736, JSON.stringify(camera));
  await page.waitForFunction((c) => {
    const w = JSON.parse(localStorage.getItem('cspacelab:v1:/:main:work') || 'null');
    return w && JSON.stringify(w.lessons.collision.camera) === JSON.stringify(c);
  }, camera, { timeout: 15000 });
  const picture = await viewPicture(page, 'workspace');
  await page.reload();
  await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 3);
  assert.equal((await api(page, 'status')).lesson, 'collision');
  assert.deepEqual((await api(page, 'snapshot')).camera, camera, 'the same camera');
  const d = await difference(page.context().browser(), picture, await viewPicture(page, 'workspace'));
  assert.ok(d.share < 0.003, `the same picture (${(d.share * 100).toFixed(3)} % differ)`);
  t.diagnostic(`after the reload ${(d.share * 100).toFixed(4)} % of the pixels differ`);
  const log = await api(page, 'log');
  assert.match(log[0].text, /^Restored from your saved work at step \d+, scene "P12: one disk across the path"; the workspace zoomed 2\.07x\./);
  // Its Fit button fits the view again, and the snapshot has no camera any more.
  await click(page, await pageButton(page, 'fit##collision-workspace'));
  assert.equal((await api(page, 'snapshot')).camera, undefined);
  assert.equal((await api(page, 'view')).fitted, true);
}));

test('an edited scene stops claiming a bundled scene\'s name; Share encodes it whole; undo names it again',
  () => withPage({ open: '?lesson=step-prm&scene=p12' }, async ({ page, browser }) => {
  const P12 = 'P12: one disk across the path';
  assert.equal((await api(page, 'state')).scene_name, P12);
  assert.match(await shareLink(page), /[?&]scene=p12&/, 'the bundled scene by name');

  // A disk drawn with the mouse.
  await drawDisk(page, [0.7, 0.25], [0.75, 0.25]);
  assert.equal((await api(page, 'get_scene')).obstacles.length, 2);
  const edited = P12 + ' (edited)';
  assert.equal((await api(page, 'state')).scene_name, edited);
  assert.equal((await api(page, 'get_scene')).name, edited);
  assert.equal((await api(page, 'snapshot')).scene.name, edited);
  assert.ok((await api(page, 'describe')).startsWith(`Scene "${edited}". The workspace spans`));
  const [download] = await Promise.all([page.waitForEvent('download'),
                                        page.evaluate(() => window.cspacelab.shell.action('export-scene'))]);
  assert.equal(download.suggestedFilename(), 'p12-one-disk-across-the-path-edited.json');
  const link = await shareLink(page);
  assert.match(new URL(link).searchParams.get('scene'), /^z\./, 'encoded whole, not named');
  const other = await browser.newPage({ viewport: VIEWPORT });
  await openLab(other, link);
  assert.deepEqual(await api(other, 'get_scene'), await api(page, 'get_scene'), 'the same scene, the same name');
  await other.close();

  // Undo (Ctrl+Z): the original again, and its name.
  await page.mouse.move(700, 400);
  await chord(page, 'Control', 'z');
  assert.equal((await api(page, 'get_scene')).obstacles.length, 1);
  assert.equal((await api(page, 'state')).scene_name, P12);
  assert.match(await shareLink(page), /[?&]scene=p12&/);

  // Moving the start by keyboard is an edit too; moving it back undoes the mark.
  const s = await api(page, 'get_scene');
  await api(page, 'set_scene', { scene: { ...s, start: [0.05, 0.1] } });
  assert.equal((await api(page, 'get_scene')).name, edited, 'other content under the bundled name');
  await api(page, 'set_scene', { scene: { ...s, name: edited } });
  assert.equal((await api(page, 'get_scene')).name, P12, 'the bundled content again: its own name');
  // A scene of its own name is marked once it changes, and not before.
  await api(page, 'set_scene', { scene: { ...s, name: 'My maze' } });
  assert.equal((await api(page, 'get_scene')).name, 'My maze');
  await drawDisk(page, [0.7, 0.25], [0.75, 0.25]);
  assert.equal((await api(page, 'get_scene')).name, 'My maze (edited)');
  await chord(page, 'Control', 'z');
  assert.equal((await api(page, 'get_scene')).name, 'My maze');
}));
