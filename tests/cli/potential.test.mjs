// cspacelab potential and descend (and plan --connector potential): P13's numbers, tau = J^T F in
// the output, the cup's local minimum and its escape, determinism, and every kind of bad input.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { json, fails, scene, tempScene } from './lib/cli.mjs';

const P13 = scene('p13.json');
const CUP = scene('potential-cup.json');
const close = (a, b, tol = 1e-9) => assert.ok(Math.abs(a - b) <= tol * Math.max(1, Math.abs(b)), `${a} != ${b}`);

test('P13: repulsion at the four vertices, net force and torque (computed by hand)', () => {
  const r = json('potential', P13, '--at', '0.5,0.56,0', '--rho0', '0.15', '--eta', '0.001');
  assert.equal(r.robot, 'polygon');
  assert.deepEqual(r.params, { zeta: 1, switch: 0.2, eta: 0.001, rho0: 0.15 });
  assert.equal(r.in_collision, false);
  const [a1, a2, a3, a4] = r.control_points;
  assert.deepEqual(r.control_points.map((p) => p.name), ['vertex 0', 'vertex 1', 'vertex 2', 'vertex 3']);
  assert.deepEqual(a1.position, [0.4, 0.51]);
  assert.deepEqual(a1.repulsive, []);  // 0.25 and 0.24 away: outside both regions of influence
  assert.deepEqual(a1.F_rep, [0, 0]);
  // a2: the square's left edge, 0.05 away.
  assert.equal(a2.nearest_obstacle, 0);
  assert.equal(a2.obstacle_type, 'polygon');
  close(a2.rho, 0.05);
  assert.deepEqual(a2.grad_rho, [-1, 0]);
  close(a2.F_rep[0], -5.333333333);
  close(a2.U_rep, 0.0888888889);
  // a3: the square's corner (0.65, 0.55).
  assert.deepEqual(a3.nearest_point, [0.65, 0.55]);
  close(a3.rho, Math.hypot(0.05, 0.06));
  close(a3.F_rep[0], -0.6440697236);
  close(a3.F_rep[1], 0.7728836683);
  // a4: the triangle's vertex (0.4, 0.75), 0.14 away.
  assert.equal(a4.nearest_obstacle, 1);
  close(a4.rho, 0.14);
  assert.deepEqual(a4.grad_rho, [0, -1]);
  close(a4.F_rep[1], -0.0242954325);
  for (const p of r.control_points) assert.ok(p.repulsive.length <= 1);  // regions apart
  close(r.totals.F_rep[0], -5.97740305689);
  close(r.totals.F_rep[1], 0.748588235813);
  close(r.generalized_force.tau_rep[2], -0.154745270416);
  close(r.totals.U_rep, 0.107833782955);
  // The named generalized force is tau; tau is the sum of the control points' J^T F.
  assert.deepEqual(r.generalized_force.force, r.generalized_force.tau.slice(0, 2));
  assert.equal(r.generalized_force.torque, r.generalized_force.tau[2]);
  const sum = [0, 0, 0];
  for (const p of r.control_points) {
    const f = [p.F_att[0] + p.F_rep[0], p.F_att[1] + p.F_rep[1]];
    for (let k = 0; k < 3; ++k) {
      const jt = p.jacobian[0][k] * f[0] + p.jacobian[1][k] * f[1];
      close(p.tau[k], jt, 1e-12);
      sum[k] += jt;
    }
  }
  for (let k = 0; k < 3; ++k) close(r.generalized_force.tau[k], sum[k], 1e-12);
  // Attraction toward the vertices' places at the goal (the scene's goal by default).
  assert.deepEqual(r.goal, [0.2, 0.25, 0.5]);
  for (const p of r.control_points) {
    const e = Math.hypot(p.position[0] - p.goal_position[0], p.position[1] - p.goal_position[1]);
    close(Math.hypot(...p.F_att), e <= 0.2 ? e : 0.2, 1e-12);  // conic beyond d: |F| = d zeta
  }
});

