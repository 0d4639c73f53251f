// Lesson "C-space notation", practice mode: every exercise's picture shows the robot its text
// describes (a drone flies, a gantry crane runs on its frame, a vacuum is round on the floor, a
// pendulum hangs, a cart that never turns has no turning arrow), and nothing on screen names Q
// or any factor of it before the student checks an answer: not the picture's captions, not the
// surfaces' captions, not the panel. Answers typed with the keyboard and Enter are judged right
// and wrong, with the explanation shown.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, withBrowser, collectErrors, waitFrames, screenshot, inspectPng, api, chord, cli, expectGolden } from './lib/harness.mjs';

// Any notation at all: SE(n), SO(n), R^n, S^n, T^n (ASCII or superscripts), (S^1)^n, a lone R
// (the prismatic factor), a product sign between two things.
const TOKENS = [
  /S[EO]\s*\(\s*\d\s*\)/, /\bR\s*\^\s*\d/, /\bR[¹²³⁴⁵⁶⁷⁸⁹]/, /\bS\s*\^\s*\d/, /\bS[¹²]/, /\bT\s*\^\s*\d/,
  /\bT[¹²³⁴⁵⁶⁷⁸⁹]/, /\(\s*S\s*\^?\s*1\s*\)/, /(^|[^A-Za-z])R($|[^A-Za-z])/, /\S\s+[x×*]\s+\S/, /Q\s*=/,
];
const escape = (s) => s.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');

// What a text gives away: the answer, one of its factors or spellings, or any notation token.
function giveaway(text, forbidden) {
  for (const f of forbidden)
    if (new RegExp(`(^|[^A-Za-z0-9^])${escape(f)}($|[^A-Za-z0-9^])`).test(text)) return `"${f}"`;
  for (const t of TOKENS) if (t.test(text)) return String(t);
  return null;
}

// The picture an exercise's words call for, and what that picture must (not) have.
function expectedPicture(text) {
  if (/drone/i.test(text)) return 'drone';
  if (/gantry/i.test(text)) return 'gantry';
  if (/vacuum/i.test(text)) return 'vacuum';
  if (/pendulum/i.test(text)) return 'pendulum';
  if (/cart/i.test(text)) return 'cart';
  if (/base that slides and turns/i.test(text)) return 'mobile-arm';
  assert.match(text, /arm/i, `an exercise of a kind this test knows: ${text}`);
  return 'arm';
}
function checkParts(kind, parts, captions) {
  const has = (p) => parts.includes(p);
  const count = (p) => parts.filter((x) => x === p).length;
  switch (kind) {
    case 'drone':  // flying: rotors, no wheels, nothing under it
      assert.equal(count('rotor'), 4, 'four rotors');
      assert.ok(has('body') && has('turn arrow') && has('arrows x y z'));
      assert.ok(!has('wheel') && !has('floor') && !has('fixed base'), `a drone flies: ${parts}`);
      for (const axis of ['x', 'y', 'z']) assert.ok(captions.includes(axis), `arrow ${axis}`);
      break;
    case 'gantry':
      for (const p of ['posts', 'rails', 'bridge', 'trolley', 'hoist', 'cable', 'arrows x y z']) assert.ok(has(p), `a gantry has ${p}`);
      for (const axis of ['x', 'y', 'z']) assert.ok(captions.includes(axis), `arrow ${axis}`);
      assert.ok(!has('wheel') && !has('turn arrow'));
      break;
    case 'vacuum':
      assert.ok(has('round body') && has('floor') && has('slide arrows') && has('turn arrow'), `${parts}`);
      break;
    case 'pendulum':
      assert.ok(has('ceiling') && has('hanging bob') && has('swing arrow'), `${parts}`);
      break;
    case 'cart':  // slides without turning
      assert.equal(count('wheel'), 2);
      assert.ok(has('slide arrows') && !has('turn arrow'), `no turning arrow on a cart that never turns: ${parts}`);
      break;
    case 'mobile-arm':
      assert.ok(count('wheel') === 2 && has('slide arrows') && has('turn arrow'), `${parts}`);
      break;
    case 'arm':
      assert.ok(has('fixed base') && !has('wheel') && !has('turn arrow'), `${parts}`);
      break;
  }
}

async function practice(page, exercise) {
  await api(page, 'set_params', { params: { mode: 'practice', exercise } });
  await waitFrames(page, 3);
  return api(page, 'state');
}

// The build mode's Q for a description: the answer and every way of writing its parts.
async function answerOf(page, description) {
  await api(page, 'set_params', { params: { mode: 'build', description } });
  await waitFrames(page, 2);
  const b = await api(page, 'state');
  assert.equal(b.mode, 'build');
  assert.equal(b.notation, cli('cspace-of', description).notation, 'the lesson agrees with the CLI');
  return { notation: b.notation, forbidden: [b.notation, ...b.factors.map((f) => f.factor), ...b.equivalent], build: b };
}

