// Lesson "Potential fields" with real mouse events: P13's rectangle, its forces against the
// CLI's `potential` at the same configuration; drag the robot and the forces change; the heat
// map on screen; descent step by step equal to the CLI's `descend`; the cup's local minimum and
// its escape; the arm's field on the torus. The table under the views (rho, grad rho, F_rep,
// F_att and J^T F per vertex, their sums, tau, and (5.5), (5.6) worked for a clicked row) is
// read back as shown and checked against the geometry written again below; it fits 1280 x 800
// without scrolling, and a 900 px embed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { withPage, withBrowser, collectErrors, worldToPage, drag, click, waitFrames, screenshot, inspectPng, api,
         cli, tempJson, pageButton, expectView, sceneProbes } from './lib/harness.mjs';

// --- P13 by hand: the field at the rectangle's vertices, independent of the lab's code.

const sub = (a, b) => [a[0] - b[0], a[1] - b[1]];
const norm = (v) => Math.hypot(v[0], v[1]);

// Whether p is inside polygon `poly` (crossings of a ray to +x).
function insidePolygon(p, poly) {
  let inside = false;
  for (let i = 0, j = poly.length - 1; i < poly.length; j = i++) {
    const [a, b] = [poly[i], poly[j]];
    if ((a[1] > p[1]) !== (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])) inside = !inside;
  }
  return inside;
}

// rho(p) to one obstacle and grad rho = (p - b) / |p - b|, b its nearest point.
function distanceTo(obstacle, p) {
  if (obstacle.type === 'disk') {
    const d = sub(p, obstacle.center), n = norm(d);
    return { rho: Math.max(0, n - obstacle.radius), grad: [d[0] / n, d[1] / n] };
  }
  assert.equal(obstacle.type, 'polygon');
  const poly = obstacle.vertices;
  let best = { d: Infinity, b: null };
  for (let i = 0; i < poly.length; ++i) {
    const a = poly[i], c = poly[(i + 1) % poly.length], e = sub(c, a);
    const t = Math.max(0, Math.min(1, ((p[0] - a[0]) * e[0] + (p[1] - a[1]) * e[1]) / (e[0] * e[0] + e[1] * e[1])));
    const b = [a[0] + t * e[0], a[1] + t * e[1]], d = norm(sub(p, b));
    if (d < best.d) best = { d, b };
  }
  if (insidePolygon(p, poly)) return { rho: 0, grad: null };
  const g = sub(p, best.b);
  return { rho: best.d, grad: [g[0] / best.d, g[1] / best.d] };
}

// The rectangle's vertices at q = (x, y, theta): (x, y) + R(theta) v.
function vertices(robot, q) {
  const [c, s] = [Math.cos(q[2]), Math.sin(q[2])];
  return robot.vertices.map(([vx, vy]) => {
    const rv = [c * vx - s * vy, s * vx + c * vy];
    return { rv, a: [q[0] + rv[0], q[1] + rv[1]] };
  });
}

