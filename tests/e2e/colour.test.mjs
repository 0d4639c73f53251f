// Colour that survives colour blindness, and text that reads (WCAG 2.1 AA 1.4.1, 1.4.3, 1.4.11).
// The colours come from the app itself (the `theme` API command, src/app/shell/theme_api.cpp),
// and from a real screenshot, so neither a copy of theme.hpp nor the GPU's blending can drift.
//
// The threshold: two colours that must be told apart stay at least CIEDE2000 10 apart for
// normal vision and for each dichromacy at full severity (Machado et al. 2009). About 2.3 is
// a difference just noticed side by side on large patches; the lab's marks are thin lines and
// 5 to 9 px dots seen apart from each other, where a difference must be obvious at a glance:
// 10 is the figure palette tools for colour-blind-safe charts use for that, and Okabe–Ito's
// pairs used here (green/vermillion, blue/orange) clear it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, api, waitFrames, keys, expectView, inspectPng, screenshot } from './lib/harness.mjs';
import { contrast, distance, deltaE2000, simulate, over, DICHROMACIES } from './lib/colour.mjs';

const MIN_DE = 10;
const MIN_TEXT = 4.5;     // WCAG 1.4.3, normal text
const MIN_GRAPHIC = 3;    // WCAG 1.4.11, marks needed to understand the picture

/** The smallest CIEDE2000 of two colours over normal vision and the three dichromacies, and where. */
function worst(a, b) {
  return [null, ...DICHROMACIES].map((kind) => ({ kind: kind || 'normal vision', de: distance(a, b, kind) }))
    .reduce((m, x) => (x.de < m.de ? x : m));
}

/** The pairs closer than MIN_DE somewhere, as lines for a failure message. */
function tooClose(pairs) {
  return pairs.map(([name, a, b]) => ({ name, a, b, ...worst(a, b) })).filter((p) => p.de < MIN_DE)
    .map((p) => `${p.name}: rgb(${p.a.slice(0, 3).map(Math.round)}) vs rgb(${p.b.slice(0, 3).map(Math.round)}), ` +
                `ΔE00 ${p.de.toFixed(1)} with ${p.kind}`);
}

test('the colour maths: published values', () => {
  // Sharma, Wu and Dalal (2005), table 1, pairs 1 and 17.
  assert.equal(deltaE2000([50, 2.6772, -79.7751], [50, 0, -82.7485]).toFixed(4), '2.0425');
  assert.equal(deltaE2000([50, 2.5, 0], [73, 25, -18]).toFixed(4), '27.1492');
  assert.equal(contrast([0, 0, 0], [255, 255, 255]), 21);
  assert.equal(contrast([118, 118, 118], [255, 255, 255]).toFixed(2), '4.54');  // WCAG's well-known grey
  for (const kind of DICHROMACIES) {  // each matrix keeps greys grey and loses one kind of contrast
    assert.ok(distance([128, 128, 128], simulate([128, 128, 128], kind)) < 1, kind);
  }
  // Each loses the contrast of its own confusion line, not another's: red/green for protanopes
  // and deuteranopes, a teal and an azure for tritanopes (who still tell red from green).
  const red = [255, 0, 0], green = [0, 255, 0], teal = [0, 180, 180], azure = [0, 140, 255];
  for (const kind of ['protanopia', 'deuteranopia']) assert.ok(distance(red, green, kind) < distance(red, green) / 2, kind);
  assert.ok(distance(teal, azure, 'tritanopia') < distance(teal, azure) / 2);
  assert.ok(distance(red, green, 'tritanopia') > distance(red, green) / 2);
});

const LOOKS = [['light', {}], ['dark', { scheme: 'dark' }], ['light, high contrast', { contrast: 'high' }],
               ['dark, high contrast', { scheme: 'dark', contrast: 'high' }]];

test('the theme, in every look: meaning stays apart for every dichromacy; text reads at 4.5:1', () => withPage(async ({ page }) => {
  const seen = new Set();
  for (const [look, choice] of LOOKS) {
    await api(page, 'page_state', { scheme: 'system', contrast: 'system', ...choice });
    await waitFrames(page, 2);  // the look changes between frames
    const theme = await api(page, 'theme');
    assert.deepEqual(theme.look, { dark: !!choice.scheme, high_contrast: !!choice.contrast }, `${look}: in use`);
    seen.add(JSON.stringify(theme.colours));
    console.log(`# ${look}:`);
    checkTheme(theme, look);
  }
  assert.equal(seen.size, LOOKS.length, 'each look has colours of its own');
}));

