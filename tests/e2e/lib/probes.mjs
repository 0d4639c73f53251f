// Probes of the lessons' main views, computed from their state as the handout's geometry and
// formulas say (for tests/e2e/lib/harness.mjs's expectView): one builder per picture, shared by
// the tests of the lesson and those that only open it (the homework map).
import assert from 'node:assert/strict';
import { api, sceneProbes, stroke } from './harness.mjs';

// Probes of P9's square from the state's point and gap: the left half and the cone through the
// gap shaded (sky blue over white), the rest of the right half white; away from the rays, the
// wall, the grid lines and the point's marker. The Monte Carlo samples are dots of 2 px: up to
// 3000 over the square cover about 3 % of it, so a few probes may land on one.
export function p9Probes({ x, y, gap }) {
  const lo = 0.5 - gap / 2, hi = 0.5 + gap / 2;
  const ray = (end, px) => end + (end - y) / (0.5 - x) * (px - 0.5);
  const shaded = ([r, g, b]) => b - r >= 20 && r >= 150;
  const probes = [];
  for (let i = 0; i < 12; ++i) for (let j = 0; j < 12; ++j) {
    const p = [(i + 0.5) / 12 + 0.013, (j + 0.5) / 12 + 0.011];
    const near = (a, b) => Math.abs(a - b) < 0.02;
    if (near(p[0], 0.5) || Math.hypot(p[0] - x, p[1] - y) < 0.05) continue;
    if (p[0] > 0.5 && [ray(lo, p[0]), ray(hi, p[0])].some((v) => near(v, p[1]))) continue;
    const seen = p[0] < 0.5 || (p[1] >= ray(lo, p[0]) && p[1] <= ray(hi, p[0]));
    probes.push({ at: p, look: seen ? shaded : 'canvas', why: seen ? 'in sight' : 'out of sight' });
  }
  return probes;
}

// Probes of the bound plot from the state's L, r, mu(F) and d = 2, by the handout's formulas:
// the path bound m e^(-sigma r^2 n), m = ceil(L/(r/2)), sigma = pi/(4 mu(F)) (blue); P8's
// whole-square bound with m = N^2 balls (orange); refined, the N^2 - B inner balls at that rate,
// the 4(N - 2) along an edge at half of it, the 4 corners at a quarter (purple). Each at a few n
// where it lies inside the plot (1e-3 to 0.5), off the target line and the other curves.
export function boundProbes(s) {
  assert.equal(s.dimension, 2);
  const rate = Math.PI / (4 * s.free_volume) * s.clearance ** 2;
  const N = Math.ceil(2 / s.clearance);
  const curves = [
    [(n) => Math.ceil(s.length / (s.clearance / 2)) * Math.exp(-rate * Math.round(n)), [0, 114, 178], 'the path bound'],
    [(n) => N * N * Math.exp(-rate * n), [230, 159, 0], "P8's bound"],
    [(n) => (N - 2) ** 2 * Math.exp(-rate * n) + 4 * (N - 2) * Math.exp(-rate * n / 2) + 4 * Math.exp(-rate * n / 4),
     [204, 121, 167], 'P8 refined'],
  ];
  const probes = [];
  for (const [f, look, why] of curves) {
    let taken = 0;
    for (let n = 100; n < 1e6 && taken < 3; n *= 1.17) {
      const v = f(n);
      if (v < 1e-3 || v > 0.5 || Math.abs(Math.log10(v / s.target)) < 0.2) continue;
      // Clear of the other curves by a factor of 3 at this n (they would draw over it).
      if (curves.some(([g]) => g !== f && Math.abs(Math.log10(g(n) / v)) < 0.5)) continue;
      probes.push({ at: [n, v], look: stroke(look), why: `${why} at n = ${Math.round(n)}` });
      ++taken;
    }
    assert.ok(taken >= 2, `${why}: ${taken} probes`);
  }
  return probes;
}

// The probes of whatever lesson is on screen (`page`: a page, or the frame holding the lab):
// {view, probes, misses}. Lessons with a scene: its
// obstacles and markers (what else is drawn over free space depends on the step); the analysis
// lesson: its plot or P9's square; Distances: the short arc on the circle, or the disk and the
// distance drawn between rim and segment. Null for the C-space notation lesson, whose picture
// is compared with references in notation.test.mjs.
export async function lessonProbes(page) {
  const { lesson } = await api(page, 'status');
  const s = await api(page, 'state');
  if (lesson === 'notation') return null;
  if (lesson === 'analysis')
    return s.tab === 'visibility' ? { view: 'p9', probes: p9Probes(s.visibility), misses: 5 } : { view: 'bound', probes: boundProbes(s) };
  if (lesson === 'distances') {
    if ((await api(page, 'snapshot')).params.tool === 's1') {
      // Halfway along the short way from q1 to q2 (orange), on the unit circle.
      const d = Math.atan2(Math.sin(s.q2 - s.q1), Math.cos(s.q2 - s.q1));
      const mid = s.q1 + d / 2;
      return { view: 'circle', probes: [{ at: [Math.cos(mid), Math.sin(mid)], look: stroke([230, 159, 0]), why: 'the short arc' }] };
    }
    // The disk (centre q, radius r) filled, on the side of its centre away from the segment.
    const { q: [qx, qy], closest: c, r } = s.segment;
    const away = Math.hypot(qx - c[0], qy - c[1]) || 1;
    const inside = [qx + (qx - c[0]) / away * r * 0.5, qy + (qy - c[1]) / away * r * 0.5];
    return { view: 'workspace', probes: [{ at: inside, look: ([R, , B]) => R < 225 && Math.abs(R - B) < 30, why: 'inside the disk' }] };
  }
  const scene = await api(page, 'get_scene');
  return { view: 'workspace', probes: sceneProbes(scene, { free: 0 }) };
}

// Probes of the torus lesson's square from its exact C-obstacle map (state's blocked_at, asked
// at a 16 x 16 grid and a little way around each point): a C-obstacle where the map is blocked
// all around, free C-space where it is free all around (`free: false` leaves those out, when a
// roadmap covers it), away from `avoid` (configurations where markers, the arm's dot or a trail
// are drawn: within 0.35 rad) and from the rows `rows` (a loop's trail along theta2 = const).
export async function cspaceProbes(page, { free = true, avoid = [], rows = [] } = {}) {
  const grid = [];
  for (let i = 0; i < 16; ++i) for (let j = 0; j < 16; ++j) grid.push([-Math.PI + (i + 0.5) * Math.PI / 8, -Math.PI + (j + 0.5) * Math.PI / 8]);
  const cross = (p) => [p, [p[0] + 0.1, p[1]], [p[0] - 0.1, p[1]], [p[0], p[1] + 0.1], [p[0], p[1] - 0.1]];
  const blocked = (await api(page, 'state', { blocked_at: grid.flatMap(cross) })).blocked_at;
  const probes = [];
  grid.forEach((p, k) => {
    const five = blocked.slice(5 * k, 5 * k + 5);
    if (five.some((b) => b !== five[0]) || (!five[0] && !free)) return;  // near a C-obstacle's edge
    if (avoid.some((m) => Math.hypot(p[0] - m[0], p[1] - m[1]) < 0.35)) return;
    if (rows.some((y) => Math.abs(p[1] - y) < 0.2)) return;
    probes.push({ at: p, look: five[0] ? 'cobstacle' : 'canvas', why: five[0] ? 'a C-obstacle' : 'free C-space' });
  });
  assert.ok(probes.filter((p) => p.look === 'cobstacle').length >= 5, `${probes.length} probes`);
  return probes;
}
