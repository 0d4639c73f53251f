// The lab on a phone: 390 x 844 CSS px held upright and 844 x 390 on its side, pixel ratio 3,
// fingers only. The compact layout gives the lesson's views the width, a finger draws and moves
// a disk, two fingers zoom, the playback strip steps PRM; nothing logs an error.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  api, openPage, screenshot, waitFrames, withBrowser, worldToPage,
} from './lib/harness.mjs';

const PORTRAIT = { width: 390, height: 844 };
const LANDSCAPE = { width: 844, height: 390 };

async function phone(browser, url, viewport, open) {
  const { page, errors } = await openPage(browser, url + open, { viewport, deviceScaleFactor: 3, hasTouch: true, isMobile: true });
  await waitFrames(page, 3);
  const cdp = await page.context().newCDPSession(page);
  // Fingers through the browser's touch events (the way a phone delivers them), frames between.
  const touch = async (type, points) => {
    await cdp.send('Input.dispatchTouchEvent', { type, touchPoints: points.map((p, i) => ({ x: p.x, y: p.y, id: i })) });
    await waitFrames(page, 2);
  };
  const tap = async (at) => {
    await touch('touchStart', [at]);
    await touch('touchEnd', []);
    await waitFrames(page, 2);
  };
  const fingerDrag = async (from, to, steps = 10) => {
    await touch('touchStart', [from]);
    for (let i = 1; i <= steps; ++i)
      await touch('touchMove', [{ x: from.x + (to.x - from.x) * i / steps, y: from.y + (to.y - from.y) * i / steps }]);
    await touch('touchEnd', []);
    await waitFrames(page, 2);
  };
  // The app's own control by its page_state name, as a point of the page (null if not drawn).
  const control = async (name) => page.evaluate((n) => {
    const r = window.cspacelab.pageState().buttons[n];
    const box = window.cspacelab.module.canvas.getBoundingClientRect();
    return r ? { x: box.left + (r[0] + r[2]) / 2, y: box.top + (r[1] + r[3]) / 2, h: r[3] - r[1] } : null;
  }, name);
  const press = async (name) => {
    const at = await control(name);
    assert.ok(at, `the control "${name}" is on screen`);
    await tap(at);
  };
  const layout = async () => (await page.evaluate(() => window.cspacelab.status())).layout;
  return { page, errors, touch, tap, fingerDrag, control, press, layout };
}

const view = (layout, name) => layout.views.find((v) => v.name === name);

test('Phone upright: the Homework map fits the screen; a problem shows its question, its numbers the tool',
  () => withBrowser(async ({ browser, url }) => {
  const { page, errors, press, layout } = await phone(browser, url, PORTRAIT, '?lesson=step-prm');
  await press('homework');
  // Every row of the map within the screen's width (P1's was 404 px on 390), a finger high.
  const rows = await page.evaluate(() => {
    const b = window.cspacelab.pageState().buttons;
    return Object.keys(b).filter((k) => k.startsWith('problem-')).map((k) => [k, b[k][2], b[k][3] - b[k][1]]);
  });
  assert.equal(rows.length, 13);
  for (const [name, right, height] of rows) {
    assert.ok(right <= PORTRAIT.width, `${name} ends at ${right} px of ${PORTRAIT.width}`);
    assert.ok(height >= 24, `${name} is ${height} px high`);
  }
  await screenshot(page, 'phone-homework-map.png');
  await press('problem-P10');
  assert.equal((await api(page, 'status')).lesson, 'distances');
  // The question is on the Controls tab: that is where the problem opens.
  assert.equal((await layout()).tab, 'controls');
  const answer = await page.evaluate(() => window.cspacelab.pageState().buttons.answer);
  assert.ok(answer, 'the answer field is on screen');
  await screenshot(page, 'phone-homework-P10.png');
  const { q1, q2 } = (await api(page, 'homework_state')).exercise.given;
  let d = Infinity;
  for (let k = -2; k <= 2; ++k) d = Math.min(d, Math.abs(q2 - q1 + 2 * Math.PI * k));
  assert.equal((await api(page, 'check_answer', { answer: d.toFixed(3) })).correct, true);
  await waitFrames(page, 3);
  // Its numbers go into the tool, and the tool is what the phone then shows.
  await press('show-in-tool');
  assert.equal((await layout()).tab, 'view');
  assert.equal((await api(page, 'state')).q1, q1);
  assert.deepEqual(errors, []);
}));

