// Lesson "Step PRM" in the browser, with real mouse and keyboard events: draw two disks and a
// polygon, undo one, step the planner forward and back, run it to the end, and check that the
// roadmap is exactly the one `cspacelab plan` builds for the same scene, parameters and seed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, chord, drawDisk, worldToPage, drag, click, keys, waitFrames, screenshot, inspectPng, api, cli, tempJson,
         refusal, expectView, sceneProbes } from './lib/harness.mjs';

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
  // The picture is that scene: the disks filled where they are, free space white, S and G.
  await expectView(page, browser, 'step-prm-drawn.png', sceneProbes(scene, { free: 16 }));

  // Step forward 50 and back 10 with the keys ('.' and ',').
  await api(page, 'set_params', { params: { samples: 120, neighbors: 'k:8', checker: 'bisection', seed: 7 } });
  await page.mouse.move(700, 400);
  for (let i = 0; i < 50; ++i) await page.keyboard.press('.');
  // (Presses sent faster than frames are drawn queue up: the platform hands ImGui one press of a
  // key a frame, so a loaded machine may still be working through them here.)
  await page.waitForFunction(() => window.cspacelab.state().steps >= 50, null, { timeout: 30000 });
  await waitFrames(page, 3);
  assert.equal((await api(page, 'state')).steps, 50);
  const at40 = await (async () => { await api(page, 'run_to', { steps: 40 }); return api(page, 'state'); })();
  await api(page, 'run_to', { steps: 50 });
  for (let i = 0; i < 10; ++i) await page.keyboard.press(',');
  await page.waitForFunction(() => window.cspacelab.state().steps <= 40, null, { timeout: 30000 });
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

  // Moving an obstacle re-runs to the same step with the same seed: the student's step, or the
  // end if the moved scene's run ends sooner; either way the roadmap a fresh run of the moved
  // scene has there (here the run was done, so the CLI's whole run tells both).
  await keys(page, 'v');
  const [disk, moved] = await worldToPage(page, [[0.3, 0.6], [0.3, 0.75]]);
  await drag(page, disk, moved);
  const after = await api(page, 'state');
  const movedScene = await api(page, 'get_scene');
  assert.ok(Math.abs(movedScene.obstacles[0].center[1] - 0.75) < 0.01);
  const fresh = cli('plan', tempJson(movedScene), '--samples', '120', '--k', '8', '--checker', 'bisection', '--seed', '7');
  if (fresh.steps <= final.steps) {
    assert.equal(after.steps, fresh.steps, 'replayed to the end of the moved scene\'s run');
    assert.equal(after.done, true);
    assert.equal(after.roadmap_hash, fresh.roadmap_hash, 'the roadmap a fresh run of the moved scene builds');
  } else {
    assert.equal(after.steps, final.steps, 'replayed to the student\'s step');
  }
  assert.notEqual(after.roadmap_hash, final.roadmap_hash);

  // The picture after the run: the moved disk where it is now, the markers, and the path (orange,
  // drawn over the roadmap) at the middle of each of its edges.
  await api(page, 'run');
  await keys(page, 'Escape');  // the dragged disk is no longer selected (drawn in the selection's blue)
  const run = await api(page, 'state', { roadmap: true });
  const probes = sceneProbes(movedScene, { free: 0 });
  assert.equal(run.solved, true);
  for (let i = 0; i + 1 < run.path.length; ++i) {
    const mid = [(run.path[i][0] + run.path[i + 1][0]) / 2, (run.path[i][1] + run.path[i + 1][1]) / 2];
    const nearMarker = [movedScene.start, movedScene.goal].some((m) => Math.hypot(mid[0] - m[0], mid[1] - m[1]) < 0.04);
    if (!nearMarker) probes.push({ at: mid, look: [230, 159, 0], why: `the path's edge ${i + 1}` });
  }
  await expectView(page, browser, 'step-prm.png', probes);
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

