// The instructor's Author view, used as an instructor with only a browser uses it: opened from
// the File menu with the mouse, fields typed with the keyboard, an exercise (P10, fixed seed,
// points, tolerance), an explore item and a task taken from a Step PRM state this test sets up
// (the task's check written with the term builder from the lesson's state), a bad value whose
// message names the item and field (and survives a reload through author=1), a preview as a
// student and back with the draft intact, the JSON exported and checked by the CLI and against
// what was built, and both SCORM zips built in the page, unpacked and compared entry by entry
// with scripts/scorm-package.mjs's from the same file and site.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { withPage, openLab, click, waitFrames, api, pageButton, screenshot, DIST, CLI } from './lib/harness.mjs';
import { readZip } from '../../scripts/zip.mjs';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

const dialog = (page) => page.locator('.lab-author');
const head = (page) => page.locator('.lab-author-head');
const item = (page, i) => page.locator(`.lab-author [data-item="${i}"]`);

/** Clicks a field with the mouse, selects what it holds and types `text` over it. */
async function typeInto(locator, text) {
  await locator.click();
  await locator.press('Control+A');
  await locator.press('Backspace');
  if (text) await locator.pressSequentially(text, { delay: 5 });
}

/** File > Author an assignment..., with the mouse on the app's menu. */
async function openFromMenu(page) {
  await click(page, await pageButton(page, 'file'));
  const at = await pageButton(page, 'author');
  assert.ok(at, 'File has "Author an assignment..."');
  await click(page, at);
  await dialog(page).waitFor({ state: 'visible' });
}

/** The download a click on the button `label` starts, saved in `dir`: its path. */
async function download(page, label, dir) {
  const [d] = await Promise.all([page.waitForEvent('download'), dialog(page).getByRole('button', { name: label, exact: true }).click()]);
  const file = path.join(dir, d.suggestedFilename());
  await d.saveAs(file);
  return file;
}

