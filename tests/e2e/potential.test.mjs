// Lesson "Potential fields" with real mouse events: P13's rectangle, its forces against the
// CLI's `potential` at the same configuration; drag the robot and the forces change; the heat
// map on screen; descent step by step equal to the CLI's `descend`; the cup's local minimum and
// its escape; the arm's field on the torus.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { withPage, worldToPage, drag, click, waitFrames, screenshot, inspectPng, api, cli,
         tempJson } from './lib/harness.mjs';

const close = (a, b, tol = 1e-12) => Math.abs(a - b) <= tol * Math.max(1, Math.abs(a), Math.abs(b));

// The CLI's view of the same scene, configuration and field.
function cliPotential(scene, q, field) {
  return cli('potential', tempJson(scene), '--at', q.join(','), '--rho0', String(field.rho0), '--eta', String(field.eta),
             '--zeta', String(field.zeta), '--switch', String(field.switch));
}

// The heat map's colour ramp (field_draw.cpp), and how far an RGB colour is from it.
const RAMP = [[255, 255, 229], [254, 227, 145], [254, 153, 41], [217, 95, 14], [140, 45, 4]];
function offRamp(c) {
  let best = Infinity;
  for (let k = 0; k + 1 < RAMP.length; ++k)
    for (let t = 0; t <= 1; t += 1 / 64)
      best = Math.min(best, Math.hypot(...[0, 1, 2].map((i) => c[i] - (RAMP[k][i] + t * (RAMP[k + 1][i] - RAMP[k][i])))));
  return best;
}

// The arm's C-obstacles on the torus square are the exact map's (`cspacelab cspace`): deep
// inside one the screen is the obstacle grey, and a free point 2-3 map pixels outside shows
// the heat map's own colour, not a blend with the grey of the 96 x 96 grid's nodes on the
// obstacle (which drew the obstacles' edges as the grid's blocks).
async function armEdgesExact(page, browser, scene, png) {
  const R = 384;
  const file = path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'csl-e2e-')), 'map.pgm');
  cli('cspace', tempJson(scene), '--out', file, '--resolution', String(R));
  const bytes = fs.readFileSync(file);
  fs.rmSync(path.dirname(file), { recursive: true });
  const pixels = bytes.subarray(bytes.length - R * R);
  const blocked = (i, j) => pixels[((j + R) % R) * R + ((i + R) % R)] === 0;
  const inside = [], outside = [];
  for (let j = 0; j < R; ++j)
    for (let i = 0; i < R; ++i) {
      let near = Infinity, free = false;  // the nearest blocked pixel within 4; any free one
      for (let dj = -4; dj <= 4; ++dj)
        for (let di = -4; di <= 4; ++di) {
          const d = Math.hypot(di, dj);
          if (d > 4) continue;
          if (blocked(i + di, j + dj)) near = Math.min(near, d);
          else free = true;
        }
      const at = [-Math.PI + (i + 0.5) * 2 * Math.PI / R, -Math.PI + (j + 0.5) * 2 * Math.PI / R];
      if (!blocked(i, j) && near >= 2 && near <= 3) outside.push(at);
      if (blocked(i, j) && !free) inside.push(at);
    }
  assert.ok(outside.length > 200 && inside.length > 200, `${outside.length} edge and ${inside.length} inner probes`);
  const pick = (list) => list.filter((_, k) => k % Math.ceil(list.length / 150) === 0);
  const probes = [...pick(outside), ...pick(inside)];
  const dpr = await page.evaluate(() => window.devicePixelRatio);
  const onPage = await worldToPage(page, probes, 'cspace');
  const { at } = await inspectPng(browser, png, onPage.map((p) => [p.x * dpr, p.y * dpr]));
  const n = pick(outside).length;
  const heat = at.slice(0, n).filter((c) => offRamp(c) < 32).length;
  const grey = at.slice(n).filter((c) => Math.abs(c[0] - 96) + Math.abs(c[1] - 96) + Math.abs(c[2] - 104) <= 6).length;
  // A few probes lie under a level line, the trajectory or the marker. (The grid's grey put
  // 14 of 150 edge probes 32-70 off the ramp, and 80 of 150 inner ones off the grey.)
  assert.ok(heat >= 0.96 * n, `${heat} of ${n} free probes by an edge in the heat map's colours`);
  assert.ok(grey >= 0.9 * (at.length - n), `${grey} of ${at.length - n} inner probes in the obstacle grey`);
}

