// An instructor's lock=, hide= and reveal= (core/teaching/restrictions.hpp; docs/web.md):
// a locked scene refuses the mouse, the keyboard, the API and Import, with the notice on
// screen; locked parameters are fixed in the app, its API and the page's controls; a hidden
// answer is absent from the pixels (its line's pixels do not change with it), from state(),
// describe, the log and the exported state, until reveal=after-answer lets it back; Share keeps
// the restrictions; and `cspacelab link` opened in Chromium gives back the file's scene bit for
// bit, in a link as short as the page's own Share. Numbers are computed here independently.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, withPage, collectErrors, openLab, keys, chord, drag, hold, waitFrames, api,
         screenshot, inspectPng, cli, tempJson, worldToPage, refusal } from './lib/harness.mjs';

const FIXED = /fixed by your instructor/;

// The smallest N whose points t = i/(N-1) on p-q land in the closed disk (P12, both ends counted).
function minGrid(p, q, center, radius) {
  for (let n = 2; n < 100000; ++n)
    for (let i = 0; i < n; ++i) {
      const t = i / (n - 1);
      if (Math.hypot(p[0] + t * (q[0] - p[0]) - center[0], p[1] + t * (q[1] - p[1]) - center[1]) <= radius) return n;
    }
  return null;
}

// The value at a JSON pointer with "*" (every element), as core's strip_answer_fields walks it:
// [found?] for each place.
function at(value, pointer) {
  let nodes = [value];
  for (const key of pointer.split('/').slice(1)) {
    const next = [];
    for (const n of nodes) {
      if (key === '*') { if (Array.isArray(n)) next.push(...n); }
      else if (n && typeof n === 'object' && !Array.isArray(n) && key in n) next.push(n[key]);
    }
    nodes = next;
  }
  return nodes;
}

// A device-pixel crop of one of the app's controls (page_state's rect) out of a screenshot.
async function controlPixels(page, browser, name) {
  const { rect, left, top, ratio } = await page.evaluate((n) => {
    const box = window.cspacelab.module.canvas.getBoundingClientRect();
    return { rect: window.cspacelab.pageState().buttons[n], left: box.left, top: box.top, ratio: devicePixelRatio };
  }, name);
  assert.ok(rect, `the control ${name} is on screen`);
  const shot = await page.screenshot();
  const probes = [];
  for (let y = Math.floor((top + rect[1]) * ratio); y < Math.ceil((top + rect[3]) * ratio); ++y)
    for (let x = Math.floor((left + rect[0]) * ratio); x < Math.ceil((left + rect[2]) * ratio); ++x) probes.push([x, y]);
  return (await inspectPng(browser, shot, probes)).at.map((c) => c.join(',')).join(';');
}

async function notice(page) {
  return (await api(page, 'status')).notice;
}

// A notice of our own, so that the next one is known to be new.
async function clearNotice(page) {
  await api(page, 'notify', { text: 'ready', seconds: 30 });
  await waitFrames(page, 1);
}

const DISK_SCENE = (radius) => ({
  version: 1, name: 'P12 variant', workspace: { min: [-0.1, -0.5], max: [1.1, 0.5] }, robot: { type: 'point' },
  obstacles: [{ type: 'disk', center: [0.2, 0.05], radius }], start: [0, 0], goal: [1, 0],
});

