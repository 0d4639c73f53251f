// Lesson "Distances" (homework P10 and P11) in the browser, with real mouse, touch and keys:
// every number the lesson reports is checked against formulas written again here (and against
// the CLI's `distance`), after a drag of a handle in each tool, typing into the fields, the
// special cases, refused parameters, the pictures' colours, and a 900 px wide embed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, withBrowser, collectErrors, openLab, worldToPage, drag, keys, chord, click, waitFrames,
         screenshot, inspectPng, api, cli, refusal, pageButton } from './lib/harness.mjs';

const TAU = 2 * Math.PI;
const close = (a, b, tol = 1e-12) => Math.abs(a - b) <= tol * Math.max(1, Math.abs(a), Math.abs(b));
const near = (a, b, tol, what) => assert.ok(Math.abs(a - b) <= tol, `${what}: ${a} vs ${b} (tolerance ${tol})`);

// ------------------------------------------------------------------ oracles

// P10 by brute force: the shortest of q2 - q1 shifted by whole turns.
function s1Distance(q1, q2) {
  let best = Math.abs(q2 - q1);
  for (let k = -400; k <= 400; ++k) best = Math.min(best, Math.abs(q2 - q1 + TAU * k));
  return best;
}
const wrapPositive = (a) => ((a % TAU) + TAU) % TAU;

// Every P10 number of the state against the oracle.
function checkS1(s) {
  const { q1, q2, s1: a } = s;
  assert.equal(a.q1, q1);
  assert.equal(a.q2, q2);
  const d = s1Distance(q1, q2);
  near(a.distance, d, 1e-12, 'd');
  near(a.modular_distance, d, 1e-12, 'd by the modulus');
  near(a.rotation_distance, d, 1e-12, 'd by rotations (atan2)');
  near(a.arccos_distance, d, Math.min(1e-7, 1e-12 + 4e-15 / Math.max(Math.sin(d), 1e-300)), 'd by arccos');
  near(a.raw_difference, Math.abs(q1 - q2), 0, '|q1 - q2|');
  near(a.modulus, Math.abs(q1 - q2) - TAU * Math.floor(Math.abs(q1 - q2) / TAU), 1e-12, '|q1 - q2| mod 2pi');
  near(a.other_way, TAU - a.modulus, 1e-12, '2pi - modulus');
  for (const [i, q] of [[0, q1], [1, q2]]) {
    near(a.cos[i], Math.cos(q), 1e-14, 'cos');
    near(a.sin[i], Math.sin(q), 1e-14, 'sin');
    near(a.degrees[i], q * 180 / Math.PI, 1e-9, 'degrees');
    assert.ok(a.wrapped[i] >= 0 && a.wrapped[i] < TAU, 'wrapped into [0, 2pi)');
    near(s1Distance(a.wrapped[i], q), 0, 1e-12, 'the same direction');
  }
  near(a.dot, Math.cos(q1) * Math.cos(q2) + Math.sin(q1) * Math.sin(q2), 1e-14, 'dot');
  near(a.dot, Math.cos(d), 1e-12, 'dot = cos d');
  near(Math.abs(a.signed_turn), d, 1e-12, '|signed turn| = d');
  near(s1Distance(q1 + a.signed_turn, q2), 0, 1e-12, 'the turn lands on q2');
  const kind = d <= 1e-9 ? 'equal' : d >= Math.PI - 1e-9 ? 'antipodal' : 'general';
  assert.equal(a.case, kind);
  if (kind === 'general') {
    const [w1, w2] = [wrapPositive(q1), wrapPositive(q2)];
    assert.equal(a.wraps_around, Math.abs(w1 - w2) > Math.PI, 'whether the short way passes 0');
  }
  return d;
}