test('potential fields: forces, dragging, heat map, descent, local minimum and escape, the arm',
  () => withPage(async ({ page, browser }) => {
  await api(page, 'select_lesson', { id: 'potential' });
  await waitFrames(page, 3);

  // P13 by default: a rectangle with four vertices as control points, two polygon obstacles.
  const scene = await api(page, 'get_scene');
  assert.equal(scene.robot.type, 'polygon');
  assert.equal(scene.obstacles.length, 2);
  let s = await api(page, 'state');
  assert.equal(s.control_points.length, 4);
  assert.deepEqual(s.from, scene.start);

  // Drag the rectangle by its body, near the upper obstacle's region of influence.
  const [grabAt, dropAt] = await worldToPage(page, [[scene.start[0], scene.start[1]], [0.55, 0.66]]);
  await drag(page, grabAt, dropAt, 12);
  s = await api(page, 'state');
  const { scale } = await page.evaluate(() => window.cspacelab.view([], 'workspace'));
  assert.ok(Math.abs(s.from[0] - 0.55) < 3 / scale && Math.abs(s.from[1] - 0.66) < 3 / scale, `dragged to ${s.from}`);
  assert.equal(s.steps, 0, 'a drag restarts the descent from where the robot is');
  // The app's forces are the CLI's, to the last bit, at the same configuration.
  const ref = cliPotential(scene, s.from, s.field);
  for (let i = 0; i < 4; ++i) {
    const a = s.control_points[i], b = ref.control_points[i];
    assert.equal(a.name, b.name);
    for (let k = 0; k < 2; ++k) {
      assert.ok(close(a.F_att[k], b.F_att[k]), `F_att ${a.name}`);
      assert.ok(close(a.F_rep[k], b.F_rep[k]), `F_rep ${a.name}`);
    }
    assert.ok(close(a.rho, b.rho), `rho ${a.name}`);
  }
  for (let k = 0; k < 3; ++k) assert.ok(close(s.tau[k], ref.generalized_force.tau[k]), 'tau = J^T F');
  assert.ok(s.control_points.some((p) => p.F_rep[0] !== 0 || p.F_rep[1] !== 0), 'a vertex within rho0 is pushed');

  // On screen: the heat map is shaded (many colours), light far from obstacles, with the robot.
  const shot = await screenshot(page, 'potential-p13.png');
  const [far, nearObstacle] = await worldToPage(page, [[0.08, 0.5], [0.75, 0.32]]);
  const dpr = await page.evaluate(() => window.devicePixelRatio);
  const png = await inspectPng(browser, shot.png, [[far.x * dpr, far.y * dpr], [nearObstacle.x * dpr, nearObstacle.y * dpr]]);
  assert.ok(png.colours > 150, `${png.colours} colours`);
  const lum = ([r, g, b]) => 0.3 * r + 0.59 * g + 0.11 * b;
  assert.ok(lum(png.at[0]) > lum(png.at[1]) + 20, `far ${png.at[0]} lighter than near an obstacle ${png.at[1]}`);

  // Descent, step by step: the same trajectory as the CLI's from the same configuration.
  await api(page, 'set_params', { params: { from: [0.5, 0.56, 0] } });
  await page.keyboard.press('.');
  await page.keyboard.press('.');
  await waitFrames(page, 2);
  assert.equal((await api(page, 'state')).steps, 2, 'two steps by key');
  await api(page, 'run_to', { steps: 1000000 });
  s = await api(page, 'state');
  const desc = cli('descend', tempJson(scene), '--from', '0.5,0.56,0');
  assert.equal(s.descent.outcome, desc.outcome);
  assert.equal(s.descent.outcome, 'goal');
  assert.deepEqual(s.descent.trajectory.at(-1), desc.final, 'the same final configuration, bit for bit');
  assert.equal(s.descent.trajectory.length, desc.trajectory.length);
  await screenshot(page, 'potential-p13-descended.png');

  // The cup: plain descent stops in a local minimum; with escapes, random walks get out.
  const bundled = await api(page, 'bundled_scenes');
  const cup = bundled['potential-cup'];
  await api(page, 'set_scene', { scene: cup });
  await api(page, 'run_to', { steps: 100000 });
  s = await api(page, 'state');
  assert.equal(s.robot, 'point');
  assert.equal(s.descent.outcome, 'local_minimum');
  const stuck = s.descent.trajectory.at(-1);
  assert.ok(stuck[1] > 0.4 && stuck[1] < 0.6 && stuck[0] > 0.4 && stuck[0] < 0.6, `stuck inside the cup at ${stuck}`);
  await screenshot(page, 'potential-cup-stuck.png');
  await api(page, 'set_params', { params: { escapes: 5, seed: 1 } });
  await api(page, 'run_to', { steps: 100000 });
  s = await api(page, 'state');
  const escaped = cli('descend', tempJson(cup), '--escapes', '5', '--seed', '1');
  assert.equal(s.descent.outcome, 'escaped');
  assert.equal(escaped.outcome, 'escaped');
  assert.deepEqual(s.descent.trajectory.at(-1), escaped.final);
  assert.ok(s.descent.local_minima >= 1 && s.descent.escapes_used >= 1);
  await screenshot(page, 'potential-cup-escaped.png');
  // Stepping back replays: the same state at the same step.
  const mid = Math.floor(s.steps / 2);
  await api(page, 'run_to', { steps: mid });
  const atMid = (await api(page, 'state')).q;
  await api(page, 'run_to', { steps: s.steps });
  await api(page, 'run_to', { steps: mid });
  assert.deepEqual((await api(page, 'state')).q, atMid);

  // Autosave and reload: the same lesson, scene, parameters and step, to the last bit.
  const saved = await api(page, 'state');
  await page.evaluate(() => window.cspacelab.shell.saveNow());
  await page.reload();
  await page.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2);
  assert.equal((await api(page, 'status')).lesson, 'potential');
  assert.deepEqual(await api(page, 'state'), saved, 'the reloaded state is the saved one');

  // A start inside an obstacle: a clear message, no descent, nothing lost.
  await api(page, 'set_params', { params: { from: [0.5, 0.65] } });
  s = await api(page, 'state');
  assert.equal(s.from_free, false);
  assert.equal(s.descent, null);
  assert.equal((await api(page, 'get_scene')).obstacles.length, 1);

  // The arm: elbow and tip are the control points; its field over the torus square.
  await api(page, 'set_scene', { scene: bundled['arm-2link'] });
  await waitFrames(page, 2);
  s = await api(page, 'state');
  assert.deepEqual(s.control_points.map((p) => p.name), ['elbow', 'tip']);
  const armRef = cliPotential(bundled['arm-2link'], s.from, s.field);
  for (let k = 0; k < 2; ++k) assert.ok(close(s.tau[k], armRef.generalized_force.tau[k]), 'joint torques = J^T F');
  // Place the arm by clicking in the torus square.
  const [onTorus] = await worldToPage(page, [[0.4, -0.3]], 'cspace');
  await click(page, onTorus);
  s = await api(page, 'state');
  const { scale: cs } = await page.evaluate(() => window.cspacelab.view([], 'cspace'));
  assert.ok(Math.abs(s.from[0] - 0.4) < 3 / cs && Math.abs(s.from[1] + 0.3) < 3 / cs, `placed at ${s.from}`);
  assert.equal(s.from_free, true, '(0.4, -0.3) is free in this scene');
  await api(page, 'run_to', { steps: 100000 });
  const armState = await api(page, 'state');
  const armDesc = cli('descend', tempJson(bundled['arm-2link']), '--from', s.from.join(','));
  assert.equal(armState.descent.outcome, armDesc.outcome);
  assert.deepEqual(armState.descent.trajectory.at(-1), armDesc.final);
  const armShot = await screenshot(page, 'potential-arm.png');
  await armEdgesExact(page, browser, bundled['arm-2link'], armShot.png);
  assert.ok(s.heat_map.levels > 0, 'level lines on the torus');

  // Undo goes back to the cup: another robot, so the lesson starts over on it (nothing of the
  // arm's two angles is left in a point robot's state).
  assert.equal(await api(page, 'undo'), true);
  await waitFrames(page, 2);
  s = await api(page, 'state');
  assert.equal(s.robot, 'point');
  assert.deepEqual(s.from, cup.start);
  assert.equal(s.control_points.length, 1);
  assert.equal(s.from.length, (await api(page, 'get_scene')).start.length);
}));
