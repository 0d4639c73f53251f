// The scene by keyboard alone (web/lab-scene-access.js): in Step PRM, from the lab's focus, Tab
// reaches "Add a disk"; the new disk's centre x takes the focus, its centre and radius typed
// are exactly the numbers get_scene gives; a negative radius is refused with the app's message
// (heard, beside the field, aria-invalid) and the scene is unchanged; the goal moves; Delete
// and the top bar copy's Undo bring the disk back. A disk drawn with the mouse appears in the
// copy. With lock=scene the fields are read-only and say why. Screenshots of the panel at
// 1280x800 and on a phone held upright (390x844) show the focused field inside the panel.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, withBrowser, api, drawDisk, recordLive, tabToButton, screenshot, openLab, waitFrames, collectErrors }
  from './lib/harness.mjs';

const G = '.lab-access-scene';
const said = (page) => page.evaluate(() => window.__said);
const heard = (page, re) => page.waitForFunction((src) => window.__said.some((t) => new RegExp(src).test(t)), re.source, { timeout: 5000 })
  .catch(async () => { throw new Error(`not heard: ${re}; heard: ${(await said(page)).join(' | ')}`); });
// The focused control as a reader names it: its box's legend and its label, or a button's text.
const named = (page) => page.evaluate(() => {
  const a = document.activeElement;
  return a.tagName === 'INPUT' ? `${a.closest('fieldset').querySelector('legend').textContent} ${a.labels[0].textContent}`
    : a.textContent;
});
async function keyTo(page, key, name, max = 20) {
  for (let n = 0; n < max; ++n) {
    await page.keyboard.press(key);
    if (await named(page) === name) return;
  }
  throw new Error(`${name} not reached by ${key}; the focus is on ${await named(page)}`);
}
const type = async (page, text) => {
  await page.keyboard.press('Control+A');
  await page.keyboard.press('Delete');
  await page.keyboard.type(text);
};
// The copy's fields as they show: {legend: [values]}.
const fields = (page) => page.evaluate((g) => Object.fromEntries([...document.querySelectorAll(`${g} fieldset`)]
  .map((f) => [f.querySelector('legend').textContent, [...f.querySelectorAll('input')].map((i) => i.value)])), G);