test('a locked scene refuses the mouse, the keys, the API and Import; locked parameters are fixed everywhere',
  () => withPage({ open: '?lesson=collision&scene=p12&grid_n=4&lock=scene,params&hide=min_n' }, async ({ page, browser }) => {
  const r = (await api(page, 'status')).restrictions;
  assert.equal(r.lock, 'scene,params');
  assert.equal(r.hide, 'min_n');
  assert.deepEqual(r.hidden_now, ['min_n']);
  const scene = await api(page, 'get_scene');
  const params = (await api(page, 'snapshot')).params;
  assert.equal(params.grid_n, 4);

  // The mouse: a drag on the disk moves nothing and says why, on screen.
  await clearNotice(page);
  const before = await screenshot(page, 'lock-before-drag.png');
  const [centre, away] = await worldToPage(page, [[0.2, 0.05], [0.5, 0.3]]);
  let after = null;
  // (Looked at in the drag: the notice lasts 4 s, a slow software-rendered drag nearly as long.)
  await hold(page, centre, away, { each: async (i) => {
    if (i !== 2) return;
    assert.match(await notice(page), /The scene is fixed by your instructor \(lock=scene\)/);
    after = await screenshot(page, 'lock-drag-refused.png');
  } });
  await page.mouse.up();
  await waitFrames(page, 2);
  assert.deepEqual(await api(page, 'get_scene'), scene, 'the drag changed nothing');
  // The notice sits at the bottom, in the middle: those pixels changed (the words are drawn).
  const box = await page.locator('canvas').boundingBox();
  const strip = [];
  for (let x = box.x + box.width * 0.3; x < box.x + box.width * 0.7; x += 3) strip.push([x, box.y + box.height - 40]);
  const a = await inspectPng(browser, before.png, strip), b = await inspectPng(browser, after.png, strip);
  assert.notDeepEqual(a.at, b.at, 'the refusal is drawn over the lab');

  // The keyboard: N focuses the start, then the goal, then the disk; the arrows, + and Delete are refused.
  for (const [key, chordKey] of [['ArrowRight'], ['+'], ['Delete'], [null, 'z']]) {
    await clearNotice(page);
    if (chordKey) await chord(page, 'Control', chordKey);
    else {
      await keys(page, 'n', 'n', 'n');
      await keys(page, key);
    }
    assert.deepEqual(await api(page, 'get_scene'), scene, `${key || 'Ctrl+' + chordKey} changed nothing`);
    assert.match(await notice(page), FIXED, `${key || 'Ctrl+' + chordKey} says why`);
  }
  // A drawing tool (D, then a drag) draws nothing.
  await keys(page, 'd');
  await drag(page, away, { x: away.x + 40, y: away.y });
  assert.deepEqual(await api(page, 'get_scene'), scene, 'no disk drawn');
  // The context menu (right-click on the disk) is refused the same way.
  await clearNotice(page);
  await page.mouse.move(centre.x, centre.y);
  await waitFrames(page, 2);
  await page.mouse.down({ button: 'right' });
  await waitFrames(page, 2);
  await page.mouse.up({ button: 'right' });
  await waitFrames(page, 2);
  assert.match(await notice(page), FIXED, 'the context menu says why');
  assert.deepEqual(await api(page, 'get_scene'), scene);

  // The API, and Import (a file dropped or picked): refused with the reason.
  assert.match(await refusal(page, 'setScene', DISK_SCENE(0.06)), FIXED);
  assert.match(await refusal(page, 'undo'), FIXED);
  assert.match(await refusal(page, 'setParams', { grid_n: 9 }), /grid_n is fixed by your instructor \(lock=params\)/);
  assert.match(await refusal(page, 'setParams', { p: [0.1, 0.1] }), FIXED);
  assert.equal(await page.evaluate((t) => window.cspacelab.shell.importFile(new File([t], 'mine.json')),
                                   JSON.stringify(DISK_SCENE(0.06))), false);
  assert.match(await notice(page), /mine\.json" was not imported: the scene is fixed by your instructor/);
  assert.deepEqual(await api(page, 'get_scene'), scene);

  // The page's controls: the parameters disabled, said fixed; the app's state unchanged.
  const dom = await page.evaluate(() => [...document.querySelectorAll('.lab-access-params .lab-access-param')].map((row) => ({
    name: row.querySelector('input, select').name, disabled: row.querySelector('input, select').disabled,
    fixed: row.querySelector('.lab-access-fixed').textContent,
  })));
  assert.deepEqual(dom.map((d) => d.name).sort(), ['grid_n', 'p', 'q']);
  for (const d of dom) {
    assert.equal(d.disabled, true, `${d.name} is disabled in the page`);
    assert.equal(d.fixed, 'fixed by your instructor');
  }
  assert.ok((await api(page, 'param_specs')).every((s) => s.locked === true));
  // The panel says what is fixed and hidden.
  await screenshot(page, 'lock-panel.png');

  // Steps still work; File > Reset brings back the instructor's scene and parameters (not the lesson's defaults).
  await api(page, 'run');
  assert.ok((await api(page, 'state')).shown > 0);
  await page.evaluate(() => window.cspacelab.shell.resetLesson());
  assert.deepEqual(await api(page, 'get_scene'), scene);
  assert.deepEqual((await api(page, 'snapshot')).params, params);
  assert.equal((await api(page, 'state')).shown, 0);

  // Share keeps the lock and the hiding: a student passing the link on passes them on.
  const { url: link } = await page.evaluate(() => window.cspacelab.shell.shareLink());
  const q = new URL(link).searchParams;
  assert.equal(q.get('lock'), 'scene,params');
  assert.equal(q.get('hide'), 'min_n');
  const embed = await page.evaluate(() => window.cspacelab.shell.embed());
  assert.match(embed[0].value, /lock=scene,params&amp;hide=min_n/);
  await page.evaluate(() => window.cspacelab.shell.closeDialog());

  // A reload keeps them (they come from the address every time).
  await page.reload();
  await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2);
  assert.equal((await api(page, 'status')).restrictions.lock, 'scene,params');
  assert.match(await refusal(page, 'setScene', DISK_SCENE(0.06)), FIXED);
}));