test('Phone upright: every lesson\'s main view takes the width', () => withBrowser(async ({ browser, url }) => {
  const { page, errors, press, layout, control } = await phone(browser, url, PORTRAIT, '?lesson=step-prm');
  let l = await layout();
  assert.equal(l.mode, 'compact');
  assert.equal(l.tab, 'view');
  assert.equal(l.touch, true, 'a phone is known to be touched');
  const main = {
    'step-prm': 'workspace', torus: 'workspace', potential: 'workspace', collision: 'workspace',
    analysis: 'workspace', distances: 'circle', notation: 'robot', compare: 'workspace', 'cspace-3d': 'workspace',
  };
  const lessons = (await api(page, 'lessons')).map((x) => x.id);
  assert.deepEqual([...lessons].sort(), Object.keys(main).sort(), 'every lesson is checked here');
  for (const id of lessons) {
    // Chosen the way a student does: the lesson menu, then the lesson.
    await press('lesson-menu');
    await press(`lesson:${id}`);
    assert.equal((await api(page, 'status')).lesson, id);
    l = await layout();
    const v = view(l, main[id]);
    assert.ok(v, `${id}: its view "${main[id]}" is drawn (${JSON.stringify(l.views)})`);
    assert.ok(v.w >= 0.9 * PORTRAIT.width, `${id}: ${main[id]} is ${v.w} px wide of ${PORTRAIT.width}`);
    assert.ok(v.h >= 150, `${id}: ${main[id]} is ${v.h} px tall`);
    await screenshot(page, `phone-portrait-${id}.png`);
  }
  // The tabs' buttons, the lesson menu and the top bar's buttons are touch targets: at least
  // 44 px high (Homework, Share, Embed and File were 26 px).
  for (const name of ['tab:view', 'tab:controls', 'lesson-menu', 'homework', 'share', 'embed', 'file'])
    assert.ok((await control(name)).h >= 44, `${name} is ${(await control(name)).h} px high, not 44`);
  // Controls: the side panel, the whole width; no view is drawn meanwhile.
  await press('tab:controls');
  l = await layout();
  assert.equal(l.tab, 'controls');
  assert.deepEqual(l.views, []);
  const panel = (await api(page, 'status')).panel;
  assert.ok(panel.height > 300, `the panel has the screen's height (${panel.height})`);
  await screenshot(page, 'phone-portrait-controls.png');
  assert.deepEqual(errors, []);
}));