// Types into the field that has the keyboard and presses Enter.
async function answer(page, text) {
  await chord(page, 'Control', 'a');  // replaces whatever the field holds
  await page.keyboard.type(text, { delay: 20 });
  await page.keyboard.press('Enter');
  await waitFrames(page, 3);
  return api(page, 'state');
}

test('notation practice: pictures match the robots, nothing gives the answer away, the keyboard answers',
  () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'notation' });
  await waitFrames(page, 2);
  let s = await practice(page, 0);
  const count = 9;
  assert.equal(s.mode, 'practice');
  const kinds = new Set();
  for (let i = 0; i < count; ++i) {
    s = await practice(page, i);
    assert.equal(s.exercise, i);
    assert.equal(s.check, undefined, 'nothing checked yet');
    const { description } = s;
    const { notation, forbidden, build } = await answerOf(page, description);
    // The build mode names Q: the detector must see it there (else it could never fail).
    assert.ok(giveaway(build.picture.captions.join('\n'), forbidden), `build mode shows ${notation}`);
    s = await practice(page, i);
    assert.equal(s.description, description);
    assert.equal(s.answer, '', 'a new exercise starts with an empty field');

    // Before checking: no text on screen gives the answer away.
    const texts = [...s.picture.captions, ...s.surface_captions, ...s.panel_texts];
    assert.ok(s.panel_texts.includes(s.exercise_text), 'the exercise is in the panel');
    assert.ok(s.picture.captions.length > 0 && s.surface_captions.length === 2 && s.panel_texts.length >= 6);
    for (const t of texts) assert.equal(giveaway(t, forbidden), null, `exercise ${i + 1} (${notation}) shows "${t}"`);

    // The picture is the robot of the words, with the joints of its description.
    const kind = expectedPicture(s.exercise_text);
    assert.equal(s.picture.kind, kind, `exercise ${i + 1}: ${s.exercise_text}`);
    kinds.add(kind);
    checkParts(kind, s.picture.parts, s.picture.captions);
    const joints = (description.match(/joints=([RP]+)/) || ['', ''])[1] + (/wrist=spherical/.test(description) ? 'WWW' : '');
    assert.equal(s.picture.joints, joints, `the joints drawn, base to tip (${description})`);
    // Two of the pictures against references looked at when they were made (the drone: rotors,
    // no wheels; the gantry: posts, rails, bridge, trolley, hoist): a part moved or lost fails.
    if (kind === 'drone' || kind === 'gantry') await expectGolden(page, browser, `notation-practice-${kind}`, 'notation-picture');

    // The keyboard: a wrong answer, then the right one, each explained in the panel.
    s = await answer(page, 'S^2');
    assert.equal(s.answer, 'S^2');
    assert.equal(s.check.correct, false, `S^2 is wrong for ${notation}`);
    assert.doesNotMatch(s.check.explanation, /^correct/);
    assert.ok(s.panel_texts.includes(s.check.explanation), 'the explanation is shown');
    s = await answer(page, notation);
    assert.equal(s.answer, notation);
    assert.equal(s.check.correct, true, `${notation} is right`);
    assert.ok(s.check.explanation.startsWith(`correct: ${notation}`), s.check.explanation);
    assert.ok(s.panel_texts.includes(s.check.explanation));
  }
  assert.deepEqual([...kinds].sort(), ['arm', 'cart', 'drone', 'gantry', 'mobile-arm', 'pendulum', 'vacuum']);
}));

// A 900 px wide embed: the drone and the gantry fit their half of the view.
test('notation practice in a 900 px embed', () => withBrowser(async ({ browser, url }) => {
  const page = await browser.newPage({ viewport: { width: 1000, height: 760 } });
  const errors = collectErrors(page);
  await page.route(url + 'host.html', (route) => route.fulfill({ contentType: 'text/html', body:
    '<!doctype html><meta charset="utf-8"><body style="margin:0"><iframe src="embed.html?lesson=notation" ' +
    'style="border:0;width:900px;height:640px;display:block" title="lab"></iframe></body>' }));
  await page.goto(url + 'host.html');
  const frame = await (await page.waitForSelector('iframe')).contentFrame();
  await frame.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2, null, { timeout: 30000 });
  for (const [exercise, kind] of [[7, 'drone'], [4, 'gantry']]) {
    await frame.evaluate((e) => window.cspacelab.call('set_params', { params: { mode: 'practice', exercise: e } }), exercise);
    await waitFrames(frame, 3);
    const s = await frame.evaluate(() => window.cspacelab.call('state', {}));
    assert.equal(s.picture.kind, kind);
    await screenshot(page, `notation-embed-900-${kind}.png`);
  }
  assert.deepEqual(errors, []);
}));