// The log in words a student reads without alarm (issue 21): a vertex with no new pair to check
// says its pairs were checked from the other vertex; an edge proven by its ends' clearances
// says so, where "0 evaluations" read as a check that did not happen. Stepped with the '.' key.
test('Step PRM: the log explains empty neighbour lists and edges proven at once', () => withPage(async ({ page }) => {
  await api(page, 'select_lesson', { id: 'step-prm' });
  await api(page, 'set_params', { params: { samples: 12, neighbors: 'k:10', checker: 'bisection', seed: 3 } });
  await page.mouse.move(700, 400);
  await waitFrames(page, 2);
  const lines = [];
  for (let i = 0; i < 400 && !(await api(page, 'state')).done; ++i) {
    await page.keyboard.press('.');
    await waitFrames(page, 1);
    const log = await api(page, 'log');
    lines.push(log.at(-1).text);
  }
  assert.equal((await api(page, 'state')).done, true, 'the run ended');
  const neighbours = lines.filter((t) => t.startsWith('connecting vertex'));
  const edges = lines.filter((t) => /^edge \d+-\d+: /.test(t));
  assert.ok(neighbours.length >= 10 && edges.length > 20, `${neighbours.length} vertices, ${edges.length} edges logged`);
  for (const t of lines) {
    assert.doesNotMatch(t, /\b0 evaluations\b/, t);
    assert.doesNotMatch(t, /: 0 close pairs to check \(k:10\)$/, t);
  }
  // With 14 vertices and k = 10 the last vertices' pairs were all seen from the other side.
  const empty = neighbours.filter((t) => /: 0 close pairs/.test(t));
  assert.ok(empty.length > 0, 'some vertex has nothing new to check');
  for (const t of empty) assert.match(t, /checked already from the other vertex/, t);
  // Edges whose ends' clearances cover them are proven at once, and the log says how.
  const atOnce = edges.filter((t) => /free at once/.test(t));
  assert.ok(atOnce.length > 0, 'some edge is proven by its ends alone');
  for (const t of atOnce) assert.match(t, /clearances cover it/);
}));

// Roadmap vertices a student can see and count (issue 21: they were 2-3 px dots): after the
// samples, before any edge, each vertex is a square (its component's colour in a dark rim) at
// least 6 px across, probed in the screenshot at the vertices' own places.
test('Step PRM: roadmap vertices are squares large enough to see', () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'step-prm' });
  await api(page, 'set_params', { params: { samples: 60, neighbors: 'k:10', checker: 'bisection', seed: 5 } });
  await api(page, 'finish_phase');  // the endpoints
  await api(page, 'finish_phase');  // the samples
  const s = await api(page, 'state', { roadmap: true });
  assert.equal(s.edges, 0);
  await page.mouse.move(5, 5);
  await waitFrames(page, 3);
  // Vertices well apart from each other and from the markers, obstacles' edges and grid lines.
  const pts = s.vertices.slice(2).filter((v, i, all) => all.every((w, j) => j === i || Math.hypot(v[0] - w[0], v[1] - w[1]) > 0.05));
  const page_pts = await worldToPage(page, pts);
  const { png } = await screenshot(page, 'step-prm-vertices.png');
  const probes = [];
  for (const p of page_pts) for (const [dx, dy] of [[2.5, 0], [-2.5, 0], [0, 2.5], [0, -2.5]]) probes.push([p.x + dx, p.y + dy]);
  const { at } = await inspectPng(browser, png, probes);
  let filled = 0;
  for (let i = 0; i < pts.length; ++i) {
    // Each probe 2.5 px from a vertex's centre is on its square (its colour or its dark rim),
    // not on the light canvas or a grid line, whose darkest channel is far above 180.
    filled += at.slice(4 * i, 4 * i + 4).every((c) => Math.min(...c) < 180) ? 1 : 0;
  }
  assert.ok(pts.length >= 15, `${pts.length} isolated vertices`);
  assert.ok(filled >= 0.9 * pts.length, `${filled} of ${pts.length} vertices cover 2.5 px around their centre`);
}));