test('Phone upright: a finger draws and moves a disk, two fingers zoom, the strip steps PRM', () => withBrowser(async ({ browser, url }) => {
  const { page, errors, touch, fingerDrag, press, layout } = await phone(browser, url, PORTRAIT, '?lesson=step-prm');
  const before = (await api(page, 'get_scene')).obstacles.length;
  // Draw: the Disk tool from the strip over the view, a drag from the centre to the rim.
  await press('tool:disk');
  const [c, rim] = await worldToPage(page, [[0.5, 0.85], [0.58, 0.85]]);
  await fingerDrag(c, rim);
  let scene = await api(page, 'get_scene');
  assert.equal(scene.obstacles.length, before + 1, 'a disk was drawn');
  const disk = scene.obstacles[scene.obstacles.length - 1];
  assert.equal(disk.type, 'disk');
  const px = (await api(page, 'view', { view: 'workspace' })).scale;
  assert.ok(Math.hypot(disk.center[0] - 0.5, disk.center[1] - 0.85) < 3 / px, `centre ${disk.center}`);
  assert.ok(Math.abs(disk.radius - 0.08) < 3 / px, `radius ${disk.radius}`);
  // Move: the Select tool, the disk's body dragged by 0.1 to the left.
  await press('tool:select');
  const [inside, left] = await worldToPage(page, [[disk.center[0] + 0.02, disk.center[1]], [disk.center[0] - 0.08, disk.center[1]]]);
  await fingerDrag(inside, left);
  scene = await api(page, 'get_scene');
  const moved = scene.obstacles[scene.obstacles.length - 1];
  assert.ok(Math.abs(moved.center[0] - (disk.center[0] - 0.1)) < 3 / px, `moved to ${moved.center}`);
  assert.ok(Math.abs(moved.center[1] - disk.center[1]) < 3 / px);
  // The start marker is a 44 px target: a press 18 px off its centre still takes it.
  const [start] = await worldToPage(page, [scene.start]);
  const [to] = await worldToPage(page, [[scene.start[0] + 0.05, scene.start[1]]]);
  await fingerDrag({ x: start.x + 18, y: start.y }, { x: to.x + 18, y: to.y });
  const dragged = (await api(page, 'get_scene')).start;
  assert.ok(Math.abs(dragged[0] - (scene.start[0] + 0.05)) < 3 / px, `start follows the finger: ${dragged}`);

  // Pinch: two fingers spread apart over the view; the scene under them comes closer.
  const fitted = (await api(page, 'view', { view: 'workspace' })).scale;
  const w = view(await layout(), 'workspace');
  const box = await page.locator('canvas').boundingBox();
  const mid = { x: box.x + w.x + w.w / 2, y: box.y + w.y + w.h / 2 };
  await touch('touchStart', [{ x: mid.x - 40, y: mid.y }, { x: mid.x + 40, y: mid.y }]);
  for (let i = 1; i <= 8; ++i)
    await touch('touchMove', [{ x: mid.x - 40 - 10 * i, y: mid.y }, { x: mid.x + 40 + 10 * i, y: mid.y }]);
  await touch('touchEnd', []);
  const zoomed = (await api(page, 'view', { view: 'workspace' })).scale;
  // The fingers went from 80 px apart to 240: three times the scale.
  assert.ok(Math.abs(zoomed / fitted - 3) < 0.1, `pinch zoomed ${fitted} -> ${zoomed}`);
  assert.equal((await api(page, 'get_scene')).obstacles.length, before + 1, 'the pinch drew or moved nothing');
  assert.deepEqual((await api(page, 'get_scene')).start, dragged, 'nor moved the start');
  await screenshot(page, 'phone-portrait-zoomed.png');

  // Step PRM from the strip over the view; then to the end.
  await press('step');
  await press('step');
  assert.equal((await api(page, 'state')).steps, 2, 'two presses of Step, two steps');
  await press('run-all');
  const s = await api(page, 'state');
  assert.ok(s.done, 'Run all ran PRM to the end');
  // The log folds to its newest line; a press opens it.
  await press('log-toggle');
  assert.equal((await layout()).log_open, true);
  await screenshot(page, 'phone-portrait-step-prm.png');
  assert.deepEqual(errors, []);
}));