// Every number of the table at q: SHV (5.6) for the push, the quadratic/conic pull toward the
// vertex's goal position, and J^T F = (F_x, F_y, (R v)_x F_y - (R v)_y F_x).
function handComputed(scene, q, field) {
  const goals = vertices(scene.robot, scene.goal).map((v) => v.a);
  const points = vertices(scene.robot, q).map(({ rv, a }, i) => {
    const d = scene.obstacles.map((o) => distanceTo(o, a));
    let nearest = 0;
    d.forEach((x, j) => { if (x.rho < d[nearest].rho) nearest = j; });
    const Frep = [0, 0];
    let Urep = 0, within = false;
    for (const { rho, grad } of d) {
      if (rho > field.rho0) continue;
      within = true;
      const k = field.eta * (1 / rho - 1 / field.rho0) / (rho * rho);
      Frep[0] += k * grad[0];
      Frep[1] += k * grad[1];
      Urep += 0.5 * field.eta * (1 / rho - 1 / field.rho0) ** 2;
    }
    const e = sub(a, goals[i]), len = norm(e);
    const katt = len <= field.switch ? field.zeta : field.switch * field.zeta / len;
    const Fatt = [-katt * e[0], -katt * e[1]];
    const F = [Fatt[0] + Frep[0], Fatt[1] + Frep[1]];
    const jt = (f) => [f[0], f[1], rv[0] * f[1] - rv[1] * f[0]];
    return { a, rv, rho: d[nearest].rho, grad: d[nearest].grad, nearest, within, Frep, Fatt, Urep, F,
             tau: jt(F), tauRep: jt(Frep), tauAtt: jt(Fatt) };
  });
  const sum = (key, n) => points.reduce((acc, p) => acc.map((x, k) => x + p[key][k]), new Array(n).fill(0));
  return { points, Frep: sum('Frep', 2), Fatt: sum('Fatt', 2), tau: sum('tau', 3), tauRep: sum('tauRep', 3),
           tauAtt: sum('tauAtt', 3) };
}

// The numbers in a shown text: "(-0.4, 0)" -> [-0.4, 0]; "(-0.05)" -> [-0.05].
const numbers = (text) => text.replace(/[()]/g, '').split(',').map((x) => {
  assert.match(x.trim(), /^-?\d+(\.\d+)?(e[-+]\d+)?$/, `a number in "${text}"`);
  return Number(x);
});
// A number shown to 4 significant digits is within half a unit of its 4th digit; a component
// shown as 0 is rounding noise next to the vector's largest (or exactly 0).
function assertShown(text, exact, what) {
  const shown = numbers(text);
  const want = Array.isArray(exact) ? exact : [exact];
  assert.equal(shown.length, want.length, `${what}: ${text}`);
  const big = Math.max(...want.map(Math.abs));
  shown.forEach((x, k) => {
    const tol = x === 0 ? 1e-9 * big : 5.0001e-4 * Math.abs(want[k]) + 1e-15;
    assert.ok(Math.abs(x - want[k]) <= tol, `${what}: shown ${text}, computed ${want}`);
  });
}
const closeTo = (a, b, what) => [a].flat().forEach((x, k) =>
  assert.ok(Math.abs(x - [b].flat()[k]) <= 1e-9 * Math.max(1, Math.abs([b].flat()[k])), `${what}: ${a} vs ${b}`));

// The lab's table and state at its configuration against the hand computation; returns it.
function checkTable(s, scene) {
  const hand = handComputed(scene, s.q, s.field);
  const t = s.forces_table;
  assert.equal(t.rows.length, hand.points.length);
  hand.points.forEach((p, i) => {
    const name = `a${String.fromCharCode(0x2081 + i)}`;  // a₁..a₄, as the handout and P13 count them
    const [label, rho, grad, Frep, Fatt, tau] = t.rows[i];
    const st = s.control_points[i];
    assert.equal(label, name);
    // The state's numbers, to rounding...
    closeTo(st.rho, p.rho, `${name} rho`);
    closeTo(st.grad_rho, p.grad, `${name} grad rho`);
    closeTo(st.F_rep, p.Frep, `${name} F_rep`);
    closeTo(st.F_att, p.Fatt, `${name} F_att`);
    closeTo(st.tau, p.tau, `${name} J^T F`);
    assert.equal(st.nearest_obstacle, p.nearest);
    assert.equal(st.within_rho0, p.within);
    // ...and the table as shown, to its 4 digits.
    assertShown(rho, p.rho, `${name} rho`);
    assertShown(grad, p.grad, `${name} grad rho`);
    if (p.within) assertShown(Frep, p.Frep, `${name} F_rep`);
    else assert.equal(Frep, '(0, 0) outside ρ₀', `${name} is beyond rho0: no push`);
    assertShown(Fatt, p.Fatt, `${name} F_att`);
    assertShown(tau, p.tau, `${name} J^T F`);
  });
  assert.equal(t.sum[0], 'Σ');
  assertShown(t.sum[3], hand.Frep, 'sum F_rep');
  assertShown(t.sum[4], hand.Fatt, 'sum F_att');
  assertShown(t.sum[5], hand.tau, 'tau');
  closeTo(s.F_rep, hand.Frep, 'F_rep');
  closeTo(s.F_att, hand.Fatt, 'F_att');
  closeTo(s.tau, hand.tau, 'tau');
  closeTo(s.tau_rep, hand.tauRep, 'tau_rep');
  closeTo(s.tau_att, hand.tauAtt, 'tau_att');
  const m = t.tau[0].match(/^τ = Σ J_i\^T F_i = τ_rep \+ τ_att = (\(.*?\)) \+ (\(.*?\)) = (\(.*?\))  \(F_x, F_y, torque\)$/);
  assert.ok(m, t.tau[0]);
  assertShown(m[1], hand.tauRep, 'tau_rep');
  assertShown(m[2], hand.tauAtt, 'tau_att');
  assertShown(m[3], hand.tau, 'tau');
  checkEquations(t, hand, s.field);
  return hand;
}