test('the scene by keyboard: add a disk, its numbers, a refusal, the goal, delete and undo',
  () => withPage({ open: 'index.html?lesson=step-prm' }, async ({ page }) => {
  await page.waitForSelector(`${G} button`, { state: 'attached' });
  await recordLive(page, `${G} [aria-live]`);
  await page.evaluate(() => {  // the top bar copy's region too (its Undo), into the same list
    const live = document.querySelector('.lab-access-actions [aria-live]');
    new MutationObserver(() => { if (live.textContent) window.__said.push(live.textContent); })
      .observe(live, { childList: true, characterData: true, subtree: true });
  });
  await api(page, 'set_scene', { scene: { version: 1, start: [0.1, 0.1], goal: [0.9, 0.9] } });
  await page.waitForFunction((g) => document.querySelectorAll(`${g} fieldset`).length === 2, G);
  assert.deepEqual(await fields(page), { Start: ['0.1', '0.1'], Goal: ['0.9', '0.9'] });

  // Add a disk: a small one, clear of start and goal; its centre x has the focus.
  await page.locator('canvas').focus();
  await tabToButton(page, 'Add a disk', 80);
  await page.keyboard.press('Enter');
  await heard(page, /^Added\. Disk 1: centre \([\d.]+, [\d.]+\), radius 0\.05\.$/);
  assert.equal(await named(page), 'Disk 1 centre x');
  const added = (await api(page, 'get_scene')).obstacles[0];
  assert.equal(added.radius, 0.05);
  for (const q of [[0.1, 0.1], [0.9, 0.9]])
    assert.ok(Math.hypot(added.center[0] - q[0], added.center[1] - q[1]) > 2 * added.radius, 'clear of start and goal');

  // Its centre and radius, typed: get_scene has exactly these numbers, and each change is read.
  await type(page, '0.4');
  await page.keyboard.press('Tab');
  await type(page, '0.55');
  await page.keyboard.press('Tab');
  assert.equal(await named(page), 'Disk 1 radius');
  await type(page, '0.1');
  await page.keyboard.press('Tab');
  await heard(page, /^Disk 1: centre \(0\.4, 0\.55\), radius 0\.1\.$/);
  const disk = { type: 'disk', center: [0.4, 0.55], radius: 0.1 };
  assert.deepEqual((await api(page, 'get_scene')).obstacles, [disk]);
  assert.equal(await named(page), 'Delete disk 1');

  // A negative radius: the app's message is heard and shown beside the field; nothing changes.
  const before = await api(page, 'get_scene');
  await page.keyboard.press('Shift+Tab');
  await type(page, '-0.2');
  await page.keyboard.press('Tab');
  await heard(page, /radius.*>= 0/);
  const radius = page.locator(`${G} fieldset:has(legend:text-is("Disk 1")) input`).nth(2);
  assert.equal(await radius.getAttribute('aria-invalid'), 'true');
  assert.equal(await radius.inputValue(), '0.1', "the app's value is back");
  const why = await radius.evaluate((i) => i.getAttribute('aria-describedby').split(' ')
    .map((id) => document.getElementById(id).textContent).join(''));
  assert.match(why, /radius.*>= 0/, 'the message describes the field');
  assert.deepEqual(await api(page, 'get_scene'), before, 'the scene is unchanged');
  // Not a number at all: the app's message too.
  await page.keyboard.press('Shift+Tab');
  await type(page, '');
  await page.keyboard.press('Tab');
  await heard(page, /radius.*number/);
  assert.deepEqual(await api(page, 'get_scene'), before, 'still unchanged');

  // The goal moves (Enter sends it too; the focus stays).
  await keyTo(page, 'Shift+Tab', 'Goal x (position)');
  await type(page, '0.8');
  await page.keyboard.press('Enter');
  await heard(page, /^Goal: \(0\.8, 0\.9\)\.$/);
  assert.deepEqual((await api(page, 'get_scene')).goal, [0.8, 0.9]);
  assert.equal(await named(page), 'Goal x (position)');
  await type(page, '5');  // outside the workspace: refused, and the goal stays
  await page.keyboard.press('Enter');
  await heard(page, /goal.*inside the workspace/);
  assert.deepEqual((await api(page, 'get_scene')).goal, [0.8, 0.9]);
  assert.equal(await page.evaluate(() => document.activeElement.value), '0.8');
  // Up and Down step by 1% of the unit workspace, each an edit (the browser's own step is 1).
  await page.keyboard.press('ArrowUp');
  await heard(page, /^Goal: \(0\.81, 0\.9\)\.$/);
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('ArrowDown');
  await heard(page, /^Goal: \(0\.79, 0\.9\)\.$/);
  assert.deepEqual((await api(page, 'get_scene')).goal, [0.79, 0.9]);
  await type(page, '0.8');
  await page.keyboard.press('Enter');
  await heard(page, /^Goal: \(0\.8, 0\.9\)\.$/);

  // Delete the disk; the focus goes to Add a disk; the top bar copy's Undo brings it back.
  await keyTo(page, 'Tab', 'Delete disk 1');
  await page.keyboard.press('Enter');
  await heard(page, /^Deleted disk 1\.$/);
  assert.deepEqual((await api(page, 'get_scene')).obstacles, []);
  assert.equal(await named(page), 'Add a disk');
  await page.waitForFunction((g) => !document.querySelector(`${g} fieldset:nth-of-type(3)`), G);
  await tabToButton(page, 'Undo', 40);
  await page.keyboard.press('Enter');
  await heard(page, /^Undone/);
  assert.deepEqual((await api(page, 'get_scene')).obstacles, [disk]);
  await page.waitForFunction((g) => document.querySelectorAll(`${g} fieldset`).length === 3, G);
  assert.deepEqual((await fields(page))['Disk 1'], ['0.4', '0.55', '0.1']);

  // A disk drawn with the mouse shows in the copy.
  await page.locator('canvas').focus();
  await drawDisk(page, [0.75, 0.25], [0.82, 0.25]);
  const drawn = (await api(page, 'get_scene')).obstacles[1];
  assert.equal(drawn.type, 'disk');
  await page.waitForFunction((g) => document.querySelectorAll(`${g} fieldset`).length === 4, G);
  assert.deepEqual((await fields(page))['Disk 2'], [...drawn.center, drawn.radius].map(String));
}));