test('Phone upright: P13\'s two plots have the View tab, its forces table the Controls tab, uncut',
  () => withBrowser(async ({ browser, url }) => {
  const { page, errors, press, layout, fingerDrag } = await phone(browser, url, PORTRAIT, '?lesson=step-prm');
  await api(page, 'open_problem', { id: 'P13', seed: 7 });
  await waitFrames(page, 3);
  await press('tab:view');
  // Under the views the table left each of them 179 px (a plot of 108 px).
  const l = await layout();
  for (const name of ['workspace', 'cspace'])
    assert.ok(view(l, name).h >= 240, `${name} is ${view(l, name).h} px tall`);
  await screenshot(page, 'phone-portrait-P13-views.png');
  // On the Controls tab: every row of the table, its columns within the width (in two tables).
  await press('tab:controls');
  await waitFrames(page, 3);
  // Under the card and the lesson's examples: swiped up to (drawn only where it is seen).
  let s = await api(page, 'state', { layout: true });
  for (let i = 0; i < 6 && s.forces_layout.rows.length === 0; ++i) {
    await fingerDrag({ x: 195, y: 700 }, { x: 195, y: 450 });
    s = await api(page, 'state', { layout: true });
  }
  assert.equal(s.forces_layout.rows.length, 4, 'a row per vertex');
  assert.ok(s.forces_layout.table_right <= s.forces_layout.area_right, JSON.stringify(s.forces_layout));
  await screenshot(page, 'phone-portrait-P13-controls.png');
  assert.deepEqual(errors, []);
}));

for (const [held, viewport] of [['upright', PORTRAIT], ['on its side', LANDSCAPE]]) {
  test(`Phone ${held}: P10's caption and P13's forces header end within the screen; P13's numbers stay by its table`,
    () => withBrowser(async ({ browser, url }) => {
    const { page, errors, press, layout, control } = await phone(browser, url, viewport, '?lesson=step-prm');
    // P10: the circle's caption broken into lines the view's width (upright it ran past the
    // screen's right edge: "…the short way passes 0" lost its last word).
    await api(page, 'open_problem', { id: 'P10', seed: 7 });
    await waitFrames(page, 3);
    await press('tab:view');
    const caption = (await api(page, 'state', { layout: true })).caption_layout;
    assert.ok(caption, 'the distances lesson says where its caption is');
    // Drawn (a box of zeros would pass the bound below), and within the view and the screen.
    assert.ok(caption.box[2] - caption.box[0] > 100 && caption.box[3] > caption.box[1], JSON.stringify(caption));
    assert.ok(caption.box[2] <= caption.view_right && caption.view_right <= viewport.width, JSON.stringify(caption));
    await screenshot(page, `phone-${viewport.width}-P10-caption.png`);
    // P13: the forces area's header, its title within its frame (upright it was cut after "ρ, ∇ρ,").
    await api(page, 'open_problem', { id: 'P13', seed: 7 });
    await waitFrames(page, 3);
    assert.equal((await layout()).tab, 'controls');
    await api(page, 'check_answer', { answer: '0' });
    await waitFrames(page, 3);
    // "Show these numbers in the tool": the numbers P13 asks about are the forces table's, on
    // the Controls tab of a phone: the tab stays, the table open and scrolled to (it went to
    // the View tab, where the table is not). On its side the card is taller than the screen:
    // the check scrolled the panel to the button (it was under the bottom edge: a swipe).
    const tool = await control('show-in-tool');
    assert.ok(tool.y + tool.h / 2 <= viewport.height, `the button is on screen without a swipe (${JSON.stringify(tool)})`);
    await press('show-in-tool');
    await waitFrames(page, 4);
    assert.equal((await layout()).tab, 'controls', 'the forces table is where P13\'s numbers are');
    const forces = (await api(page, 'state', { layout: true })).forces_layout;
    assert.ok(forces.header_right <= forces.header_clip && forces.header_clip <= viewport.width, JSON.stringify(forces));
    assert.ok(forces.rows.length >= 1, `the table is on screen without a swipe (${JSON.stringify(forces)})`);
    if (viewport === PORTRAIT) assert.equal(forces.rows.length, 4, 'every vertex\'s row on screen');
    await screenshot(page, `phone-${viewport.width}-P13-shown.png`);
    assert.deepEqual(errors, []);
  }));
}