// (5.5), (5.6) and J^T F with the numbers put in, for the row chosen.
function checkEquations(t, hand, field) {
  const k = t.chosen, p = hand.points[k], name = `a${String.fromCharCode(0x2081 + k)}`;
  const [head, ...rest] = t.equations;
  const h = head.match(/^(\S+) = (\(.*?\)): nearest obstacle (\d+), ρ = (\S+), ∇ρ = (\(.*?\)); ρ₀ = (\S+), η = (\S+)$/);
  assert.ok(h, head);
  assert.equal(h[1], name);
  assertShown(h[2], p.a, `${name} position`);
  assert.equal(Number(h[3]), p.nearest);
  assertShown(h[4], p.rho, `${name} rho`);
  assertShown(h[5], p.grad, `${name} grad rho`);
  assertShown(h[6], field.rho0, 'rho0');
  assertShown(h[7], field.eta, 'eta');
  let i = 0;
  if (!p.within) {
    assert.equal(rest[i++], `ρ = ${h[4]} > ρ₀ = ${h[6]}: outside ρ₀, so (5.5) U_rep = 0 and (5.6) F_rep = (0, 0)`);
  } else {
    const d = 1 / p.rho - 1 / field.rho0;
    const u = rest[i++].match(/^\(5\.5\) U_rep = ½ η \(1\/ρ − 1\/ρ₀\)² = ½ · (\S+) · \(1\/(\S+) − 1\/(\S+)\)² = ½ · (\S+) · (\S+)² = (\S+)$/);
    assert.ok(u, rest[i - 1]);
    assertShown(u[1], field.eta, 'eta');
    assertShown(u[2], p.rho, 'rho');
    assertShown(u[3], field.rho0, 'rho0');
    assertShown(u[4], field.eta, 'eta');
    assertShown(u[5], d, '1/rho - 1/rho0');
    assertShown(u[6], p.Urep, 'U_rep');
    const f = rest[i++].match(/^\(5\.6\) F_rep = η \(1\/ρ − 1\/ρ₀\) \(1\/ρ²\) ∇ρ = (\S+) · \(1\/(\S+) − 1\/(\S+)\) · \(1\/(\S+)²\) · (\(.*?\)) = (\S+) · (\S+) · (\S+) · (\(.*?\)) = (\(.*?\))$/);
    assert.ok(f, rest[i - 1]);
    assertShown(f[4], p.rho, 'rho');
    assertShown(f[5], p.grad, 'grad rho');
    assertShown(f[7], d, '1/rho - 1/rho0');
    assertShown(f[8], 1 / (p.rho * p.rho), '1/rho^2');
    assertShown(f[10], p.Frep, 'F_rep');
  }
  const rv = rest[i++].match(/^R v = (\S+) − \(x, y\) = (\(.*?\));  F = F_att \+ F_rep = (\(.*?\)) \+ (\(.*?\)) = (\(.*?\))$/);
  assert.ok(rv, rest[i - 1]);
  assert.equal(rv[1], name);
  assertShown(rv[2], p.rv, 'R v');
  assertShown(rv[3], p.Fatt, 'F_att');
  if (p.within) assertShown(rv[4], p.Frep, 'F_rep');
  assertShown(rv[5], p.F, 'F');
  const jt = rest[i++].match(/^(\S+): J\^T F = \(F_x, F_y, \(R v\)_x F_y − \(R v\)_y F_x\) = \((\S+), (\S+), (\S+) · (\S+) − (\S+) · (\S+)\) = (\(.*?\))$/);
  assert.ok(jt, rest[i - 1]);
  assertShown(jt[2], p.F[0], 'F_x');
  assertShown(jt[3], p.F[1], 'F_y');
  assertShown(jt[4], p.rv[0], '(R v)_x');
  assertShown(jt[5], p.F[1], 'F_y');
  assertShown(jt[6], p.rv[1], '(R v)_y');
  assertShown(jt[7], p.F[0], 'F_x');
  assertShown(jt[8], p.tau, 'J^T F');
  assert.equal(i, rest.length, 'nothing else in the worked equations');
}

