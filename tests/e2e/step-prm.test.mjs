// Lesson "Step PRM" in the browser, with real mouse and keyboard events: draw two disks and a
// polygon, undo one, step the planner forward and back, run it to the end, and check that the
// roadmap is exactly the one `cspacelab plan` builds for the same scene, parameters and seed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, chord, drawDisk, worldToPage, drag, click, keys, waitFrames, screenshot, inspectPng, api, cli, tempJson,
         refusal } from './lib/harness.mjs';

test('Step PRM: edit with the mouse, step, step back, run, and match the CLI',
  () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'step-prm' });
  await api(page, 'set_scene', { scene: { version: 1, start: [0.05, 0.05], goal: [0.95, 0.95] } });
  await waitFrames(page, 2);

  // Two disks.
  await drawDisk(page, [0.3, 0.6], [0.42, 0.6]);
  await drawDisk(page, [0.7, 0.35], [0.8, 0.35]);
  // A polygon: click its vertices, Enter closes it.
  await keys(page, 'p');
  for (const v of await worldToPage(page, [[0.45, 0.1], [0.6, 0.12], [0.55, 0.3], [0.48, 0.2]])) await click(page, v);
  await keys(page, 'Enter');
  let scene = await api(page, 'get_scene');
  assert.deepEqual(scene.obstacles.map((o) => o.type), ['disk', 'disk', 'polygon']);
  assert.equal(scene.obstacles[2].vertices.length, 4);
  // A polygon whose edges cross is refused, with a message, and nothing changes.
  for (const v of await worldToPage(page, [[0.1, 0.8], [0.3, 0.95], [0.3, 0.8], [0.1, 0.95]])) await click(page, v);
  await keys(page, 'Enter');
  assert.match((await api(page, 'status')).notice, /self-intersecting/);
  await keys(page, 'Escape');
  assert.equal((await api(page, 'get_scene')).obstacles.length, 3);
  // Undo one: the polygon goes.
  await chord(page, 'Control', 'z');
  scene = await api(page, 'get_scene');
  assert.deepEqual(scene.obstacles.map((o) => o.type), ['disk', 'disk']);

  // Step forward 50 and back 10 with the keys ('.' and ',').
  await api(page, 'set_params', { params: { samples: 120, neighbors: 'k:8', checker: 'bisection', seed: 7 } });
  await page.mouse.move(700, 400);
  for (let i = 0; i < 50; ++i) await page.keyboard.press('.');
  await waitFrames(page, 3);
  assert.equal((await api(page, 'state')).steps, 50);
  const at40 = await (async () => { await api(page, 'run_to', { steps: 40 }); return api(page, 'state'); })();
  await api(page, 'run_to', { steps: 50 });
  for (let i = 0; i < 10; ++i) await page.keyboard.press(',');
  await waitFrames(page, 3);
  const back = await api(page, 'state');
  assert.equal(back.steps, 40);
  assert.equal(back.roadmap_hash, at40.roadmap_hash, 'stepping back gives the identical state');
  assert.equal(back.nodes, at40.nodes);
  const log = await api(page, 'log');
  assert.match(log.at(-1).text, /^sample #\d+ at \(/, 'the log says what the step did');

  // Run to the end; the same roadmap as the CLI's.
  await api(page, 'run');
  const final = await api(page, 'state', { roadmap: true });
  assert.equal(final.done, true);
  const scenePath = tempJson(await api(page, 'get_scene'));
  const plan = cli('plan', scenePath, '--samples', '120', '--k', '8', '--checker', 'bisection', '--seed', '7', '--roadmap');
  assert.equal(final.roadmap_hash, plan.roadmap_hash);
  assert.deepEqual(final.vertices, plan.vertices);
  assert.deepEqual(final.edge_list, plan.edge_list);
  assert.equal(final.solved, plan.solved);
  assert.deepEqual(final.path, plan.path);
  assert.equal(final.components, plan.components);
  assert.equal(final.steps, plan.steps);

  // Moving an obstacle re-runs to the same step with the same seed.
  await keys(page, 'v');
  const [disk, moved] = await worldToPage(page, [[0.3, 0.6], [0.3, 0.75]]);
  await drag(page, disk, moved);
  const after = await api(page, 'state');
  assert.equal(after.steps, final.steps > after.steps ? after.steps : final.steps);
  assert.notEqual(after.roadmap_hash, final.roadmap_hash);
  assert.ok(Math.abs((await api(page, 'get_scene')).obstacles[0].center[1] - 0.75) < 0.01);

  await page.mouse.move(5, 5);
  await waitFrames(page, 3);
  const { png } = await screenshot(page, 'step-prm.png');
  assert.ok((await inspectPng(browser, png)).colours > 40);
}));

// A radius rule's pairs grow with n^2: the lab keeps a run's expected pairs within a million
// (what k = 50 with the most samples checks), refusing more through the API with the reason and
// lowering r when a smaller workspace would make the same r cover more pairs.
test('Step PRM: parameters that would check too many pairs are refused or brought within bounds',
  () => withPage(async ({ page }) => {
  await api(page, 'select_lesson', { id: 'step-prm' });
  const setParams = (params) => refusal(page, 'setParams', params);
  assert.equal(await setParams({ samples: 2000, neighbors: 'radius:0.1' }), null);
  const before = await api(page, 'state');
  // pi 0.3^2 of the 20002 * 20001 / 2 pairs: 56557150.
  assert.equal(await setParams({ samples: 20000, neighbors: 'radius:0.3' }),
               'neighbors: radius:0.3 with 20000 samples means about 56557150 candidate pairs; the lab checks at ' +
               'most 1000000 (r at most 0.03989 with this n)');
  assert.match(await setParams({ samples: 20000 }), /radius:0\.1 with 20000 samples/, 'n alone can be too many');
  assert.equal(await setParams({ checker: 'step:0.0001' }), 'checker: D must be at least 0.001 in the lab');
  // Few samples: every pair is within the bound, so any r goes; and D = 0.001 itself is allowed.
  assert.equal(await setParams({ samples: 500, neighbors: 'radius:5', checker: 'step:0.001' }), null);
  assert.equal((await api(page, 'state')).params.neighbors, 'radius:5');
  assert.equal(await setParams({ samples: 2000, neighbors: 'radius:0.1', checker: 'bisection' }), null);
  const same = await api(page, 'state');
  assert.deepEqual(same.params, before.params, 'refusals change nothing');
  assert.equal(same.roadmap_hash, before.roadmap_hash);
  assert.equal(await setParams({ samples: 20000, neighbors: 'radius:0.0398' }), null);
  await api(page, 'run');
  const full = await api(page, 'state');
  assert.equal(full.done, true);
  // Below the bound: obstacles take samples and cut pairs, and balls stick out of the square.
  assert.ok(full.edge_checks <= 1e6 && full.edge_checks > 0.5e6, `edge checks ${full.edge_checks}`);

  // The same r in a workspace of a quarter the side covers 16 times the pairs: r is lowered.
  assert.equal(await setParams({ samples: 2000, neighbors: 'radius:0.1' }), null);
  await api(page, 'set_scene', { scene: { version: 1, workspace: { min: [0, 0], max: [0.25, 0.25] },
                                          start: [0.01, 0.01], goal: [0.24, 0.24] } });
  const lowered = (await api(page, 'state')).params.neighbors;
  const r = Number(lowered.split(':')[1]);
  // C(2002, 2) pi r^2 / 0.0625 = 1e6
  assert.ok(Math.abs(r - Math.sqrt(1e6 * 0.0625 / (2002 * 2001 / 2) / Math.PI)) < 1e-9, lowered);
}));