test('the arm: joint torques; a point robot: the force itself; no obstacles: rho is null', () => {
  const arm = json('potential', scene('arm-2link.json'), '--at', '0.5,0.5');
  assert.deepEqual(arm.control_points.map((p) => p.name), ['elbow', 'tip']);
  assert.deepEqual(arm.generalized_force.torques, arm.generalized_force.tau);
  assert.equal(arm.control_points[0].jacobian[0][1], 0);  // the elbow does not move with theta2
  const empty = tempScene({ version: 1, goal: [0.9, 0.5] });
  const r = json('potential', empty, '--at', '0.5,0.5', '--zeta', '2', '--switch', '0.5');
  assert.equal(r.control_points[0].rho, null);
  assert.equal(r.control_points[0].nearest_obstacle, null);
  close(r.control_points[0].F_att[0], 0.8);  // quadratic: -zeta e
  close(r.control_points[0].F_att[1], 0);
  close(r.totals.U, 0.16);
  for (let k = 0; k < 2; ++k) close(r.generalized_force.force[k], r.control_points[0].F_att[k]);  // J = I
  const other = json('potential', empty, '--at', '0.5,0.5', '--goal', '0.1,0.5');
  close(other.control_points[0].F_att[0], -0.2);  // conic: length d zeta = 0.2
  close(other.control_points[0].F_att[1], 0);
});

test('inside an obstacle: in collision, the potential infinite (null), grad rho the way out', () => {
  const r = json('potential', CUP, '--at', '0.35,0.5');
  assert.equal(r.in_collision, true);
  assert.equal(r.contact, true);
  const p = r.control_points[0];
  assert.equal(p.inside, true);
  assert.equal(p.rho, 0);
  assert.equal(p.U_rep, null);
  assert.equal(r.totals.U, null);
  assert.equal(p.grad_rho.length, 2);
});

test('descend: the cup traps plain descent; random walks get out, the same way every time', () => {
  const plain = json('descend', CUP);
  assert.equal(plain.outcome, 'local_minimum');
  assert.equal(plain.local_minima, 1);
  assert.equal(plain.escapes_used, 0);
  assert.ok(plain.final[1] > 0.5 && plain.final[1] < 0.6, `stuck under the cup's ceiling at ${plain.final}`);
  assert.deepEqual(plain.trajectory[0], [0.52, 0.2]);
  assert.deepEqual(plain.trajectory.at(-1), plain.final);
  assert.equal(plain.trajectory.length, plain.descent_steps + 1);

  const args = ['descend', CUP, '--escapes', '10', '--seed', '2', '--events'];
  const r = json(...args);
  assert.equal(r.outcome, 'escaped');
  assert.ok(r.distance_to_goal <= 0.01);
  assert.ok(r.escapes_used >= 1);
  assert.equal(r.walk_steps, 40 * r.escapes_used);
  assert.equal(r.trajectory.length, 1 + r.descent_steps + r.walk_steps);
  for (let i = 0; i + 1 < r.trajectory.length; ++i) {
    const [a, b] = [r.trajectory[i], r.trajectory[i + 1]];
    assert.ok(Math.hypot(b[0] - a[0], b[1] - a[1]) <= 0.1 * Math.SQRT2 + 1e-12);
  }
  const kinds = r.events.map((e) => e.kind);
  assert.equal(kinds.filter((k) => k === 'local_minimum').length, r.escapes_used);
  assert.equal(kinds.at(-1), 'reached_goal');
  assert.equal(r.events.length, r.steps);
  assert.deepEqual(json(...args), r);  // seeded
  assert.notDeepEqual(json('descend', CUP, '--escapes', '10', '--seed', '3').trajectory, r.trajectory);
});