// The row of control point i, clicked with the mouse; the table stays where it was (its area
// has room for the longest equations, so the views above do not change size).
async function clickRow(page, i) {
  const { forces_layout: layout } = await api(page, 'state', { layout: true });
  const [x0, y0, , y1] = layout.rows[i];
  const box = await page.locator('canvas').boundingBox();
  await click(page, { x: box.x + x0 + 8, y: box.y + (y0 + y1) / 2 });
  await waitFrames(page, 2);
  assert.deepEqual((await api(page, 'state', { layout: true })).forces_layout.rows, layout.rows, 'the table did not move');
}

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

  // The table under the views, as shown, against P13 by hand. At the start two vertices are
  // within rho0 of the square and two are beyond every obstacle's: the table must show both.
  let hand = checkTable(s, scene);
  assert.deepEqual(hand.points.map((p) => p.within), [false, true, true, false], 'the start has both kinds of vertices');
  const hardest = hand.points.reduce((b, p, i) => (norm(p.Frep) > norm(hand.points[b].Frep) ? i : b), 0);
  assert.equal(s.forces_table.chosen, hardest, 'at first the equations are worked for the vertex pushed hardest');
  // Visible at 1280 x 800 without scrolling: the whole area fits and the table is not cut.
  const layout = (await api(page, 'state', { layout: true })).forces_layout;
  const canvas = await page.locator('canvas').boundingBox();
  assert.equal(layout.scrolls, false, 'the forces area needs no scrolling');
  assert.ok(layout.bottom <= canvas.height && layout.table_right <= layout.area_right, JSON.stringify(layout));
  // Click another row: its equations; a vertex beyond rho0 says so and shows no push.
  await clickRow(page, 2);
  s = await api(page, 'state');
  assert.equal(s.forces_table.chosen, 2);
  checkTable(s, scene);
  await screenshot(page, 'potential-p13-table.png');
  await clickRow(page, 0);
  s = await api(page, 'state');
  assert.equal(s.forces_table.chosen, 0);
  assert.match(s.forces_table.equations[1], /outside ρ₀/);
  checkTable(s, scene);
  assert.equal((await api(page, 'snapshot')).params.point, 0, 'the chosen row is a parameter (links keep it)');
  // Turned: a torque from every vertex's lever arm.
  await api(page, 'set_params', { params: { from: [0.5, 0.56, 0.4], point: 1 } });
  s = await api(page, 'state');
  assert.equal(s.from_free, true);
  hand = checkTable(s, scene);
  assert.ok(hand.points.filter((p) => p.within).length >= 1 && Math.abs(hand.tau[2]) > 1e-3, 'a torque');
  await api(page, 'set_params', { params: { from: scene.start, point: -1 } });

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
  // The table follows the drag: near both obstacles now.
  hand = checkTable(s, scene);
  assert.deepEqual(new Set(hand.points.filter((p) => p.within).map((p) => p.nearest)), new Set([0, 1]),
                   'vertices within rho0 of each obstacle');

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
  // Drawn there: the robot (the lab's blue) in the cup, the cup's walls filled (over the heat map).
  await expectView(page, browser, 'potential-cup-stuck.png', [
    ...sceneProbes(cup, { free: 0, markers: false }),
    // (its control point: a dark dot, 3 px across its centre, in a blue ring; the heat map is
    // nowhere as dark)
    { at: stuck, look: 'dark', why: 'the robot where the descent stopped' },
    { at: stuck, dx: 2, look: 'dark', why: 'the robot where the descent stopped' },
  ]);
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