test('the Author view: an exercise, an explore item and a task built, checked, previewed and exported with its SCORM zips',
  { timeout: 240000 }, () => withPage({ open: '?lesson=step-prm&scene=p12&samples=80&neighbors=k:8&seed=3' }, async ({ page, url }) => {
  const out = fs.mkdtempSync(path.join(os.tmpdir(), 'csl-author-'));
  // Not loaded for a student: the Author view's scripts come only when it is opened.
  assert.equal(await page.evaluate(() => typeof window.CSpaceLabAuthor), 'undefined');
  await openFromMenu(page);
  assert.equal(await page.evaluate(() => typeof window.CSpaceLabAuthor + typeof window.CSpaceLabScormPackage), 'functionobject');

  // The head: title by mouse and keyboard, Tab to the description, the pass mark.
  await typeInto(head(page).getByLabel('Title', { exact: true }), 'Week 3: roadmaps');
  await page.keyboard.press('Tab');
  await page.keyboard.type('Three things to do.');
  await typeInto(head(page).getByLabel('Pass mark'), '0.5');

  // An exercise: P10 with fixed numbers (seed 7), 2 points, a tolerance.
  await dialog(page).getByLabel('Homework problem').selectOption('P10');
  await dialog(page).getByRole('button', { name: 'Add exercise' }).click();
  await typeInto(item(page, 0).getByLabel('Points'), '-3');
  // A bad value: core's message names the item and the field, under the item and in the list.
  const itemErrors = item(page, 0).locator('.lab-author-item-errors li');
  await itemErrors.first().waitFor();
  const message = await itemErrors.first().textContent();
  assert.match(message, /^items\[0\].*points: .*-3/, message);
  assert.match(await page.locator('.lab-author-summary').textContent(), /^Not valid yet: 1 problem/);
  // ... and nothing typed is lost: a reload with author=1 opens the view on the same draft.
  await page.waitForTimeout(400);
  await openLab(page, url + '?lesson=step-prm&scene=p12&samples=80&neighbors=k:8&seed=3&author=1');
  await dialog(page).waitFor({ state: 'visible' });
  assert.equal(await head(page).getByLabel('Title', { exact: true }).inputValue(), 'Week 3: roadmaps');
  assert.equal(await item(page, 0).getByLabel('Points').inputValue(), '-3');
  assert.match(await item(page, 0).locator('.lab-author-item-errors li').first().textContent(), /^items\[0\].*points/);
  await typeInto(item(page, 0).getByLabel('Points'), '2');
  await item(page, 0).getByLabel('Numbers').selectOption('fixed');
  await typeInto(item(page, 0).getByLabel('Seed', { exact: true }), '7');
  await typeInto(item(page, 0).getByLabel('Tolerance (optional)'), '0.01');
  // Tries: none is not a limit (core's message under the item), three is.
  await typeInto(item(page, 0).getByLabel('Tries (optional)'), '0');
  await item(page, 0).locator('.lab-author-item-errors li', { hasText: /tries: .*\[1, 100\], got 0/ }).waitFor();
  await typeInto(item(page, 0).getByLabel('Tries (optional)'), '3');

  // The lab set up for the explore item: Escape hides the view, the test changes the lesson's
  // parameters, and the view comes back from the menu.
  await page.keyboard.press('Escape');
  await dialog(page).waitFor({ state: 'hidden' });
  await page.evaluate(() => window.cspacelab.setParams({ samples: 60, seed: 11 }));
  await waitFrames(page, 2);
  const labState = await page.evaluate(() => window.cspacelab.snapshot());
  assert.equal(labState.params.samples, 60);
  await openFromMenu(page);
  await dialog(page).getByRole('button', { name: 'Add explore item (the lab now)' }).click();
  await typeInto(item(page, 1).getByLabel('Title', { exact: true }), 'Look at 60 samples');
  await typeInto(item(page, 1).getByLabel('Prompt'), 'How many components does the roadmap have?');
  assert.match(await item(page, 1).locator('.lab-author-state').textContent(), /lesson step-prm, its scene/);

  // A task: the same state, its check built from a field of the lesson's state().
  await dialog(page).getByRole('button', { name: 'Add task (the lab now)' }).click();
  await typeInto(item(page, 2).getByLabel('Title', { exact: true }), 'Few samples');
  await typeInto(item(page, 2).getByLabel('Prompt'), 'Find a path with at most 60 samples.');
  await item(page, 2).getByLabel('Field of the state').selectOption('/params/samples');
  await item(page, 2).getByLabel('Is', { exact: true }).selectOption('max');
  await typeInto(item(page, 2).getByLabel('Value', { exact: true }), '60');
  await item(page, 2).getByRole('button', { name: 'Add to the check' }).click();
  const check = JSON.parse(await item(page, 2).getByLabel(/^Check/).inputValue());
  assert.deepEqual(check, { all: [{ pointer: '/params/samples', max: 60 }] });
  await page.waitForFunction(() => /^Valid: 3 items, 3 points in all/.test(document.querySelector('.lab-author-summary').textContent));

  // Reorder: the task up, then back down (the keyboard: Enter on the focused button).
  await item(page, 2).getByRole('button', { name: 'Move up: item 3' }).click();
  assert.match(await item(page, 1).locator('h3').textContent(), /^Item 2: Task/);
  // Focus stays on the moved item's "Move up": Tab to its "Move down", Enter.
  assert.equal(await page.evaluate(() => document.activeElement.getAttribute('aria-label')), 'Move up: item 2');
  await page.keyboard.press('Tab');
  await page.keyboard.press('Enter');
  assert.match(await item(page, 2).locator('h3').textContent(), /^Item 3: Task/);

  // Screenshots of the view at desktop width and at 390 px.
  await screenshot(page, 'author-desktop.png');
  const box = await dialog(page).locator('.lab-author-box').boundingBox();
  assert.ok(box.width > 600 && box.width <= 1280, `the view is wide on a desktop (${box.width})`);

  // Preview as a student, and back: the draft is as it was, the lab too.
  const before = await page.evaluate(() => window.cspacelab.snapshot());
  await dialog(page).getByRole('button', { name: 'Preview as a student' }).click();
  await dialog(page).waitFor({ state: 'hidden' });
  const preview = await api(page, 'assignment_state');
  assert.equal(preview.title, 'Week 3: roadmaps');
  assert.deepEqual(preview.items.map((i) => i.kind), ['exercise', 'explore', 'task']);
  assert.equal(preview.items[0].seed, 7);
  assert.equal(preview.learner, 'preview');
  await waitFrames(page, 3);
  await screenshot(page, 'author-preview.png');
  await page.getByRole('button', { name: 'Back to the draft' }).click();
  await dialog(page).waitFor({ state: 'visible' });
  await assert.rejects(api(page, 'assignment_state'), /no assignment is open/);
  assert.deepEqual(await page.evaluate(() => window.cspacelab.snapshot()), before);
  assert.equal(await head(page).getByLabel('Title', { exact: true }).inputValue(), 'Week 3: roadmaps');
  assert.equal(await item(page, 0).getByLabel('Tolerance (optional)').inputValue(), '0.01');
  assert.equal(await item(page, 2).getByLabel('Prompt').inputValue(), 'Find a path with at most 60 samples.');

  // The JSON: what was built, and valid for the CLI.
  const jsonFile = await download(page, 'Export JSON', out);
  assert.equal(path.basename(jsonFile), 'week-3-roadmaps.json');
  const file = JSON.parse(fs.readFileSync(jsonFile, 'utf8'));
  const setup = { lesson: 'step-prm', scene: labState.scene, params: labState.params };
  assert.deepEqual(file, {
    format: 'cspacelab-assignment', version: 1, title: 'Week 3: roadmaps', description: 'Three things to do.', pass: 0.5,
    items: [
      { kind: 'exercise', problem: 'P10', seed: 7, points: 2, tolerance: 0.01, tries: 3 },
      { kind: 'explore', title: 'Look at 60 samples', prompt: 'How many components does the roadmap have?', ...setup, points: 0 },
      { kind: 'task', title: 'Few samples', prompt: 'Find a path with at most 60 samples.', ...setup, points: 1, check },
    ],
  });
  const valid = spawnSync(CLI, ['assignment', 'validate', jsonFile], { encoding: 'utf8' });
  assert.equal(valid.status, 0, valid.stderr);
  assert.equal(JSON.parse(valid.stdout).title, 'Week 3: roadmaps');

  // The SCORM zips built in the page against the packager's from the same file and site.
  const packaged = spawnSync(process.execPath, [path.join(ROOT, 'scripts/scorm-package.mjs'), jsonFile, '--dist', DIST, '--out', path.join(out, 'node')],
                             { encoding: 'utf8', env: { ...process.env, CSPACELAB_CLI: CLI } });
  assert.equal(packaged.status, 0, packaged.stderr);
  for (const [label, zipName, schema] of [['Export SCORM 1.2', 'week-3-roadmaps-scorm12.zip', '<schemaversion>1.2</schemaversion>'],
                                          ['Export SCORM 2004', 'week-3-roadmaps-scorm2004.zip', '<schemaversion>2004 4th Edition</schemaversion>']]) {
    const zipFile = await download(page, label, out);
    assert.equal(path.basename(zipFile), zipName);
    const browserZip = readZip(fs.readFileSync(zipFile));  // checks every entry's CRC-32
    const nodeZip = readZip(fs.readFileSync(path.join(out, 'node', zipName)));
    assert.deepEqual(browserZip.map((e) => e.name), nodeZip.map((e) => e.name), `${zipName}: the same files in the same order`);
    for (let i = 0; i < nodeZip.length; ++i)
      assert.ok(browserZip[i].data.equals(nodeZip[i].data), `${zipName}: ${nodeZip[i].name} has the same bytes`);
    const names = browserZip.map((e) => e.name);
    assert.deepEqual(names.slice(0, 3), ['imsmanifest.xml', 'launch.html', 'assignment.json']);
    for (const f of ['cspacelab.wasm', 'cspacelab.js', 'index.html', 'lab.js', 'lab-assignment.js', 'site-files.json']) assert.ok(names.includes(f), f);
    assert.ok(!names.includes('cspacelab-single.html'));
    const manifest = browserZip[0].data.toString('utf8');
    assert.ok(manifest.includes(schema));
    assert.ok(manifest.includes('<title>Week 3: roadmaps</title>'));
    assert.ok(manifest.includes(zipName.endsWith('12.zip') ? '<adlcp:masteryscore>50</adlcp:masteryscore>' : '<imsss:minNormalizedMeasure>0.5</imsss:minNormalizedMeasure>'));
    for (const f of names.slice(1)) assert.ok(manifest.includes(`<file href="${f}"/>`), `the manifest lists ${f}`);
    assert.equal(browserZip[2].data.toString('utf8'), fs.readFileSync(jsonFile, 'utf8'), 'the package holds the exported file');
  }

  // The phone's width: the view fits (no sideways scrolling), every field still reachable.
  await page.setViewportSize({ width: 390, height: 844 });
  await waitFrames(page, 3);
  const narrow = await dialog(page).locator('.lab-author-box').boundingBox();
  assert.ok(narrow.x >= 0 && narrow.x + narrow.width <= 390, `the view fits 390 px (${narrow.x}, ${narrow.width})`);
  assert.ok(await dialog(page).locator('.lab-author-box').evaluate((b) => b.scrollWidth <= b.clientWidth), 'no sideways scrolling');
  await screenshot(page, 'author-390.png');
}));

