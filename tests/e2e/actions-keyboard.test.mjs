// The canvas's top bar by keyboard alone (web/lab-actions-access.js): from the lab's focus, Tab
// reaches Undo and Redo, Share (its dialog gives the focus back), the File menu's exports and
// import (the scene that goes out is the scene that comes back; a broken file's error is read
// out), and Reset with its confirmation (Escape keeps everything; the work comes back from
// Previous work). Every notice the canvas shows is read in the copy's live region. A minimal
// embed offers the full lab instead of the Author view.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { withPage, api, drawDisk, waitFrames, recordLive, focused, tabToButton } from './lib/harness.mjs';

const G = '.lab-access-actions';
const heard = (page, re) => page.waitForFunction((src) => window.__said.some((t) => new RegExp(src).test(t)), re.source, { timeout: 5000 })
  .catch(async (e) => { throw new Error(`not heard: ${re}; heard: ${(await said(page)).join(' | ')}; focus: ${await focused(page)}`); });
const said = (page) => page.evaluate(() => window.__said);

test('the top bar by keyboard: undo, redo, share, export and import, reset and previous work',
  () => withPage({ open: 'index.html?lesson=step-prm' }, async ({ page }) => {
  await page.waitForSelector(`${G} button`, { state: 'attached' });
  await recordLive(page, `${G} [aria-live]`);
  await api(page, 'set_scene', { scene: { version: 1, start: [0.1, 0.1], goal: [0.9, 0.9] } });
  await drawDisk(page, [0.5, 0.5], [0.6, 0.5]);  // one edit, with the mouse, to undo
  const drawn = await api(page, 'get_scene');
  assert.equal(drawn.obstacles.length, 1);

  // From the lab's focus, Tab reaches Undo (through the homework, lessons, parameters, steps).
  await page.locator('canvas').focus();
  await tabToButton(page, 'Undo', 80);  // through the homework, lessons, parameters, steps
  await page.keyboard.press('Enter');
  await heard(page, /^Undone/);
  assert.equal((await api(page, 'get_scene')).obstacles.length, 0, 'the disk is undone');
  await page.keyboard.press('Enter');  // and the scene set before it
  await page.keyboard.press('Enter');
  await heard(page, /^Nothing to undo\.$/);
  assert.deepEqual(await said(page), ['Undone: the last scene edit.', 'Undone: the last scene edit.', 'Nothing to undo.']);
  await page.keyboard.press('Tab');
  assert.equal(await focused(page), 'Redo');
  await page.keyboard.press('Enter');
  await page.keyboard.press('Enter');
  await heard(page, /^Redone\.$/);
  assert.deepEqual(await api(page, 'get_scene'), drawn, 'and redone');

  // Share: the dialog holds the link; Escape closes it and the focus is back on Share.
  await page.keyboard.press('Tab');
  assert.equal(await focused(page), 'Share a link to this state');
  await page.keyboard.press('Enter');
  const dialog = page.locator('.lab-dialog');
  await dialog.waitFor();
  const link = await dialog.locator('textarea').inputValue();
  assert.match(link, /\/index\.html\?/, 'the dialog holds the link');
  assert.equal(await page.evaluate(() => document.activeElement.tagName), 'TEXTAREA', 'the focus is in the dialog');
  await heard(page, /^(Link copied to the clipboard|Copy the link from the dialog)\.$/);
  await page.keyboard.press('Escape');
  await dialog.waitFor({ state: 'detached' });
  assert.equal(await focused(page), 'Share a link to this state', 'the focus is back where the student was');
  // Again, at once: the same words are a new notice, and they are heard again.
  await page.keyboard.press('Enter');
  await dialog.waitFor();
  await page.waitForFunction(() => window.__said.filter((t) => /^(Link copied|Copy the link)/.test(t)).length === 2,
                             null, { timeout: 5000 })
    .catch(async () => { throw new Error(`the second Share was not heard: ${(await said(page)).join(' | ')}`); });
  await page.keyboard.press('Escape');
  await dialog.waitFor({ state: 'detached' });

  // Export the scene: the file is the scene on screen.
  await tabToButton(page, 'Export the scene (JSON)', 3);
  const [dl] = await Promise.all([page.waitForEvent('download'), page.keyboard.press('Enter')]);
  const exported = JSON.parse(fs.readFileSync(await dl.path(), 'utf8'));
  assert.deepEqual(exported.obstacles, drawn.obstacles);
  assert.deepEqual([exported.start, exported.goal], [drawn.start, drawn.goal]);

  // Import: the picker opens from the key press; a broken file changes nothing and is read out.
  await page.keyboard.press('Shift+Tab');
  assert.equal(await focused(page), 'Import a scene (JSON)');
  const pick = async (text) => {
    // Playwright intercepts the picker once it listens: a round trip first, then the key.
    const waiting = page.waitForEvent('filechooser');
    await page.evaluate(() => 0);
    await page.keyboard.press('Enter');
    const chooser = await waiting;
    await chooser.setFiles({ name: 'scene.json', mimeType: 'application/json', buffer: Buffer.from(text) });
  };
  await pick('{"version": 1, "obstacles": [{"type": "disk", "center": [0.5, 0.5], "radius": -1}]}');
  await heard(page, /radius/);
  assert.deepEqual(await api(page, 'get_scene'), drawn, 'a broken file changes nothing');
  const other = { ...exported, obstacles: [{ type: 'disk', center: [0.314, 0.7], radius: 0.05 }] };
  await pick(JSON.stringify(other));
  await page.waitForFunction(() => window.cspacelab.call('get_scene').obstacles[0]?.center?.[0] === 0.314);
  assert.equal(await focused(page), 'Import a scene (JSON)', 'the focus stays on the button');

  // Reset asks first: Escape keeps the scene; Reset resets; Previous work brings it back.
  await tabToButton(page, 'Reset the lesson to its default', 5);
  await page.keyboard.press('Enter');
  const question = await focused(page);
  assert.match(question, /^Reset Step PRM to its default scene and parameters\?/, 'the question has the focus');
  await page.keyboard.press('Escape');
  assert.equal(await focused(page), 'Reset the lesson to its default');
  assert.equal((await api(page, 'get_scene')).obstacles[0].center[0], 0.314, 'nothing was reset');
  await page.keyboard.press('Enter');
  await tabToButton(page, 'Reset', 1);
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => !window.cspacelab.call('get_scene').obstacles.some((o) => o.center?.[0] === 0.314));
  assert.equal(await focused(page), 'Reset the lesson to its default', 'the focus goes back to the button');
  await page.waitForSelector(`${G} select option`, { state: 'attached' });
  const options = await page.locator(`${G} select option`).allTextContents();
  assert.match(options[0], /reset.*Step PRM/i, 'the work before the reset is the newest previous work');
  // Each entry is restored by its id, not its place in a list that may have changed since.
  assert.deepEqual(await page.locator(`${G} select option`).evaluateAll((os) => os.map((o) => o.value)),
                   await page.evaluate(() => document.querySelector('.lab').cspacelabShell.historyIds));
  await tabToButton(page, 'Restore', 3);
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => window.cspacelab.call('get_scene').obstacles[0]?.center?.[0] === 0.314);
  await waitFrames(page, 2);
  assert.equal(await focused(page), 'Restore', 'the focus stays (the reset default is now previous work)');
  assert.match((await page.locator(`${G} select option`).allTextContents())[0], /before restoring other work · Step PRM$/);
  // What the student heard, once each, in order: the copy's own words and the canvas's notices.
  const expected = [/^Undone/, /^Undone/, /^Nothing to undo/, /^Redone/, /^Redone/, /^Link copied|^Copy the link/,
                    /^Link copied|^Copy the link/,
                    /^Import: "scene\.json" is not a scene.*radius.*Nothing changed\.$/, /^Imported "scene\.json"\.$/,
                    /^Step PRM is back to its default\./, /^Restored .*reset.*Step PRM/];
  const words = await said(page);
  assert.equal(words.length, expected.length, words.join(' | '));
  expected.forEach((re, i) => assert.match(words[i], re));
}));

test('a minimal embed offers the full lab, not the Author view', () =>
  withPage({ open: 'embed.html?lesson=collision' }, async ({ page }) => {
    await page.waitForSelector(`${G} button`, { state: 'attached' });
    const labels = await page.locator(`${G} button`).allTextContents();
    assert.ok(labels.includes('Open in the full lab'), labels.join(', '));
    assert.ok(!labels.includes('Author an assignment'));
    assert.ok(labels.includes('Share a link to this state') && labels.includes('Undo'));
  }));