function checkTheme({ colours: c, components, text }, look) {
  const canvas = c.canvas;
  const onCanvas = (x) => over(x, canvas);
  const obstacle = onCanvas(c.obstacle);
  const pairs = [
    ['start vs goal', c.start, c.goal],
    ['free vs in collision', c.free, c.hit],
    ['the robot free vs in collision', c.robot, c.hit],
    ['the path vs an obstacle', c.path, obstacle],
    ['the path vs the canvas', c.path, canvas],
    ['the path vs the step being shown', c.path, c.current],
    ['start vs an obstacle', c.start, obstacle],
    ['goal vs an obstacle', c.goal, obstacle],
    ['the warning ring vs an obstacle', c.warning, obstacle],
    ['a C-obstacle vs free C-space', obstacle, canvas],
    ['the step being shown vs the robot', c.current, c.robot],
    ['the step being shown vs free', c.current, c.free],
  ];
  components.forEach((a, i) => {
    pairs.push([`roadmap component ${i} vs the path`, a, c.path]);
    for (let j = i + 1; j < components.length; ++j) pairs.push([`roadmap components ${i} vs ${j}`, a, components[j]]);
  });
  // For the record: the closest pairs and the faintest text.
  for (const p of pairs.map(([name, a, b]) => ({ name, ...worst(a, b) })).sort((x, y) => x.de - y.de).slice(0, 6))
    console.log(`# ${p.name}: ΔE00 ${p.de.toFixed(1)} (${p.kind})`);
  for (const t of text.map((x) => ({ ...x, ratio: contrast(x.fg, x.bg) })).sort((x, y) => x.ratio - y.ratio).slice(0, 6))
    console.log(`# ${t.name}: ${t.ratio.toFixed(2)}:1`);
  assert.deepEqual(tooClose(pairs), [], `${look}: pairs closer than ΔE00 ${MIN_DE}`);

  const faint = [['start', c.start], ['goal', c.goal], ['free', c.free], ['in collision', c.hit], ['robot', c.robot],
                 ['an obstacle', obstacle],
                 ...components.map((x, i) => [`roadmap component ${i}`, x])]
    .map(([name, x]) => [name, contrast(onCanvas(x), canvas)]).filter(([, r]) => r < MIN_GRAPHIC)
    .map(([name, r]) => `${name} on the canvas: ${r.toFixed(2)}:1`);
  assert.deepEqual(faint, [], `${look}: marks under ${MIN_GRAPHIC}:1 on the canvas`);
  // The path stands out from the canvas and from an obstacle under it: by its own colour or by
  // its outline (orange on white is 2.1:1, so the light look's dark outline does that there).
  const standsOut = (bg) => Math.max(contrast(onCanvas(c.path), bg), contrast(over(c.path_outline, bg), bg));
  for (const [name, bg] of [['the canvas', canvas], ['an obstacle', obstacle]])
    assert.ok(standsOut(bg) >= MIN_GRAPHIC, `${look}: the path or its outline at ${MIN_GRAPHIC}:1 on ${name}: ${standsOut(bg).toFixed(2)}`);

  assert.ok(text.length >= 15, 'the text colours are listed');
  const unreadable = text.map((t) => ({ ...t, ratio: contrast(t.fg, t.bg) })).filter((t) => t.ratio < MIN_TEXT)
    .map((t) => `${t.name}: rgb(${t.fg.slice(0, 3)}) on rgb(${t.bg.slice(0, 3)}) is ${t.ratio.toFixed(2)}:1`);
  assert.deepEqual(unreadable, [], `${look}: text under ${MIN_TEXT}:1`);
}

test('on the screen: the start, goal and path pixels as drawn stay apart for every dichromacy',
  () => withPage({ open: '?lesson=step-prm&scene=wall-gap&samples=120&neighbors=k:8&seed=7' }, async ({ page, browser }) => {
  await api(page, 'run');
  await keys(page, 'Escape');
  const run = await api(page, 'state', { roadmap: true });
  const scene = await api(page, 'get_scene');
  assert.equal(run.solved, true, 'a path to look at');
  // The middle of the path's longest edge away from the markers, and the markers left of their letter.
  const edges = run.path.slice(1).map((b, i) => [run.path[i], b])
    .filter(([a, b]) => [scene.start, scene.goal].every((m) => Math.hypot((a[0] + b[0]) / 2 - m[0], (a[1] + b[1]) / 2 - m[1]) > 0.05))
    .sort(([a, b], [c, d]) => Math.hypot(d[0] - c[0], d[1] - c[1]) - Math.hypot(b[0] - a[0], b[1] - a[1]));
  assert.ok(edges.length > 0);
  const [a, b] = edges[0];
  const probes = [
    { at: scene.start, look: 'start', dx: -6, why: 'the start marker' },
    { at: scene.goal, look: 'goal', dx: -6, why: 'the goal marker' },
    { at: [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2], look: () => true, why: 'the path' },
    { at: [scene.workspace.min[0] + 0.01, scene.workspace.min[1] + 0.01], dx: 6, dy: -6, look: 'canvas', why: 'the canvas' },
  ];
  const shot = await expectView(page, browser, 'colour-path.png', probes);
  const scale = await page.evaluate(() => window.devicePixelRatio);
  const box = await page.evaluate(() => window.cspacelab.module.canvas.getBoundingClientRect().toJSON());
  const { points } = await api(page, 'view', { points: probes.map((p) => p.at) });
  const { at } = await inspectPng(browser, shot.png,
    points.map(([x, y], i) => [(box.x + x + (probes[i].dx || 0)) * scale, (box.y + y + (probes[i].dy || 0)) * scale]));
  const [start, goal, path, canvas] = at;
  const { colours } = await api(page, 'theme');
  assert.ok(distance(path, colours.path) < 5, `the path is drawn in its colour: rgb(${path}) vs rgb(${colours.path})`);
  assert.deepEqual(tooClose([['start vs goal', start, goal], ['path vs start', path, start], ['path vs goal', path, goal],
                             ['path vs canvas', path, canvas]]), [], 'pixels of the screenshot closer than ΔE00 10');
  for (const kind of DICHROMACIES)
    console.log(`# ${kind}: start/goal ΔE00 ${distance(start, goal, kind).toFixed(1)}, path/canvas ${distance(path, canvas, kind).toFixed(1)}`);
}));