test('a hidden answer is absent from the pixels, state(), describe, the log and the exported state',
  () => withPage({ open: '?lesson=collision&scene=p12&grid_n=4&hide=min_n' }, async ({ page, browser }) => {
  const p = [0, 0], q = [1, 0];
  // Two scenes whose smallest N differ (computed here): with the answer hidden, the pixels
  // where it is written do not change between them; shown, they do.
  const radii = [0.1, 0.06];
  const expected = radii.map((r) => minGrid(p, q, [0.2, 0.05], r));
  assert.notEqual(expected[0], expected[1]);
  const looks = { hidden: [], shown: [] };
  for (const mode of ['hidden', 'shown']) {
    await api(page, 'restrict', { hide: mode === 'hidden' ? 'min_n' : '' });
    for (const [i, radius] of radii.entries()) {
      await api(page, 'set_scene', { scene: DISK_SCENE(radius) });
      await waitFrames(page, 3);
      const state = await api(page, 'state');
      const text = await api(page, 'describe');
      const log = (await api(page, 'log')).map((l) => l.text).join('\n');
      if (mode === 'shown') {
        assert.equal(state.min_grid, expected[i], 'the lab\'s N is the one computed here');
      } else {
        for (const field of ['min_grid', 'min_grid_interior', 'min_grid_one_end'])
          assert.ok(!(field in state), `${field} is not in state()`);
        assert.doesNotMatch(text + log, /smallest|least N/);
        // The page's parallel DOM (describe and the log's newest line) holds nothing more.
        const access = await page.evaluate(() => document.querySelector('.lab-access').textContent);
        assert.doesNotMatch(access, /smallest|least N/);
        // The state a student exports (File > Export roadmap / path).
        const exported = await page.evaluate(() => {
          const shell = window.cspacelab.shell;
          let file = null;
          const keep = shell.downloadJson;
          shell.downloadJson = (name, value) => { file = value; };
          try { shell.exportState(); } finally { shell.downloadJson = keep; }
          return file;
        });
        assert.equal(exported.format, 'cspacelab-state');
        assert.ok(!('min_grid' in exported.state) && !('min_grid_interior' in exported.state));
      }
      looks[mode].push(await controlPixels(page, browser, 'min-n'));
      await screenshot(page, `hide-min-n-${mode}-${i}.png`);
    }
  }
  assert.equal(looks.hidden[0], looks.hidden[1], 'hidden: the line looks the same whatever N is');
  assert.notEqual(looks.shown[0], looks.shown[1], 'shown: the line changes with N (so the comparison can fail)');
}));