test('Phone on its side: a checked problem scrolls its result and buttons on screen, no swipe (P1 to P13)',
  () => withBrowser(async ({ browser, url }) => {
  const { page, errors } = await phone(browser, url, LANDSCAPE, '?lesson=step-prm');
  // The card is taller than the screen on its side: "Show these numbers in the tool" was under
  // the panel's bottom edge for P8 to P13 (P13's at 400 to 426 px of 390), seen only by a swipe.
  for (let i = 1; i <= 13; ++i) {
    const id = `P${i}`;
    await api(page, 'open_problem', { id, seed: 7 });
    await waitFrames(page, 3);
    assert.equal((await api(page, 'status')).layout.tab, 'controls');
    await api(page, 'check_answer', { answer: '0' });
    await waitFrames(page, 4);
    const b = await page.evaluate(() => window.cspacelab.pageState().buttons);
    // Between the tabs and the "more below" row (the screen's edge without it).
    const top = b['tab:controls'][3], bottom = b['panel-more'] ? b['panel-more'][1] : LANDSCAPE.height;
    const shown = ['show-solution', 'show-in-tool', 'see-in-3d'].filter((n) => b[n]);
    if (i >= 8) assert.ok(b['show-in-tool'], `${id} offers its numbers in the tool`);
    for (const n of shown)
      assert.ok(b[n][1] >= top && b[n][3] <= bottom, `${id}: ${n} at ${b[n]}, on screen from ${top} to ${bottom} px`);
    if (id === 'P13') await screenshot(page, 'phone-844-P13-checked.png');
  }
  assert.deepEqual(errors, []);
}));

for (const [held, viewport] of [['upright', PORTRAIT], ['on its side', LANDSCAPE]]) {
  test(`Phone ${held}: P13's shown numbers' notice names its tabs and covers none of the panel`,
    () => withBrowser(async ({ browser, url }) => {
    const { page, errors, press, layout, control } = await phone(browser, url, viewport, '?lesson=step-prm');
    await api(page, 'open_problem', { id: 'P13', seed: 7 });
    await waitFrames(page, 3);
    await api(page, 'check_answer', { answer: '0' });
    await waitFrames(page, 3);
    await press('show-in-tool');
    await screenshot(page, `phone-${viewport.width}-P13-notice.png`);  // first: the notice goes in 5 s
    // Read aloud by the page's accessible copy too: "the table here" meant nothing there.
    const { notice } = await api(page, 'status');
    assert.match(notice, /Controls tab/);
    assert.match(notice, /View tab/);
    assert.doesNotMatch(notice, /\bhere\b/i);
    // Over the top bar, above the tabs: not over the Field sliders at the bottom of the panel.
    const box = (await layout()).notice;
    assert.ok(box, 'the notice says where it is');
    const tabs = await control('tab:controls');
    assert.ok(box.y + box.h <= tabs.y - tabs.h / 2, `the notice ${JSON.stringify(box)} ends above the tabs (${JSON.stringify(tabs)})`);
    assert.ok(box.x >= 0 && box.x + box.w <= viewport.width, JSON.stringify(box));
    assert.deepEqual(errors, []);
  }));

  test(`Phone ${held}: P10's arc lengths keep off q₁'s and q₂'s dots`, () => withBrowser(async ({ browser, url }) => {
    const { page, errors, press } = await phone(browser, url, viewport, '?lesson=step-prm');
    await api(page, 'open_problem', { id: 'P10', seed: 7 });
    await waitFrames(page, 3);
    await press('tab:view');
    const meets = (a, b) => a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
    // The preset (on its side "d = 0.9832" sat on q₂'s dot), angles close together, across 0 and π.
    for (const [q1, q2] of [[0.5, 5.8], [1.0, 1.4], [5.01, 1.89], [3.0, 3.3], [6.1, 0.3]]) {
      await api(page, 'set_params', { params: { q1, q2 } });
      await waitFrames(page, 3);
      const c = (await api(page, 'state', { layout: true })).circle_layout;
      assert.ok(c && c.arc_labels.length === 2, JSON.stringify(c));
      const [d, rest] = c.arc_labels;
      for (const [k, dot] of c.handles.slice(0, 2).entries()) {  // q₁'s dot, q₂'s
        assert.ok(!meets(d, dot), `q = (${q1}, ${q2}): "d = …" ${d} over q${k + 1}'s dot ${dot}`);
        assert.ok(!meets(rest, dot), `q = (${q1}, ${q2}): "2π − d = …" ${rest} over q${k + 1}'s dot ${dot}`);
      }
      assert.ok(!meets(d, rest), `q = (${q1}, ${q2}): the two lengths overlap`);
      if (q1 === 0.5) await screenshot(page, `phone-${viewport.width}-P10-labels.png`);
    }
    assert.deepEqual(errors, []);
  }));
}

