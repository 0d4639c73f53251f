// Lesson "C-spaces in 3-D", issue 25's rest: the checked questions answered by mouse and
// keyboard (each verdict against figures this test computes itself: the CLI's volume, the short
// way between the prompt's angles), the planners other than PRM drawn in the block (RRT-Connect's
// trees, through links, Share and lock), and the volume's zoom travelling in camera=.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  withPage, withBrowser, openLab, collectErrors, click, chord, waitFrames, screenshot, inspectPng, api, refusal,
  pageButton,
} from './lib/harness.mjs';
import { cliFreeFraction } from './lib/cspace-volume.mjs';

const TWO_PI = 2 * Math.PI;
const wrap = (a) => a - TWO_PI * Math.floor((a + Math.PI) / TWO_PI);
const close = (a, b, tol = 45) => Math.abs(a[0] - b[0]) + Math.abs(a[1] - b[1]) + Math.abs(a[2] - b[2]) <= tol;

// A page control's rectangle (page_state's buttons, canvas px) in page px, or null.
async function controlRect(page, name) {
  return page.evaluate((n) => {
    const r = window.cspacelab.pageState().buttons[n];
    const box = window.cspacelab.module.canvas.getBoundingClientRect();
    return r ? { x: box.left + r[0], y: box.top + r[1], w: r[2] - r[0], h: r[3] - r[1] } : null;
  }, name);
}

// Presses a panel control with the mouse, scrolling the panel with the wheel until it is in view.
async function press(page, name) {
  const height = page.viewportSize().height;
  for (let i = 0; i < 20; ++i) {
    const r = await controlRect(page, name);
    assert.ok(r, `the control ${name} is drawn`);
    if (r.y > 40 && r.y + r.h < height - 60) {
      await click(page, { x: r.x + Math.min(10, r.w / 2), y: r.y + r.h / 2 });
      await waitFrames(page, 3);
      return r;
    }
    await page.mouse.move(r.x + 5, height / 2);
    await page.mouse.wheel(0, r.y < 40 ? -100 : 100);
    await waitFrames(page, 3);
  }
  throw new Error(`could not scroll ${name} into view`);
}

// Types an answer into the lesson's field (a click puts the cursor there) and presses Enter.
async function typeAnswer(page, text) {
  await press(page, 'c3d-answer');
  await chord(page, 'Control', 'a');
  await page.keyboard.type(text, { delay: 15 });
  await page.keyboard.press('Enter');
  await waitFrames(page, 3);
  return (await api(page, 'state')).question;
}

// Pixels of `rgb` in the panel's strip under the Check button, where the verdict is written.
async function verdictPixels(page, browser, rgb) {
  await page.mouse.move(2, 2);
  await waitFrames(page, 2);
  const r = await controlRect(page, 'c3d-check');
  const png = await page.screenshot();
  const probes = [];
  for (let y = r.y + r.h + 2; y < r.y + r.h + 60; y += 1) for (let x = r.x; x < r.x + 300; x += 2) probes.push([x, y]);
  return (await inspectPng(browser, png, probes)).at.filter((c) => close(c, rgb, 30)).length;
}