// P11 from the handout's derivation, and by 100001 samples of the segment.
function segmentOracle(p1, p2, q, r) {
  const dx = p2[0] - p1[0], dy = p2[1] - p1[1];
  const L = dx * dx + dy * dy;
  const tRaw = L === 0 ? null : ((q[0] - p1[0]) * dx + (q[1] - p1[1]) * dy) / L;
  const t = tRaw === null ? 0 : Math.min(1, Math.max(0, tRaw));
  const c = [p1[0] + t * dx, p1[1] + t * dy];
  const cd = Math.hypot(q[0] - c[0], q[1] - c[1]);
  let sampled = Infinity;
  for (let i = 0; i <= 100000; ++i)
    sampled = Math.min(sampled, Math.hypot(q[0] - p1[0] - (i / 1e5) * dx, q[1] - p1[1] - (i / 1e5) * dy));
  const kind = L === 0 ? 'degenerate' : tRaw <= 0 ? 'p1' : tRaw >= 1 ? 'p2' : 'interior';
  return { L, tRaw, t, c, cd, sampled, step: Math.sqrt(L) / 1e5, kind };
}

function checkSegment(s) {
  const g = s.segment;
  assert.deepEqual([g.p1, g.p2, g.q, g.r], [s.p1, s.p2, s.q, s.r]);
  const o = segmentOracle(s.p1, s.p2, s.q, s.r);
  near(g.length_squared, o.L, 1e-14, '|p2 - p1|^2');
  if (o.tRaw === null) assert.equal(g.t_raw, null, 't* undefined');
  else near(g.t_raw, o.tRaw, 1e-12 * Math.max(1, Math.abs(o.tRaw)), 't*');
  near(g.t, o.t, 1e-12, 't');
  near(g.closest[0], o.c[0], 1e-12, 'c.x');
  near(g.closest[1], o.c[1], 1e-12, 'c.y');
  near(g.centre_distance, o.cd, 1e-12, '|q - c|');
  assert.ok(g.centre_distance <= o.sampled + 1e-12 && g.centre_distance >= o.sampled - o.step / 2 - 1e-12,
            'the nearest of 100001 samples agrees');
  near(g.distance, Math.max(0, o.cd - s.r), 1e-12, 'max(0, |q - c| - r)');
  near(g.signed_distance, o.cd - s.r, 1e-12, '|q - c| - r');
  near(g.lab_clearance, o.cd - s.r, 1e-12, 'eta');
  assert.equal(g.case, o.kind);
  assert.equal(g.meets, o.cd <= s.r);
  return o;
}

// The CLI computes the same distances with the same core functions: equal to the bit.
function checkCli(s) {
  const a = cli('distance', 's1', String(s.q1), String(s.q2));
  assert.equal(a.distance, s.s1.distance);
  assert.equal(a.rotation, s.s1.rotation_distance);
  const b = cli('distance', 'segment-disk', '--p1', s.p1.join(','), '--p2', s.p2.join(','), '--center', s.q.join(','),
                '--radius', String(s.r));
  assert.equal(b.signed, s.segment.lab_clearance);
  near(b.distance, s.segment.distance, 1e-12, 'the CLI distance');
}

const unit = (a) => [Math.cos(a), Math.sin(a)];
const isOrange = ([r, g, b]) => r > 200 && g > 130 && g < 190 && b < 70;  // the short arc, the distance
const isFaintBlue = ([r, g, b]) => b > r + 30 && b > 160 && g < 200;      // the long arc, faint over the circle
const isVermillion = ([r, g, b]) => r > 170 && g < 130 && b < 70;

async function probe(page, browser, name, points, view) {
  const at = await worldToPage(page, points, view);
  const { png } = await screenshot(page, name);
  return (await inspectPng(browser, png, at.map((p) => [p.x, p.y]))).at;
}

// ------------------------------------------------------------------ P10