test('A tablet on its side by touch: the lesson buttons and the top bar\'s are 44 px high; by mouse as before',
  () => withBrowser(async ({ browser, url }) => {
  const viewport = { width: 1180, height: 820 };
  for (const touch of [true, false]) {
    const { page, errors } = await openPage(browser, url + '?lesson=torus', { viewport, hasTouch: touch, isMobile: touch });
    await waitFrames(page, 3);
    const l = (await api(page, 'status')).layout;
    assert.equal(l.mode, 'wide');
    assert.equal(l.touch, touch);
    const heights = await page.evaluate(() => Object.entries(window.cspacelab.pageState().buttons)
      .filter(([k]) => /^(lesson:|homework$|share$|embed$|file$)/.test(k)).map(([k, r]) => [k, r[3] - r[1]]));
    assert.equal(heights.length, 9 + 4, JSON.stringify(heights));
    // By touch a finger's 44 px (they were 26); by mouse ImGui's frame, as they were.
    for (const [name, h] of heights)
      assert.ok(touch ? h >= 44 : h < 30, `${touch ? 'touch' : 'mouse'}: ${name} is ${h} px high`);
    // The views keep most of the screen.
    const ws = view(l, 'workspace');
    assert.ok(ws.h >= 500, `the workspace is ${ws.h} px tall`);
    await screenshot(page, `tablet-1180x820-${touch ? 'touch' : 'mouse'}.png`);
    assert.deepEqual(errors, []);
    await page.close();
  }
}));

test('Phone on its side: compact, views side by side, PRM stepped', () => withBrowser(async ({ browser, url }) => {
  const { page, errors, press, layout } = await phone(browser, url, LANDSCAPE, '?lesson=torus');
  let l = await layout();
  await screenshot(page, 'phone-landscape-torus.png');
  assert.equal(l.mode, 'compact');
  const ws = view(l, 'workspace'), cs = view(l, 'cspace');
  assert.ok(ws && cs, 'the torus lesson shows the arm and its C-space');
  assert.ok(cs.x >= ws.x + ws.w - 1, 'side by side on a wide screen');
  assert.ok(ws.h >= 170, `the views have the height left (${ws.h})`);
  await press('step');
  assert.equal(await api(page, 'step', { count: 0 }), 1, 'one press of Step, one step');
  await press('lesson-menu');
  await press('lesson:step-prm');
  l = await layout();
  assert.ok(view(l, 'workspace').h >= 170);
  await press('run-all');
  assert.ok((await api(page, 'state')).done);
  await screenshot(page, 'phone-landscape-step-prm.png');
  assert.deepEqual(errors, []);
}));