test('questions: answered right and wrong by mouse and keyboard, each verdict shown',
  () => withPage({ viewport: { width: 1280, height: 800 } }, async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'cspace-3d' });
  await waitFrames(page, 3);
  await press(page, 'section:Questions');  // folded at first, so that the first state fits the panel
  await waitFrames(page, 2);
  const texts = (await api(page, 'theme')).text;
  const good = texts.find((t) => t.name === 'a found path, a passed check').fg.slice(0, 3);
  const bad = texts.find((t) => t.name === 'no path, a missed collision').fg.slice(0, 3);
  let s = await api(page, 'state');
  assert.equal(s.robot, 'polygon');
  assert.equal(s.question.id, 'name');
  assert.equal(s.question.check, null);

  // Q's name, typed: wrong (R^3 leaves out that theta wraps), then right in two spellings.
  let q = await typeAnswer(page, 'R^3');
  assert.equal(q.answer, 'R^3');
  assert.equal(q.check.correct, false);
  assert.ok((await verdictPixels(page, browser, bad)) > 20, 'the wrong verdict is written in the bad colour');
  assert.equal(await verdictPixels(page, browser, good), 0);
  await screenshot(page, 'cspace3d-question-wrong.png');
  q = await typeAnswer(page, 'R^2 x S^1');
  assert.equal(q.check.correct, true, q.check.explanation);
  assert.ok((await verdictPixels(page, browser, good)) > 20, 'the right verdict is written in the good colour');
  assert.equal(await verdictPixels(page, browser, bad), 0);

  // Next question (a click): the dimension.
  await press(page, 'c3d-next-question');
  q = (await api(page, 'state')).question;
  assert.equal(q.id, 'dimension');
  assert.equal(q.check, null, 'a new question starts unchecked');
  assert.equal((await typeAnswer(page, '2')).check.correct, false);
  assert.equal((await typeAnswer(page, String(s.q.length))).check.correct, true);

  // Glued faces, by the radio buttons and Check: only theta is an angle (SE(2)).
  await press(page, 'c3d-next-question');
  q = (await api(page, 'state')).question;
  assert.equal(q.id, 'glued');
  assert.deepEqual(q.choices.map((c) => c.key), ['none', 'top-bottom', 'sides', 'all']);
  await press(page, 'c3d-choice:all');
  await press(page, 'c3d-check');
  q = (await api(page, 'state')).question;
  assert.equal(q.answer, 'all');
  assert.equal(q.check.correct, false);
  assert.ok((await verdictPixels(page, browser, bad)) > 20);
  await press(page, 'c3d-choice:top-bottom');
  assert.equal((await api(page, 'state')).question.check, null, 'a new choice clears the verdict');
  await press(page, 'c3d-check');
  assert.equal((await api(page, 'state')).question.check.correct, true);

  // The seam: the prompt's angles, and the short way worked out here.
  await press(page, 'c3d-next-question');
  q = (await api(page, 'state')).question;
  assert.equal(q.id, 'seam');
  const configs = [...q.prompt.matchAll(/[ABC] = \(([^)]*)\)/g)].map((m) => m[1].split(',').map(Number));
  assert.equal(configs.length, 3, q.prompt);
  const crosses = (p, r) => {
    const end = wrap(p[2]) + wrap(r[2] - p[2]);
    return end > Math.PI || end < -Math.PI;
  };
  const b = crosses(configs[0], configs[1]), c = crosses(configs[0], configs[2]);
  const want = b && c ? 'both' : b ? 'B' : c ? 'C' : 'neither';
  const wrong = want === 'C' ? 'B' : 'C';
  await press(page, `c3d-choice:${wrong}`);
  await press(page, 'c3d-check');
  assert.equal((await api(page, 'state')).question.check.correct, false);
  await press(page, `c3d-choice:${want}`);
  await press(page, 'c3d-check');
  assert.equal((await api(page, 'state')).question.check.correct, true, `the short way crosses to ${want}`);

  // The free share, against the CLI's volume of the same scene at the same cells.
  await press(page, 'c3d-next-question');
  s = await api(page, 'state');
  assert.equal(s.question.id, 'free');
  const free = 100 * cliFreeFraction(await api(page, 'get_scene'), s.free_fraction_cells);
  assert.equal((await typeAnswer(page, (free + 2).toFixed(1))).check.correct, false);
  assert.equal((await typeAnswer(page, (free / 100).toFixed(3))).check.correct, false, 'a fraction is not a percentage');
  const right = await typeAnswer(page, `${free.toFixed(1)}%`);
  assert.equal(right.check.correct, true, right.check.explanation);
  await screenshot(page, 'cspace3d-question-right.png');

  // The 3-link arm: all three pairs glued; a link opens the question, the API answers it.
  const bundled = await api(page, 'bundled_scenes');
  await api(page, 'set_scene', { scene: bundled['arm-3link'] });
  await api(page, 'set_params', { params: { question: 'glued', answer: 'top-bottom', check: true } });
  assert.equal((await api(page, 'state')).question.check.correct, false);
  await press(page, 'c3d-choice:all');
  await press(page, 'c3d-check');
  assert.equal((await api(page, 'state')).question.check.correct, true);
  assert.equal((await api(page, 'snapshot')).params.question, 'glued');
  assert.equal(await refusal(page, 'call', 'set_params', { params: { question: 'colour' } }),
               'question: name, dimension, glued, seam or free');
}));