test('Distances, angles on S^1: drag, type, the special cases, the arcs on screen', () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'distances' });
  await waitFrames(page, 3);
  let s = await api(page, 'state');
  assert.deepEqual((await api(page, 'snapshot')).params, { tool: 's1', q1: 0.5, q2: 5.8, p1: [0.2, 0.3], p2: [0.8, 0.6], q: [0.55, 0.2], r: 0.1 });
  assert.equal(checkS1(s).toFixed(6), (TAU - 5.3).toFixed(6));
  assert.equal(s.s1.wraps_around, true, 'the default: the short way crosses 0');
  checkCli(s);

  // The short arc (orange) passes 0; the other way round is faint.
  let rgb = await probe(page, browser, 'distances-s1.png', [unit(0.2), unit(1.6), unit(3.5)], 'circle');
  assert.ok(isOrange(rgb[0]), `short arc at 0.2 rad: ${rgb[0]}`);
  assert.ok(isFaintBlue(rgb[1]) && isFaintBlue(rgb[2]), `long arc: ${rgb[1]} ${rgb[2]}`);

  // Drag q2 with the mouse from 5.8 round to 2.2 rad: the short way no longer passes 0.
  const [from, to] = await worldToPage(page, [unit(5.8), unit(2.2)], 'circle');
  await drag(page, from, to, 12);
  s = await api(page, 'state');
  assert.equal(s.q1, 0.5);
  near(s.q2, 2.2, 0.02, 'q2 follows the mouse');
  checkS1(s);
  assert.equal(s.s1.case, 'general');
  assert.equal(s.s1.wraps_around, false);
  checkCli(s);
  rgb = await probe(page, browser, 'distances-s1-dragged.png', [unit(0.2), unit(1.6), unit(3.5)], 'circle');
  assert.ok(isFaintBlue(rgb[0]), `0.2 rad is now on the long arc: ${rgb[0]}`);
  assert.ok(isOrange(rgb[1]), `1.6 rad is on the short arc: ${rgb[1]}`);

  // Dragged near the opposite point it snaps there: antipodal, both halves drawn alike.
  const [q2At, nearOpposite] = await worldToPage(page, [unit(s.q2), unit(0.5 + Math.PI + 0.01)], 'circle');
  await drag(page, q2At, nearOpposite, 8);
  s = await api(page, 'state');
  checkS1(s);
  assert.equal(s.s1.case, 'antipodal');
  near(s.s1.distance, Math.PI, 1e-12, 'd = pi');
  await screenshot(page, 'distances-s1-antipodal.png');

  // The keyboard: type into q1, Tab to q2; an angle outside [0, 2pi) wraps.
  const q1Field = await pageButton(page, 'distances-q1');
  await click(page, q1Field);
  await chord(page, 'Control', 'a');
  await page.keyboard.type('7', { delay: 30 });
  await keys(page, 'Tab');
  await chord(page, 'Control', 'a');
  await page.keyboard.type('-1', { delay: 30 });
  await keys(page, 'Enter');
  s = await api(page, 'state');
  assert.equal(s.q1, 7);
  assert.equal(s.q2, -1);
  checkS1(s);
  near(s.s1.wrapped[0], 7 - TAU, 1e-12, '7 wraps');
  near(s.s1.distance, 8 - TAU, 1e-12, 'd(7, -1)');
  checkCli(s);
  // Out of range while typing: refused with a notice, the last good value kept.
  await click(page, q1Field);
  await chord(page, 'Control', 'a');
  await page.keyboard.type('1e9', { delay: 30 });
  await keys(page, 'Enter');
  s = await api(page, 'state');
  assert.equal(s.q1, 1, '"1" and "1e" were taken on the way, 1e9 was not');
  assert.match((await api(page, 'status')).notice, /within ±1000/);

  // The buttons: equal, then opposite.
  await click(page, await pageButton(page, 'distances-equal'));
  s = await api(page, 'state');
  checkS1(s);
  assert.equal(s.s1.case, 'equal');
  assert.equal(s.s1.distance, 0);
  await click(page, await pageButton(page, 'distances-antipodal'));
  s = await api(page, 'state');
  checkS1(s);
  assert.equal(s.s1.case, 'antipodal');

  // Through the API: whole turns apart are equal; refusals name the key and change nothing.
  await api(page, 'set_params', { params: { q1: 1, q2: 1 + 4 * Math.PI } });
  s = await api(page, 'state');
  checkS1(s);
  assert.equal(s.s1.case, 'equal');
  const before = (await api(page, 'snapshot')).params;
  for (const [params, message] of [
    [{ q1: 'x' }, /^q1: /], [{ q2: 1001 }, /^q2: .*1000/], [{ q1: 0.3, q2: -1e4 }, /^q2: /],
    [{ tool: 'circle' }, /^tool: /], [{ r: -0.1 }, /^r: /], [{ p1: [0, 0, 0] }, /^p1: /], [{ q: [0, 2000] }, /^q: /],
    [{ p2: ['a', 1] }, /^p2: /], [{ nope: 1 }, /unknown parameter "nope"/], [[1, 2], /must be an object/],
  ]) {
    const why = await refusal(page, 'setParams', params);
    assert.match(String(why), message, JSON.stringify(params));
    assert.deepEqual((await api(page, 'snapshot')).params, before, `${JSON.stringify(params)} changed nothing`);
  }
  // Its work restores exactly (links and autosave go through params()).
  const snapshot = await api(page, 'snapshot');
  await api(page, 'set_params', { params: { q1: 2 } });
  await api(page, 'restore', snapshot);
  assert.deepEqual(await api(page, 'snapshot'), snapshot);
}));