test('lock=scene: the fields are read-only and say why; a lesson without a scene has no copy',
  () => withPage({ open: 'index.html?lesson=step-prm&lock=scene' }, async ({ page }) => {
  await page.waitForSelector(`${G} fieldset input`, { state: 'attached' });
  await recordLive(page, `${G} [aria-live]`);
  await page.waitForFunction((g) => document.querySelector(`${g} input`).readOnly, G);
  const inputs = page.locator(`${G} input`);
  for (let i = 0; i < await inputs.count(); ++i) {
    const input = inputs.nth(i);
    assert.ok(await input.evaluate((e) => e.readOnly), 'read-only');
    const why = await input.evaluate((e) => e.getAttribute('aria-describedby').split(' ')
      .map((id) => document.getElementById(id).textContent).join(' '));
    assert.match(why, /Fixed by your instructor \(lock=scene\)/);
  }
  const scene = await api(page, 'get_scene');
  await page.locator(`${G} > button`).focus();  // Add a disk (Tab reaches it: the test above)
  assert.equal(await page.evaluate(() => document.activeElement.getAttribute('aria-disabled')), 'true');
  await page.keyboard.press('Enter');
  await heard(page, /fixed by your instructor \(lock=scene\)/);
  await keyTo(page, 'Shift+Tab', 'Goal y (position)');
  await page.keyboard.type('5');
  await page.keyboard.press('Tab');
  assert.deepEqual(await api(page, 'get_scene'), scene, 'nothing changed');

  // The torus lesson's arm: joint angles; the notation lesson has no scene, so no copy. (The
  // focus leaves the copy first: a row with the focus is not rebuilt.)
  await page.locator('canvas').focus();
  await api(page, 'select_lesson', { id: 'torus' });
  await page.waitForFunction((g) => /joint 1 θ \(radians\)/.test(document.querySelector(`${g} label`)?.textContent), G)
    .catch(async () => { throw new Error(`torus: ${await page.locator(`${G} label`).allTextContents()}`); });
  await api(page, 'select_lesson', { id: 'notation' });
  await page.waitForFunction((g) => document.querySelector(g).hidden, G);
}));

test('the copy panel with the focus in the scene, at 1280x800 and on a phone held upright',
  () => withBrowser(async ({ browser, url }) => {
  for (const [name, options] of [['wide', { viewport: { width: 1280, height: 800 } }],
    ['phone', { viewport: { width: 390, height: 844 }, deviceScaleFactor: 3, hasTouch: true, isMobile: true }]]) {
    const ctx = await browser.newContext(options);
    const page = await ctx.newPage();
    await page.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
    const errors = collectErrors(page);
    await openLab(page, url + 'index.html?lesson=step-prm&scene=narrow-passage');
    await page.waitForSelector(`${G} fieldset input`, { state: 'attached' });
    await page.locator(`${G} fieldset:has(legend:text-is("Polygon 1")) input`).focus();
    await waitFrames(page, 2);
    await screenshot(page, `scene-copy-${name}.png`);
    // The focused field is on screen, inside the panel, and wide enough to read its numbers.
    const [panel, field, view] = await page.evaluate(() => {
      const box = (e) => { const r = e.getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom]; };
      return [box(document.querySelector('.lab-access')), box(document.activeElement), [0, 0, innerWidth, innerHeight]];
    });
    assert.ok(field[0] >= panel[0] && field[2] <= panel[2] && field[1] >= panel[1] && field[3] <= panel[3],
              `${name}: the field ${field} is inside the panel ${panel}`);
    assert.ok(panel[0] >= view[0] && panel[2] <= view[2] && panel[3] <= view[3], `${name}: the panel is on screen`);
    assert.ok(field[2] - field[0] >= 200, `${name}: the vertices' field is ${field[2] - field[0]} px wide`);
    assert.deepEqual(errors, []);
    await ctx.close();
  }
}));