test('a stored draft of the wrong shape opens as far as it can be read; Start over asks, then empties it',
  { timeout: 120000 }, () => withPage(async ({ page, url }) => {
  // Another version's draft, or one edited by hand: a number for the title, items that are no
  // items. The view used to end in a TypeError here.
  await page.evaluate(() => localStorage.setItem('cspacelab:v1:author:' + location.pathname, JSON.stringify({
    title: 7, description: null, pass: '0.5',
    items: [null, 3, { kind: 'bogus' }, { kind: 'exercise', problem: 'P10', points: 2, seed: 4, seedMode: 'fixed' },
            { kind: 'task', prompt: ['not text'], lesson: 'step-prm', check: { pointer: '/solved', equals: true } }],
  })));
  await openLab(page, url + '?author=1');
  await dialog(page).waitFor({ state: 'visible' });
  assert.equal(await head(page).getByLabel('Title', { exact: true }).inputValue(), '7');
  assert.equal(await page.locator('.lab-author [data-item]').count(), 2, 'the exercise and the task; the rest dropped');
  assert.equal(await item(page, 0).getByLabel('Points').inputValue(), '2');
  // The task's check, stored as an object, is kept (as the text the dialog edits).
  assert.match(await item(page, 1).getByLabel(/^Check \(a condition/).inputValue(), /"pointer":\s*"\/solved"/);
  // Start over is a question first: No keeps everything, Yes empties the draft and its storage.
  page.once('dialog', (d) => d.dismiss());
  await dialog(page).getByRole('button', { name: 'Start over' }).click();
  assert.equal(await page.locator('.lab-author [data-item]').count(), 2, 'No: nothing deleted');
  page.once('dialog', (d) => d.accept());
  await dialog(page).getByRole('button', { name: 'Start over' }).click();
  assert.equal(await page.locator('.lab-author [data-item]').count(), 0);
  assert.equal(await head(page).getByLabel('Title', { exact: true }).inputValue(), '');
  const kept = await page.evaluate(() => JSON.parse(localStorage.getItem('cspacelab:v1:author:' + location.pathname) || 'null'));
  assert.ok(kept === null || (kept.items.length === 0 && kept.title === ''), `the stored draft is empty too: ${JSON.stringify(kept)}`);
}));