test('A laptop keeps the wide layout; a tablet upright stacks two views', () => withBrowser(async ({ browser, url }) => {
  for (const [viewport, mode] of [[{ width: 1280, height: 800 }, 'wide'], [{ width: 768, height: 1024 }, 'wide']]) {
    const { page, errors } = await openPage(browser, url + '?lesson=torus', { viewport });
    await waitFrames(page, 3);
    const l = (await api(page, 'status')).layout;
    assert.equal(l.mode, mode);
    const ws = view(l, 'workspace'), cs = view(l, 'cspace');
    if (viewport.width > viewport.height) assert.ok(cs.x >= ws.x + ws.w - 1, 'side by side');
    else assert.ok(cs.y >= ws.y + ws.h - 1 && cs.w > 400, `stacked, each the width (${ws.w}, ${cs.w})`);
    await screenshot(page, `layout-${viewport.width}x${viewport.height}.png`);
    assert.deepEqual(errors, []);
    await page.close();
  }
}));

test('Phone: a long press opens the context menu; add a disk where the finger was, then delete it',
  () => withBrowser(async ({ browser, url }) => {
  const { page, errors, touch, tap, control } = await phone(browser, url, PORTRAIT, '?lesson=step-prm&scene=prm-demo');
  const longPress = async (at) => {
    await touch('touchStart', [at]);
    // The app opens the menu after 0.5 s and 30 frames held still (a busy machine draws slowly).
    await page.waitForFunction(() => Object.keys(window.cspacelab.pageState().buttons).some((b) => b.startsWith('context-')),
                               null, { timeout: 10000 });
    await touch('touchEnd', []);
    await waitFrames(page, 2);
  };
  const before = await api(page, 'get_scene');
  const spot = [0.2, 0.45];  // free in prm-demo: between the lower disk and the upper polygon
  const [at] = await worldToPage(page, [spot]);
  // A short tap opens nothing.
  await tap(at);
  assert.equal(await control('context-add-disk'), null, 'a tap is not a long press');
  // Nor is a press with the Disk tool held still: it draws (a slow start of a disk).
  await tap(await control('tool:disk'));
  await touch('touchStart', [at]);
  await page.waitForTimeout(700);
  await waitFrames(page, 40);
  assert.equal(await control('context-add-disk'), null, 'no menu while drawing');
  await touch('touchEnd', []);
  assert.deepEqual(await api(page, 'get_scene'), before, 'a disk of no size is not added');
  await tap(await control('tool:select'));
  await longPress(at);
  assert.ok(await control('context-add-disk'), 'the menu for empty space');
  assert.equal(await control('context-delete'), null, 'no obstacle there to delete');
  await screenshot(page, 'phone-context-menu.png');
  await tap(await control('context-add-disk'));
  const added = await api(page, 'get_scene');
  assert.equal(added.obstacles.length, before.obstacles.length + 1);
  const disk = added.obstacles.at(-1);
  assert.equal(disk.type, 'disk');
  const scale = (await page.evaluate(() => window.cspacelab.status())).layout.views.find((v) => v.name === 'workspace').w;
  assert.ok(Math.hypot(disk.center[0] - spot[0], disk.center[1] - spot[1]) < 3 / scale, `where the finger was: ${disk.center}`);
  assert.ok(disk.radius > 0.01 && disk.radius < 0.2, `a disk of a sensible size: ${disk.radius}`);
  assert.deepEqual(added.start, before.start, 'nothing else moved');
  // The new disk, long-pressed: its menu deletes it.
  await longPress(at);
  assert.ok(await control('context-delete'), 'the menu for an obstacle');
  await tap(await control('context-delete'));
  assert.deepEqual(await api(page, 'get_scene'), before, 'deleted: the scene as it was');
  // A long press on the start opens the menu and moves nothing (the press began a drag).
  const [start] = await worldToPage(page, [before.start]);
  await longPress(start);
  assert.ok(await control('context-undo'), 'the menu opened on the start');
  await tap(await control('context-undo'));
  assert.equal((await api(page, 'get_scene')).obstacles.length, before.obstacles.length + 1, 'Undo brought the disk back');
  assert.deepEqual((await api(page, 'get_scene')).start, before.start);
  assert.deepEqual(errors, []);
}));