// A 900 px wide embed: the table fits its width (the area under the views scrolls, in its own
// box, when the embed is short) and shows the same numbers.
test('potential fields: the forces table in a 900 px embed', () => withBrowser(async ({ browser, url }) => {
  const page = await browser.newPage({ viewport: { width: 1000, height: 760 } });
  const errors = collectErrors(page);
  await page.route(url + 'host.html', (route) => route.fulfill({ contentType: 'text/html', body:
    '<!doctype html><meta charset="utf-8"><body style="margin:0"><iframe src="embed.html?lesson=potential&amp;scene=p13" ' +
    'style="border:0;width:900px;height:700px;display:block" title="lab"></iframe></body>' }));
  await page.goto(url + 'host.html');
  const frame = await (await page.waitForSelector('iframe')).contentFrame();
  await frame.waitForFunction(() => window.cspacelab && window.cspacelab.status().frames >= 2, null, { timeout: 30000 });
  await waitFrames(frame, 4);
  const s = await frame.evaluate(() => window.cspacelab.call('state', { layout: true }));
  checkTable(s, await frame.evaluate(() => window.cspacelab.call('get_scene', {})));
  const { forces_layout: layout } = s;
  assert.ok(layout.table_right <= layout.area_right, `the table is not cut: ${JSON.stringify(layout)}`);
  assert.ok(layout.rows.every((r) => r[3] <= 700), 'every row on screen');
  await screenshot(page, 'potential-embed-900.png');
  assert.deepEqual(errors, []);
}));

// "Descend from the start" descends (issue 21): pressed with the mouse it puts the robot back at
// the start and plays the descent, as the button says; it used to move the robot and wait.
test('potential fields: "Descend from the start" starts the descent', () => withPage(async ({ page }) => {
  await api(page, 'select_lesson', { id: 'potential' });
  await waitFrames(page, 2);
  const scene = await api(page, 'get_scene');
  // Somewhere else first, as a student who dragged the robot away.
  await api(page, 'set_params', { params: { from: [scene.start[0] + 0.05, scene.start[1] - 0.05, scene.start[2]] } });
  await waitFrames(page, 2);
  const before = await api(page, 'state');
  assert.notDeepEqual(before.from, scene.start);
  assert.equal(before.steps, 0);
  await click(page, await pageButton(page, 'potential-descend'));
  await page.waitForFunction(() => window.cspacelab.call('state', {}).steps >= 10, null, { timeout: 20000 });
  const s = await api(page, 'state');
  assert.deepEqual(s.from, scene.start, 'from the scene\'s start');
  assert.deepEqual(s.descent.trajectory[0], scene.start);
  // It went downhill: the potential where it stands is below the start's.
  await api(page, 'set_params', { params: { from: scene.start } });
  const atStart = (await api(page, 'state')).U;
  assert.ok(s.descent.U < atStart, `U ${s.descent.U} after ${s.descent.steps} steps, ${atStart} at the start`);
}));