test('RRT-Connect in 3-D: chosen by a link, its trees drawn in the block, kept by Share and lock',
  () => withBrowser(async ({ browser, url }) => {
  const ctx = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await ctx.newPage();
  await page.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
  const errors = collectErrors(page);
  await openLab(page, url + '?lesson=cspace-3d&planner=rrt-connect&samples=1500&seed=4');
  await waitFrames(page, 3);
  let s = await api(page, 'state');
  assert.equal(s.prm.planner, 'rrt-connect');
  assert.equal((await api(page, 'snapshot')).params.planner, 'rrt-connect');
  assert.equal(s.prm.nodes, 0, 'nothing grown before a step');
  const layout = (await api(page, 'status')).layout.views.find((v) => v.name === 'volume');
  const box = await page.locator('canvas').boundingBox();
  const vol = { x: box.x + layout.x, y: box.y + layout.y, w: layout.w - 30, h: layout.h };
  const probes = [];
  for (let y = vol.y; y < vol.y + vol.h; y += 2) for (let x = vol.x; x < vol.x + vol.w; x += 2) probes.push([x, y]);
  await page.mouse.move(2, 2);
  await waitFrames(page, 2);
  const before = (await inspectPng(browser, await page.screenshot(), probes)).at;

  await api(page, 'run');
  await waitFrames(page, 3);
  s = await api(page, 'state', { roadmap: true });
  assert.equal(s.prm.planner, 'rrt-connect');
  assert.ok(s.prm.solved, 'RRT-Connect joined its trees in SE(2)');
  // Two trees joined by one edge: one edge fewer than vertices, and every vertex reached.
  const { vertices, edge_list: edges } = s.prm;
  assert.ok(vertices.length > 10, `${vertices.length} vertices`);
  assert.equal(edges.length, vertices.length - 1, 'a tree (two trees and their join)');
  const seen = new Set([0]);
  for (let grew = true; grew;) {
    grew = false;
    for (const [a, b] of edges) if (seen.has(a) !== seen.has(b)) { seen.add(a); seen.add(b); grew = true; }
  }
  assert.equal(seen.size, vertices.length, 'every vertex is joined to the start');
  // Edges through the glued top and bottom, from the tree's own vertices (theta is the third).
  const seams = edges.filter(([a, b]) => Math.abs(wrap(vertices[b][2]) - wrap(vertices[a][2])) > Math.PI).length;
  assert.equal(s.prm.seam_crossing_edges, seams);
  await page.mouse.move(2, 2);
  await waitFrames(page, 2);
  const shot = await screenshot(page, 'cspace3d-rrt-connect.png');
  const after = (await inspectPng(browser, shot.png, probes)).at;
  const changed = after.filter((c, i) => !close(c, before[i], 30)).length;
  assert.ok(changed > 200, `${changed} probes in the block changed as the trees grew`);

  // Share keeps the planner; lock=planner keeps the student from changing it.
  await click(page, await pageButton(page, 'share'));
  await page.waitForSelector('.lab-dialog textarea');
  const link = await page.inputValue('.lab-dialog textarea');
  await page.keyboard.press('Escape');
  assert.equal(new URL(link).searchParams.get('planner'), 'rrt-connect', link);
  const locked = await ctx.newPage();
  const lockedErrors = collectErrors(locked);
  await openLab(locked, url + '?lesson=cspace-3d&planner=rrt&lock=planner');
  await waitFrames(locked, 3);
  assert.equal((await api(locked, 'state')).prm.planner, 'rrt');
  assert.match(await refusal(locked, 'call', 'set_params', { params: { planner: 'prm' } }), /planner/);
  assert.equal((await api(locked, 'state')).prm.planner, 'rrt');
  // The planner by the panel's combo, with the mouse: a click opens it, a click picks RRT.
  await press(page, 'c3d-planner');
  await press(page, 'c3d-planner:rrt');
  s = await api(page, 'state');
  assert.equal(s.prm.planner, 'rrt');
  assert.equal(s.prm.nodes, 0, 'a new planner starts at step 0');
  // A bad name is refused with the list, and nothing changes.
  assert.match(await refusal(page, 'call', 'set_params', { params: { planner: 'rrt-star', samples: 300 } }),
               /^planner: unknown planner 'rrt-star' \(prm, prm-star, lazy-prm, rrt, rrt-connect\)$/);
  assert.equal((await api(page, 'snapshot')).params.samples, 1500);
  assert.deepEqual(errors, []);
  assert.deepEqual(lockedErrors, []);
  await ctx.close();
}));