// ------------------------------------------------------------------ P11

test('Distances, segment to disk: drag, the cases, the picture, typing, F', () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'distances' });
  await waitFrames(page, 2);
  // The toggle at the top of the panel, with the mouse.
  await click(page, await pageButton(page, 'distances-tool-segment'));
  let s = await api(page, 'state');
  assert.equal(s.tool, 'segment');
  let o = checkSegment(s);
  assert.equal(s.segment.case, 'interior');
  near(o.tRaw, 0.4, 1e-12, "the default's t*");
  checkCli(s);
  const view = await api(page, 'view', { view: 'workspace', points: [[0, 0], [1, 1]] });
  assert.ok(view.scale > 100, 'the workspace view is registered');

  // Pixels: the disk is filled at its centre's side, the distance drawn orange between rim and c.
  const rimToC = [0.55 + (0.44 - 0.55) * 0.7, 0.2 + (0.42 - 0.2) * 0.7];  // on q -> c, outside the disk
  let rgb = await probe(page, browser, 'distances-segment.png', [[0.62, 0.18], [0.63, 0.77], rimToC], 'workspace');
  const disk = rgb[0], empty = rgb[1];
  assert.ok(disk[0] < 225 && Math.abs(disk[0] - disk[2]) < 30, `disk fill: ${disk}`);
  assert.ok(empty[0] > 235 && empty[1] > 235 && empty[2] > 235, `background: ${empty}`);
  assert.ok(isOrange(rgb[2]), `the distance segment: ${rgb[2]}`);

  // Drag the disk's centre q with the mouse beyond p2: the nearest point becomes p2.
  const [qAt, target] = await worldToPage(page, [[0.55, 0.2], [0.9, 0.75]], 'workspace');
  await drag(page, qAt, target, 10);
  s = await api(page, 'state');
  near(s.q[0], 0.9, 2 / view.scale, 'q.x follows the mouse');
  near(s.q[1], 0.75, 2 / view.scale, 'q.y follows the mouse');
  o = checkSegment(s);
  assert.equal(s.segment.case, 'p2');
  assert.ok(o.tRaw > 1);
  assert.deepEqual(s.segment.closest, s.p2, 'c is p2 itself');
  checkCli(s);
  rgb = await probe(page, browser, 'distances-segment-dragged.png', [[0.63, 0.18], [0.97, 0.77]], 'workspace');
  assert.ok(rgb[0][0] > 235 && rgb[0][2] > 235, `the disk left: ${rgb[0]}`);
  assert.ok(rgb[1][0] < 225, `the disk is here now: ${rgb[1]}`);

  // Drag the rim: r grows until the disk meets the segment (distance 0, eta negative, red edge).
  s = await api(page, 'state');
  const [rimAt, wider] = await worldToPage(page, [[s.q[0] + s.r, s.q[1]], [s.q[0] + 0.25, s.q[1]]], 'workspace');
  await drag(page, rimAt, wider, 8);
  s = await api(page, 'state');
  near(s.r, 0.25, 2 / view.scale, 'r follows the rim');
  o = checkSegment(s);
  assert.equal(s.segment.meets, true);
  assert.equal(s.segment.distance, 0);
  assert.ok(s.segment.lab_clearance < 0, 'eta keeps the depth');
  const edge = [];
  for (let k = -4; k <= 4; ++k) edge.push([s.q[0], s.q[1] - s.r + k / view.scale]);
  rgb = await probe(page, browser, 'distances-segment-meets.png', edge, 'workspace');
  assert.ok(rgb.some(isVermillion), `a red rim: ${JSON.stringify(rgb)}`);

  // The other cases through the API: p1, degenerate, interior meeting, r = 0.
  for (const params of [
    { p1: [0.2, 0.3], p2: [0.8, 0.6], q: [0.05, 0.1], r: 0.05 },
    { p1: [0.3, 0.3], p2: [0.3, 0.3], q: [0.6, 0.7], r: 0.2 },
    { p1: [0.1, 0.5], p2: [0.9, 0.5], q: [0.5, 0.55], r: 0.1 },
    { p1: [0.1, 0.5], p2: [0.9, 0.5], q: [0.5, 0.5], r: 0 },
    { p1: [0, 0], p2: [1, 0], q: [0, 1], r: 0.5 },  // t* exactly 0 is the endpoint
  ]) {
    await api(page, 'set_params', { params });
    s = await api(page, 'state');
    checkSegment(s);
    checkCli(s);
  }
  assert.equal(s.segment.case, 'p1');
  assert.equal(s.segment.t_raw, 0);
  // The "p2 = p1" button makes the segment a point.
  await click(page, await pageButton(page, 'distances-degenerate'));
  s = await api(page, 'state');
  assert.deepEqual(s.p2, s.p1);
  checkSegment(s);
  assert.equal(s.segment.case, 'degenerate');
  assert.equal(s.segment.t_raw, null);

  // Typing a coordinate: the first field of p1.
  const field = (await page.evaluate(() => window.cspacelab.pageState().buttons['distances-p1']));
  const box = await page.locator('canvas').boundingBox();
  await click(page, { x: box.x + field[0] + (field[2] - field[0]) * 0.2, y: box.y + (field[1] + field[3]) / 2 });
  await chord(page, 'Control', 'a');
  await page.keyboard.type('0.125', { delay: 30 });
  await keys(page, 'Enter');
  s = await api(page, 'state');
  assert.equal(s.p1[0], 0.125);
  checkSegment(s);

  // F fits the workspace view again after zooming.
  await api(page, 'set_params', { params: { p1: [0.2, 0.3], p2: [0.8, 0.6], q: [0.55, 0.2], r: 0.1 } });
  await waitFrames(page, 2);
  const fitted = (await api(page, 'view', { view: 'workspace' })).scale;
  await page.mouse.move(target.x, target.y);
  await page.mouse.wheel(0, -300);
  await waitFrames(page, 3);
  assert.ok((await api(page, 'view', { view: 'workspace' })).scale > fitted * 1.1, 'zoomed in');
  await keys(page, 'f');
  assert.equal((await api(page, 'view', { view: 'workspace' })).scale, fitted, 'F fits it');
}));

