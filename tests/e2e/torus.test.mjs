// Lesson "2-link arm and the torus" with real mouse events: pose the arm from the C-space,
// drag an obstacle and see its C-obstacle move, grow PRM on the torus with edges across the
// seams, and compare the C-obstacle map with the CLI's PGM.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { withPage, worldToPage, drag, click, keys, waitFrames, screenshot, inspectPng, api, cli,
         tempJson, pageButton, expectView, sceneProbes, refusal } from './lib/harness.mjs';
import { cspaceProbes } from './lib/probes.mjs';

test('the arm and its torus: linked views, live C-obstacles, PRM across seams',
  () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'torus' });
  await waitFrames(page, 3);

  // Pose the arm by clicking in the C-space square.
  const [target] = await worldToPage(page, [[1.2, -0.8]], 'cspace');
  await click(page, target);
  let s = await api(page, 'state');
  const { scale } = await page.evaluate(() => window.cspacelab.view([], 'cspace'));
  assert.ok(Math.abs(s.q[0] - 1.2) <= 2 / scale && Math.abs(s.q[1] + 0.8) <= 2 / scale, `q = ${s.q}`);
  // Dragging link 1 in the workspace turns theta1 only.
  const scene = await api(page, 'get_scene');
  const base = scene.robot.base, l1 = scene.robot.lengths[0];
  const mid1 = [base[0] + 0.5 * l1 * Math.cos(s.q[0]), base[1] + 0.5 * l1 * Math.sin(s.q[0])];
  const turned = [base[0] + 0.5 * l1 * Math.cos(2.0), base[1] + 0.5 * l1 * Math.sin(2.0)];
  const [from, to] = await worldToPage(page, [mid1, turned], 'workspace');
  await drag(page, from, to);
  const after = await api(page, 'state');
  assert.ok(Math.abs(after.q[0] - 2.0) < 0.05, `theta1 ${after.q[0]}`);
  assert.ok(Math.abs(after.q[1] - s.q[1]) < 1e-9, 'theta2 unchanged');

  // Drag an obstacle in the workspace: its C-obstacle moves (the map changes, live).
  const probe = [];
  for (let i = 0; i < 24; ++i) for (let j = 0; j < 24; ++j) probe.push([-Math.PI + (i + 0.5) * Math.PI / 12, -Math.PI + (j + 0.5) * Math.PI / 12]);
  const before = (await api(page, 'state', { blocked_at: probe })).blocked_at;
  const disk = scene.obstacles[0];
  const [d0, d1] = await worldToPage(page, [disk.center, [disk.center[0] - 0.12, disk.center[1] + 0.1]], 'workspace');
  await keys(page, 'v');
  await drag(page, d0, d1);
  const moved = await api(page, 'get_scene');
  assert.ok(Math.abs(moved.obstacles[0].center[1] - (disk.center[1] + 0.1)) < 0.02, 'the disk moved');
  const afterMove = (await api(page, 'state', { blocked_at: probe })).blocked_at;
  const changed = before.filter((b, i) => b !== afterMove[i]).length;
  assert.ok(changed > 5, `${changed} probed configurations changed`);
  // The map agrees with the CLI's PGM of the same scene.
  const pgmFile = path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'csl-')), 'map.pgm');
  const cspace = cli('cspace', tempJson(moved), '--resolution', '24', '--out', pgmFile);
  const pgm = fs.readFileSync(pgmFile);
  const header = pgm.subarray(0, 15).toString('latin1');
  const offset = header.indexOf('255\n') + 4;
  let agree = 0;
  for (let i = 0; i < 24; ++i) for (let j = 0; j < 24; ++j) {
    const free = pgm[offset + j * 24 + i] === 255;  // row j is theta2, column i is theta1
    agree += free === !afterMove[i * 24 + j];
  }
  assert.ok(agree >= 574, `${agree}/576 probes agree with the CLI`);
  assert.ok(Math.abs(cspace.free_fraction - afterMove.filter((b) => !b).length / 576) < 0.01);

  // PRM on the torus: some edges take the short way across a seam.
  await api(page, 'set_params', { params: { samples: 400, neighbors: 'k:10', seed: 3, view: 'both' } });
  await api(page, 'run');
  s = await api(page, 'state');
  assert.ok(s.prm.nodes > 300 && s.prm.edges > 1000, `roadmap ${s.prm.nodes} / ${s.prm.edges}`);
  assert.ok(s.prm.seam_crossing_edges > 0, `seam-crossing edges: ${s.prm.seam_crossing_edges}`);
  const plan = cli('plan', tempJson(await api(page, 'get_scene')), '--samples', '400', '--k', '10', '--seed', '3');
  assert.equal(s.prm.roadmap_hash, plan.roadmap_hash, 'the same roadmap as the CLI');

  // The exercise: the loop around the torus.
  await api(page, 'set_params', { params: { exercise: 'around' } });
  await page.mouse.move(5, 5);
  await waitFrames(page, 20);
  assert.equal((await api(page, 'state')).exercise, 'around');
  // The square: the C-obstacles where the map has them, under the roadmap (whose edges are free),
  // off the markers and the loop's trail (a row at the loop's theta2, through the C-obstacles).
  const last = await api(page, 'state');
  await expectView(page, browser, 'torus.png',
                   await cspaceProbes(page, { free: false, avoid: [last.start, last.goal], rows: [last.q[1]] }), 'cspace');
}));