test('every lesson: hide=answers takes its listed fields out of state() and its numbers out of describe and the log',
  () => withPage(async ({ page }) => {
  const catalogue = cli('link', '--list');  // the core's lists, as the CLI checks links with them
  const lessons = await api(page, 'lessons');
  // The core's list (what cspacelab link checks) is the app's: ids, names, parameters.
  assert.deepEqual(catalogue.lessons.map((l) => [l.id, l.name]), lessons.map((l) => [l.id, l.name]));
  const bundled = await api(page, 'bundled_scenes');
  for (const l of catalogue.lessons) {
    await api(page, 'select_lesson', { id: l.id });
    const specs = (await api(page, 'param_specs')).map((s) => s.name).sort();
    assert.deepEqual(specs, [...l.params].sort(), `${l.id}: the core lists its parameters`);
    // The robots it takes: a bundled scene of each type is taken or refused as listed.
    for (const [name, s] of Object.entries(bundled)) {
      const type = s.robot.type === 'arm' && s.robot.lengths.length === 2 ? 'arm2' : s.robot.type;
      const took = (await refusal(page, 'setScene', s)) === null;
      assert.equal(took, l.robots.includes(type), `${l.id} and ${name} (${type})`);
    }
    await api(page, 'restore', { lesson: l.id });
  }

  // A state where every answer has a value: run what can be run.
  const setups = {
    'step-prm': async () => { await api(page, 'set_scene', { scene: bundled['wall-gap'] }); await api(page, 'run'); },
    torus: async () => api(page, 'run'),
    'cspace-3d': async () => { await api(page, 'set_params', { params: { samples: 1000, neighbors: 'k:10', seed: 2 } }); await api(page, 'run'); },
    compare: async () => api(page, 'run'),
    distances: async () => {},
    analysis: async () => {},
  };
  for (const l of catalogue.lessons) {
    await api(page, 'select_lesson', { id: l.id });
    if (setups[l.id]) await setups[l.id]();
    await api(page, 'restrict', {});
    const shown = await api(page, 'state');
    const shownText = await api(page, 'describe');
    const answers = catalogue.answers.filter((a) => a.lesson === l.id);
    assert.ok(answers.length > 0, `${l.id} has answers to hide`);
    for (const a of answers)
      for (const f of a.fields) assert.ok(at(shown, f).length > 0, `${l.id}: ${f} is in the state to hide`);
    await api(page, 'restrict', { hide: 'answers', lesson: l.id });
    assert.deepEqual((await api(page, 'status')).restrictions.hidden_now, answers.map((a) => a.name));
    const hidden = await api(page, 'state');
    for (const a of answers)
      for (const f of a.fields) assert.equal(at(hidden, f).length, 0, `${l.id}: ${f} is hidden`);
    const text = await api(page, 'describe');
    const log = (await api(page, 'log')).map((x) => x.text).join('\n');
    // The numbers a description would read out (4 significant digits).
    const four = (v) => String(Number(v.toPrecision(4)));
    if (l.id === 'compare') {
      for (const p of shown.planners) assert.ok(p.path_length > 0, `compare: ${p.planner} found a path`);
      assert.match(shownText, /length \d/);
      assert.doesNotMatch(text, /length/, 'compare: describe');
      assert.doesNotMatch(log, /length \d/, 'compare: the log');
    }
    if (l.id === 'step-prm' || l.id === 'torus' || l.id === 'cspace-3d') {
      const length = l.id === 'step-prm' ? shown.path_length : shown.prm.path_length;
      assert.ok(length > 0, `${l.id}: a path was found`);
      assert.match(shownText, new RegExp(`length ${four(length).replace('.', '\\.')}`));
      assert.doesNotMatch(text, /length/, `${l.id}: describe`);
      if (l.id === 'step-prm') {
        assert.match(log, /a path of \d+ edges/);
        assert.doesNotMatch(log, /length \d/, 'the log line keeps the edges, not the length');
        assert.match(log, /length hidden/, 'and says the length is hidden');
      }
    }
    if (l.id === 'distances') {
      assert.ok(shownText.includes(four(shown.s1.distance)));
      assert.ok(!text.includes(four(shown.s1.distance)) && /hidden by your instructor/.test(text));
    }
    if (l.id === 'notation') {
      assert.ok(shownText.includes(shown.notation));
      assert.ok(!text.includes(shown.notation));
    }
    await api(page, 'restrict', {});
  }
}));