test('Phone: under lock=scene a long press on empty space says why no menu opens',
  () => withBrowser(async ({ browser, url }) => {
  const { page, errors, touch, control } = await phone(browser, url, PORTRAIT, '?lesson=step-prm&scene=prm-demo&lock=scene');
  const before = await api(page, 'get_scene');
  assert.equal((await api(page, 'status')).notice, '', 'the link was read without complaint');
  const [at] = await worldToPage(page, [[0.2, 0.45]]);  // free in prm-demo
  await touch('touchStart', [at]);
  // As long as an unlocked lab takes to open its menu (0.5 s and 30 frames held still).
  await page.waitForFunction(() => /fixed by your instructor/.test(window.cspacelab.status().notice), null, { timeout: 10000 });
  await touch('touchEnd', []);
  await waitFrames(page, 2);
  assert.equal(await control('context-add-disk'), null, 'no menu');
  assert.deepEqual(await api(page, 'get_scene'), before, 'nothing changed');
  assert.deepEqual(errors, []);
}));

test('Phone on its side: a swipe scrolls the Controls panel, and one that starts on a button does not press it',
  () => withBrowser(async ({ browser, url }) => {
  // ImGui scrolls by wheel and scrollbar only; a student's swipe did nothing before panel.cpp's
  // follow_finger. On its side, a phone shows a third of Step PRM's panel.
  const { page, errors, tap, fingerDrag, control, press } = await phone(browser, url, LANDSCAPE, '?lesson=step-prm');
  await press('tab:controls');
  const panel = async () => (await api(page, 'status')).panel;
  const steps = async () => (await api(page, 'status')).stepping.steps;
  let p = await panel();
  assert.ok(p.scroll_max > 150, `the panel has more than a screen to show (${p.scroll_max} px to scroll)`);
  assert.equal(p.scroll, 0);
  const box = await page.evaluate(() => window.cspacelab.module.canvas.getBoundingClientRect().toJSON());
  // Up from the Step button: the panel follows the finger, and PRM takes no step.
  const at = await control('step');
  assert.ok(at, 'Step is in the panel');
  const up = Math.min(100, Math.round(at.y - box.top - 10));
  assert.ok(up > 40, `room to swipe up from Step (${up} px)`);
  await fingerDrag(at, { x: at.x, y: at.y - up });
  await waitFrames(page, 3);
  p = await panel();
  assert.ok(Math.abs(p.scroll - up) <= 4, `scrolled by the finger's ${up} px (${p.scroll})`);
  assert.equal(await steps(), 0, 'the swipe did not press the Step button it began on');
  // On to the end: the panel stops there, however far the finger goes.
  const mid = { x: box.left + box.width / 2, y: box.top + box.height * 0.8 };
  await fingerDrag(mid, { x: mid.x, y: box.top + 10 });
  await fingerDrag(mid, { x: mid.x, y: box.top + 10 });
  await waitFrames(page, 3);
  p = await panel();
  assert.ok(Math.abs(p.scroll - p.scroll_max) <= 1, `at the end (${p.scroll} of ${p.scroll_max})`);
  await screenshot(page, 'phone-controls-swiped.png');
  // Down again, back to the top.
  for (let i = 0; i < 6 && (await panel()).scroll > 0; ++i)
    await fingerDrag({ x: mid.x, y: box.top + box.height * 0.45 }, { x: mid.x, y: box.top + box.height - 20 });
  await waitFrames(page, 3);
  assert.equal((await panel()).scroll, 0);
  // A sideways drag is no swipe; a tap still presses the button.
  const again = await control('step');
  await fingerDrag(again, { x: again.x + 30, y: again.y + 3 });
  assert.equal((await panel()).scroll, 0, 'a sideways drag does not scroll');
  const before = await steps();
  await tap(await control('step'));
  await waitFrames(page, 3);
  assert.equal(await steps(), before + 1, 'a tap on Step steps');
  assert.deepEqual(errors, []);
}));