// What a new student meets first (issue 21): the arm's dot, S and G apart in the square, so that
// "drag in the square to pose the arm" from the dot poses the arm and leaves the start alone;
// axes read in multiples of pi; the loop around the torus says it is not a path.
test('the torus at load: markers apart, a drag from the dot poses the arm, axes in pi, the loop is not a path',
  () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'torus' });
  await waitFrames(page, 3);
  const s = await api(page, 'state');
  const [dot, start, goal] = await worldToPage(page, [s.q, s.start, s.goal], 'cspace');
  const apart = (a, b) => Math.hypot(a.x - b.x, a.y - b.y);
  // A marker is 9 px in radius and the dot 6: 24 px leaves both whole and pressable.
  assert.ok(apart(dot, start) >= 24, `the dot ${JSON.stringify(dot)} and S ${JSON.stringify(start)} overlap`);
  assert.ok(apart(dot, goal) >= 24, 'the dot and G overlap');
  assert.equal(s.q_free, true, 'the arm stands free');

  // The square shows the exact C-obstacles, as the map (state's blocked_at) has them.
  const cprobes = await cspaceProbes(page, { avoid: [s.q, s.start, s.goal] });
  assert.ok(cprobes.length >= 60, `${cprobes.length} probes`);
  await expectView(page, browser, 'torus-cspace-at-load.png', cprobes, 'cspace');
  // The workspace: the obstacles, and free space away from the three arms drawn (start, goal, now).
  const scene0 = await api(page, 'get_scene');
  const arm = (q) => {
    const [bx, by] = scene0.robot.base, [l1, l2] = scene0.robot.lengths;
    const elbow = [bx + l1 * Math.cos(q[0]), by + l1 * Math.sin(q[0])];
    return [[[bx, by], elbow], [elbow, [elbow[0] + l2 * Math.cos(q[0] + q[1]), elbow[1] + l2 * Math.sin(q[0] + q[1])]]];
  };
  await expectView(page, browser, 'torus-workspace-at-load.png',
                   sceneProbes(scene0, { markers: false, avoid: [s.q, s.start, s.goal].flatMap(arm) }));

  // From the dot, a drag poses the arm; the start stays where it was.
  const target = [s.q[0] - 0.6, s.q[1] + 0.9];
  const [to] = await worldToPage(page, [target], 'cspace');
  await drag(page, dot, to);
  const after = await api(page, 'state');
  const { scale } = await page.evaluate(() => window.cspacelab.view([], 'cspace'));
  assert.ok(Math.hypot(after.q[0] - target[0], after.q[1] - target[1]) <= 3 / scale, `posed at ${after.q}`);
  assert.deepEqual(after.start, s.start, 'the start did not move');
  assert.equal(after.prm.planner_builds, s.prm.planner_builds, 'nothing was replanned');

  // The square's axes are angles: labelled in multiples of pi, as a student thinks of them.
  const { ticks } = await page.evaluate(() => window.cspacelab.view([], 'cspace'));
  for (const axis of ['x', 'y']) {
    assert.ok(ticks[axis].includes('π') && ticks[axis].includes('−π') && ticks[axis].includes('0'), `${axis}: ${ticks[axis]}`);
    for (const label of ticks[axis]) assert.match(label, /^(0|−?\d*π(\/\d+)?)$/, `${axis}: "${label}"`);
  }
  // The workspace's axes are lengths, in decimals.
  const workspace = (await page.evaluate(() => window.cspacelab.view([], 'workspace'))).ticks;
  assert.ok(workspace.x.includes('0.5') && !workspace.x.some((l) => l.includes('π')), `workspace: ${workspace.x}`);

  // The loop around the torus, pressed with the mouse: the workspace says it is no path.
  const around = await pageButton(page, 'torus-loop-around');
  await click(page, around);
  await waitFrames(page, 3);
  const looping = await api(page, 'state');
  assert.equal(looping.exercise, 'around');
  assert.match(looping.workspace_caption, /not a (planned )?path/);
  // In this scene the loop crosses C-obstacles, and the caption says where the arm would hit.
  assert.match(looping.workspace_caption, /hits/);
}));

// A 3-link arm is a scene the lab reads (issue 23), but this lesson's square is T^2: it says so
// and keeps its scene; the collision and potential lessons likewise.
test('an arm of 3 links is refused by the lessons of the 2-link arm, with the reason', () => withPage(async ({ page }) => {
  const arm3 = { version: 1, robot: { type: 'arm', base: [0.5, 0.5], lengths: [0.2, 0.15, 0.1] }, start: [0, 0, 0], goal: [1, 0, 0] };
  for (const [lesson, why] of [['torus', /2-link arm.*'arm' robot with 3 coordinates/], ['collision', /point robot and the 2-link arm/],
                               ['potential', /2-link arm on its torus; the scene's arm has 3 links/]]) {
    await api(page, 'select_lesson', { id: lesson });
    const before = await api(page, 'get_scene');
    assert.match(String(await refusal(page, 'setScene', arm3)), why, lesson);
    assert.deepEqual(await api(page, 'get_scene'), before, `${lesson}: its scene kept`);
  }
}));