test('reveal=after-answer: the answer comes back once its exercise was answered right',
  () => withPage({ open: '?problem=P12&seed=11&hide=answers&reveal=after-answer' }, async ({ page }) => {
  const hw = await api(page, 'homework_state');
  assert.equal(hw.problem, 'P12');
  assert.equal((await api(page, 'status')).lesson, 'collision');
  assert.equal((await api(page, 'status')).notice, '', 'a problem link takes lock, hide and reveal without a complaint');
  assert.ok(!('min_grid' in (await api(page, 'state'))));
  const { center, radius } = hw.exercise.given;
  const n = minGrid([0, 0], [1, 0], center, radius);
  assert.equal(await page.evaluate(() => window.cspacelab.checkAnswer('2').correct), false);
  assert.ok(!('min_grid' in (await api(page, 'state'))), 'a wrong answer reveals nothing');
  // The card's Show the solution: typing the answer back is no answer of the student's.
  assert.equal((await api(page, 'show_solution')).expected, n);
  assert.equal(await page.evaluate((a) => window.cspacelab.checkAnswer(a).correct, String(n)), true);
  assert.ok(!('min_grid' in (await api(page, 'state'))), 'right only after the solution was shown: still hidden');
  // A new exercise (another seed): a wrong try shows no answer, so right after it reveals.
  const fresh = await api(page, 'exercise', { id: 'P12', seed: 12 });
  const m = minGrid([0, 0], [1, 0], fresh.given.center, fresh.given.radius);
  assert.equal(await page.evaluate((a) => window.cspacelab.checkAnswer(a).correct, String(m + 7)), false);
  assert.ok(!('min_grid' in (await api(page, 'state'))));
  assert.equal(await page.evaluate((a) => window.cspacelab.checkAnswer(a).correct, String(m)), true);
  const state = await api(page, 'state');
  assert.equal(typeof state.min_grid, 'number', 'answered right: min N is back');
  assert.deepEqual((await api(page, 'status')).restrictions.hidden_now, []);
  // Only P12's answer: the Distances lesson's stay hidden.
  await api(page, 'select_lesson', { id: 'distances' });
  assert.ok(!('distance' in (await api(page, 'state')).s1));
}));

test('lock=lesson keeps the lab on its lesson; bad words are named and the rest applies',
  () => withPage({ open: '?lesson=distances&lock=lesson,q9,tool&hide=s1_distance,min_n' }, async ({ page }) => {
  await page.waitForFunction(() => window.cspacelab.status().notice !== '');
  const text = await notice(page);
  assert.match(text, /Not used from the link: lock: "q9" is not scene, params, lesson or a parameter of distances \(tool, q1, q2, p1, p2, q, r\)/);
  assert.match(text, /hide: "min_n" is not answers, none or an answer of distances \(s1_distance, segment_distance\)/);
  const r = (await api(page, 'status')).restrictions;
  assert.equal(r.lock, 'lesson,tool');
  assert.equal(r.hide, 's1_distance');
  assert.equal(r.locked_lesson, 'distances');
  assert.match(await refusal(page, 'selectLesson', 'collision'), /The lesson is fixed by your instructor \(lock=lesson\)/);
  assert.match(await refusal(page, 'setParams', { tool: 'segment' }), /tool is fixed by your instructor \(lock=tool\)/);
  assert.equal(await refusal(page, 'setParams', { q1: 1 }), null, 'q1 is not locked');
  assert.match(await refusal(page, 'openProblem', 'P12'), /lock=lesson/);
  // The page's lesson buttons: every other lesson disabled.
  await page.waitForFunction(() => document.querySelector('.lab-access-lessons button[data-lesson="collision"]').disabled);
  const buttons = await page.evaluate(() => [...document.querySelectorAll('.lab-access-lessons button')]
    .map((b) => [b.dataset.lesson, b.disabled]));
  assert.equal(buttons.length, (await api(page, 'lessons')).length, 'a button for every lesson');
  for (const [id, disabled] of buttons) assert.equal(disabled, id !== 'distances', id);
  assert.equal((await api(page, 'status')).lesson, 'distances');
}));