// Touch: a finger drags q2 on the circle and q on the workspace (ImGui takes touch as the mouse).
test('Distances: a finger drags the handles', () => withBrowser(async ({ browser, url }) => {
  const ctx = await browser.newContext({ viewport: { width: 1280, height: 800 }, hasTouch: true });
  const page = await ctx.newPage();
  const errors = collectErrors(page);
  await openLab(page, url + '?lesson=distances');
  await waitFrames(page, 3);
  const cdp = await ctx.newCDPSession(page);
  const touch = async (type, at) => {
    await cdp.send('Input.dispatchTouchEvent', { type, touchPoints: at ? [{ x: at.x, y: at.y }] : [] });
    await waitFrames(page, 2);
  };
  const fingerDrag = async (from, to, steps = 10) => {
    await touch('touchStart', from);
    for (let i = 1; i <= steps; ++i)
      await touch('touchMove', { x: from.x + (to.x - from.x) * i / steps, y: from.y + (to.y - from.y) * i / steps });
    await touch('touchEnd');
    await waitFrames(page, 2);
  };
  const [from, to] = await worldToPage(page, [unit(5.8), unit(4.0)], 'circle');
  await fingerDrag(from, to);
  let s = await api(page, 'state');
  near(s.q2, 4.0, 0.03, 'q2 follows the finger');
  checkS1(s);

  await api(page, 'set_params', { params: { tool: 'segment' } });
  await waitFrames(page, 2);
  const [qAt, target] = await worldToPage(page, [[0.55, 0.2], [0.3, 0.7]], 'workspace');
  await fingerDrag(qAt, target);
  s = await api(page, 'state');
  const { scale } = await api(page, 'view', { view: 'workspace' });
  near(s.q[0], 0.3, 3 / scale, 'q.x follows the finger');
  near(s.q[1], 0.7, 3 / scale, 'q.y follows the finger');
  checkSegment(s);
  await screenshot(page, 'distances-touch.png');
  assert.deepEqual(errors, []);
}));