test('the volume\'s zoom travels in camera=, and links without it still read the same',
  () => withBrowser(async ({ browser, url }) => {
  const ctx = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await ctx.newPage();
  await page.addInitScript(() => localStorage.setItem('cspacelab:v1:welcomed', '1'));
  const errors = collectErrors(page);
  await openLab(page, url + '?lesson=cspace-3d');
  await waitFrames(page, 3);
  const layout = (await api(page, 'status')).layout.views.find((v) => v.name === 'volume');
  const box = await page.locator('canvas').boundingBox();
  await page.mouse.move(box.x + layout.x + layout.w * 0.4, box.y + layout.y + layout.h * 0.5);
  await waitFrames(page, 2);
  for (let i = 0; i < 3; ++i) {
    await page.mouse.wheel(0, -100);
    await waitFrames(page, 2);
  }
  const zoomed = (await api(page, 'state')).drawn;
  assert.ok(Math.abs(zoomed.zoom - 1.728) < 1e-9, `three notches of 1.2: ${zoomed.zoom}`);
  assert.deepEqual((await api(page, 'camera')).volume, [zoomed.yaw, zoomed.pitch, 1.728]);
  await page.mouse.move(2, 2);
  await waitFrames(page, 2);
  // The zoom made the block bigger: more of the view differs from the unzoomed one.
  const probes0 = [];
  for (let i = 0; i < 400; ++i) probes0.push([box.x + layout.x + (i % 20 + 0.5) * layout.w / 20, box.y + layout.y + (Math.floor(i / 20) + 0.5) * layout.h / 20]);
  const zoomedPixels = (await inspectPng(browser, await page.screenshot(), probes0)).at;

  // Share: the link holds the zoom; a fresh page shows the same block at the same size.
  await click(page, await pageButton(page, 'share'));
  await page.waitForSelector('.lab-dialog textarea');
  const link = await page.inputValue('.lab-dialog textarea');
  await page.keyboard.press('Escape');
  assert.match(new URL(link).searchParams.get('camera'), /^volume:[-\d.]+,[-\d.]+,1\.728$/);
  const other = await ctx.newPage();
  const otherErrors = collectErrors(other);
  await openLab(other, link);
  await waitFrames(other, 3);
  assert.equal((await api(other, 'state')).drawn.zoom, 1.728);
  assert.deepEqual(await api(other, 'camera'), await api(page, 'camera'));
  await other.mouse.move(2, 2);
  await waitFrames(other, 2);
  const probes = [];
  for (let i = 0; i < 400; ++i) probes.push([box.x + layout.x + (i % 20 + 0.5) * layout.w / 20, box.y + layout.y + (Math.floor(i / 20) + 0.5) * layout.h / 20]);
  const a = (await inspectPng(browser, await page.screenshot(), probes)).at;
  const b = (await inspectPng(browser, await other.screenshot(), probes)).at;
  assert.ok(a.filter((c, i) => !close(c, b[i], 20)).length <= 4, 'the same picture of the zoomed block');

  // A link from before zoom travelled (yaw, pitch): the zoom is 1, and the block is drawn
  // smaller than in the zoomed link with the same turn.
  const [yaw, pitch] = (await api(page, 'camera')).volume;
  await other.goto(url + `?lesson=cspace-3d&camera=volume:${yaw},${pitch}`);
  await waitFrames(other, 3);
  assert.deepEqual((await api(other, 'camera')).volume, [yaw, pitch]);
  assert.equal((await api(other, 'state')).drawn.zoom, 1);
  await other.mouse.move(2, 2);
  await waitFrames(other, 2);
  const unzoomed = (await inspectPng(browser, await other.screenshot(), probes)).at;
  assert.ok(unzoomed.filter((c, i) => !close(c, zoomedPixels[i], 20)).length > 20, 'the zoom changes the picture');
  await other.goto(url + '?lesson=cspace-3d&camera=volume:1.2,0.4,9');
  await waitFrames(other, 3);
  assert.match((await api(other, 'status')).notice, /volume's zoom 9 is outside \[0\.5, 4\]/);
  assert.equal((await api(other, 'state')).drawn.zoom, 1);
  // The torus's 3-D view does not zoom: a third number is refused there.
  await other.goto(url + '?lesson=torus&camera=torus:1.2,0.4,2');
  await waitFrames(other, 3);
  assert.match((await api(other, 'status')).notice, /torus is a 3-D view: \[yaw, pitch\] in radians/);
  assert.deepEqual(errors, []);
  assert.deepEqual(otherErrors, []);
  await ctx.close();
}));

test('the lesson\'s new panel on a phone and a desktop (pictures to look at)', async () => {
  for (const [name, viewport] of [['phone', { width: 390, height: 844 }], ['desktop', { width: 1280, height: 800 }]])
    await withPage({ viewport, open: '?lesson=cspace-3d&planner=rrt-connect&samples=1500&seed=4&steps=100000&question=glued' },
      async ({ page }) => {
        await waitFrames(page, 3);
        assert.equal((await api(page, 'state')).prm.planner, 'rrt-connect');
        await screenshot(page, `cspace3d-more-${name}-view.png`);
        if (name === 'phone') {
          const at = await controlRect(page, 'tab:controls');
          assert.ok(at, 'the Controls tab is on screen');
          await click(page, { x: at.x + at.w / 2, y: at.y + at.h / 2 });
          await waitFrames(page, 3);
          await press(page, 'section:Questions');
          await waitFrames(page, 2);
          await press(page, 'c3d-choice:top-bottom');
          await press(page, 'c3d-check');
          assert.equal((await api(page, 'state')).question.check.correct, true, 'a finger-sized panel answers too');
        }
        await screenshot(page, `cspace3d-more-${name}-panel.png`);
      });
});