test('cspacelab link, opened in Chromium, gives back the file\'s scene bit for bit, as short as Share',
  () => withBrowser(async ({ browser, url }) => {
  const scene = {
    version: 1, name: 'Week 6 — the gap',
    workspace: { min: [0, 0], max: [1, 1] }, robot: { type: 'point' },
    obstacles: [{ type: 'disk', center: [0.1 + 0.2, 1 / 3], radius: Math.PI / 30 },
                { type: 'polygon', vertices: [[0.55, 0.1], [0.8, 0.15000000000000002], [0.7, 0.4]] },
                { type: 'segment', a: [0.45, 0.3], b: [0.45, 0.9] },
                { type: 'disk', center: [0.85, 0.75], radius: 0.0625 }],
    start: [0.05, 0.1], goal: [0.93, 0.91],
  };
  const file = tempJson(scene);
  const normal = cli('validate', file).scene;
  const out = cli('link', file, '--lesson', 'step-prm', '--params', '{"samples": 150, "seed": 12, "neighbors": "k:7"}',
                  '--lock', 'scene', '--hide', 'path_length', '--task', 'Find the gap, then explain it.', '--base', url);
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  await page.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
  const errors = collectErrors(page);
  await openLab(page, out.url);
  assert.equal(await notice(page), '', 'nothing in the link was refused');
  assert.equal(await page.evaluate(() => document.querySelector('.lab-task').textContent.includes('Find the gap, then explain it.')), true,
               'the task is shown with the lab');
  const got = await api(page, 'get_scene');
  assert.deepEqual(got, normal);
  assert.equal(JSON.stringify(got), JSON.stringify(normal), 'every number to the last bit');
  assert.equal(got.obstacles[0].radius, Math.PI / 30);
  const params = (await api(page, 'snapshot')).params;
  assert.deepEqual([params.samples, params.seed, params.neighbors], [150, 12, 'k:7']);
  assert.equal((await api(page, 'status')).restrictions.lock, 'scene');
  assert.deepEqual((await api(page, 'status')).restrictions.hidden_now, ['path_length']);
  // As short as the page's own Share of the same scene (the same deflate, zlib level 6).
  const share = new URL((await page.evaluate(() => window.cspacelab.shell.shareLink())).url).searchParams.get('scene');
  const mine = new URL(out.url).searchParams.get('scene');
  assert.match(share, /^z\./);
  // (Chromium's zlib is a fork of zlib with its own match finder: a byte or two either way.)
  assert.ok(mine.length <= share.length * 1.02 + 4, `cspacelab link ${mine.length} characters, Share ${share.length}`);
  console.log(`scene in the link: cspacelab link ${mine.length} characters, Share ${share.length}`);

  // The iframe, in a course page: the same lab, the same scene.
  const host = url + 'link-host.html';
  await page.route(host, (route) => route.fulfill({
    contentType: 'text/html',
    body: `<!doctype html><html><head><meta charset="utf-8"><title>course</title></head><body>${out.iframe}</body></html>`,
  }));
  await page.goto(host);
  const frame = await (await page.waitForSelector('iframe')).contentFrame();
  await frame.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2, null, { timeout: 30000 });
  assert.equal(JSON.stringify(await frame.evaluate(() => window.cspacelab.call('get_scene'))), JSON.stringify(normal));
  assert.equal(await page.getAttribute('iframe', 'title'), 'C-Space Lab: Step PRM');
  assert.deepEqual(errors, []);
}));