// A 900 px wide embed: both tools fit, the numbers are the lesson's, and the link's parameters
// are applied.
test('Distances in a 900 px wide embed', () => withBrowser(async ({ browser, url }) => {
  const page = await browser.newPage({ viewport: { width: 960, height: 700 } });
  const errors = collectErrors(page);
  const host = url + 'test-host.html';
  await page.route(host, (route) => route.fulfill({
    contentType: 'text/html',
    body: `<!doctype html><html><head><meta charset="utf-8"><title>host</title></head><body style="margin:0">
      <iframe src="embed.html?lesson=distances&amp;q1=0.25&amp;q2=3" style="border:0;width:900px;height:600px"
      title="lab"></iframe></body></html>`,
  }));
  await page.goto(host);
  const frame = await (await page.waitForSelector('iframe')).contentFrame();
  await frame.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2, null, { timeout: 30000 });
  await waitFrames(frame, 3);
  let s = await frame.evaluate(() => window.cspacelab.state());
  assert.equal(s.q1, 0.25);
  assert.equal(s.q2, 3);
  checkS1(s);
  const shotS1 = await screenshot(page, 'distances-embed-s1.png');
  // The short arc (0.25 -> 3 counter-clockwise) is orange.
  const box = await page.locator('iframe').boundingBox();
  const local = (await frame.evaluate(() => window.cspacelab.view([[Math.cos(1.9), Math.sin(1.9)]], 'circle'))).points[0];
  const [arc] = (await inspectPng(browser, shotS1.png, [[box.x + local[0], box.y + local[1]]])).at;
  assert.ok(isOrange(arc), `the short arc in the embed: ${arc}`);
  await frame.evaluate(() => window.cspacelab.setParams({ tool: 'segment', q: [0.1, 0.1], r: 0.3 }));
  await waitFrames(frame, 3);
  s = await frame.evaluate(() => window.cspacelab.state());
  checkSegment(s);
  assert.equal(s.segment.case, 'p1');
  assert.equal(s.segment.meets, true);
  await screenshot(page, 'distances-embed-segment.png');
  assert.deepEqual(errors, []);
}));

// The homework map opens this lesson for P10 and P11 and, once an answer was checked, puts the
// exercise's numbers into the tool: the lesson takes them, and its distance is the exercise's.
test('Distances from the homework map: P10 and P11 exercises shown in the tools', () => withPage(async ({ page }) => {
  for (const [id, tool, check] of [['P10', 's1', checkS1], ['P11', 'segment', checkSegment]]) {
    const opened = await api(page, 'open_problem', { id, seed: 7 });
    assert.equal((await api(page, 'status')).lesson, 'distances');
    assert.equal((await api(page, 'state')).tool, tool);
    const checked = await api(page, 'check_answer', { answer: '0.1' });
    await api(page, 'show_exercise');
    await waitFrames(page, 2);
    const s = await api(page, 'state');
    for (const [key, value] of Object.entries(opened.exercise.given)) assert.deepEqual(s[key], value, `${id}: ${key}`);
    check(s);
    const distance = tool === 's1' ? s.s1.distance : s.segment.distance;
    near(Number(checked.expected), distance, 1e-5, `${id}: the exercise's answer is the lesson's distance`);
  }
  await screenshot(page, 'distances-homework-p11.png');
}));