test('descend: the goal in P13 and on the arm; a step budget', () => {
  const p13 = json('descend', P13);
  assert.equal(p13.outcome, 'goal');
  assert.ok(p13.distance_to_goal <= 0.01);
  const arm = json('descend', scene('arm-2link.json'), '--step', '0.05', '--tolerance', '0.02');
  assert.equal(arm.outcome, 'goal');
  assert.equal(arm.descent.step, 0.05);
  const short = json('descend', P13, '--max-steps', '3');
  assert.equal(short.outcome, 'max_steps');
  assert.equal(short.trajectory.length, 4);
  const to = json('descend', P13, '--from', '0.3,0.3,0', '--to', '0.5,0.15,1');
  assert.deepEqual(to.to, [0.5, 0.15, 1]);
  assert.equal(to.outcome, 'goal');
});

test('plan --connector potential: edges are descents, the path runs through their waypoints', () => {
  const r = json('plan', scene('prm-demo.json'), '--connector', 'potential', '--samples', '150');
  assert.equal(r.connector, 'potential');
  assert.equal(r.solved, true);
  assert.deepEqual(r.path[0], [0.05, 0.05]);
  assert.deepEqual(r.path.at(-1), [0.95, 0.95]);
  let length = 0;
  for (let i = 0; i + 1 < r.path.length; ++i) {
    const d = Math.hypot(r.path[i + 1][0] - r.path[i][0], r.path[i + 1][1] - r.path[i][1]);
    assert.ok(d <= 0.02 + 1e-12, `a piece of ${d}: steps of 0.01, the last of an edge up to 0.02`);
    length += d;
  }
  close(r.path_length, length, 1e-12);
  const straight = json('plan', scene('prm-demo.json'), '--samples', '150');
  assert.equal(straight.connector, 'straight');
  assert.notEqual(straight.roadmap_hash, r.roadmap_hash);
  assert.deepEqual(json('plan', scene('prm-demo.json'), '--samples', '150', '--connector', 'straight').roadmap_hash,
                   straight.roadmap_hash);
  fails(/--connector: 'bent' is not straight or potential/, 'plan', scene('prm-demo.json'), '--connector', 'bent');
});

test('bad input: one line naming the problem, exit status 2', () => {
  fails(/missing --at Q/, 'potential', P13);
  fails(/--at: expected 3 comma-separated numbers for robot type 'polygon', got 2/, 'potential', P13, '--at', '0.5,0.5');
  fails(/--rho0: '0' is not a number > 0/, 'potential', P13, '--at', '0.5,0.5,0', '--rho0', '0');
  fails(/--eta: '-1' is not a number >= 0/, 'potential', P13, '--at', '0.5,0.5,0', '--eta', '-1');
  fails(/--switch: 'x' is not a finite number/, 'potential', P13, '--at', '0.5,0.5,0', '--switch', 'x');
  fails(/--goal: .* lies outside the workspace/, 'potential', P13, '--at', '0.5,0.5,0', '--goal', '2,2,0');
  fails(/unknown option --escapes/, 'potential', P13, '--at', '0.5,0.5,0', '--escapes', '3');
  fails(/nope\.json: cannot read file/, 'potential', 'nope.json', '--at', '0,0');
  fails(/the start is in collision with obstacles\[0\] \(a polygon\)/, 'descend', CUP, '--from', '0.35,0.5');
  fails(/the goal is in collision with obstacles\[0\]/, 'descend', CUP, '--to', '0.5,0.65');
  fails(/--step: '-0.1' is not a number > 0/, 'descend', CUP, '--step', '-0.1');
  fails(/--max-steps: '1000000' is not an integer in \[0, 100000\]/, 'descend', CUP, '--max-steps', '1000000');
  fails(/--walk-steps: '0' is not an integer in \[1, 10000\]/, 'descend', CUP, '--walk-steps', '0');
  fails(/--escapes: 'two' is not an integer in \[0, 10000\]/, 'descend', CUP, '--escapes', 'two');
  fails(/--tolerance: must be >= 0/, 'descend', CUP, '--tolerance', '-1');
  fails(/unexpected argument 'extra'/, 'descend', CUP, 'extra');
});
