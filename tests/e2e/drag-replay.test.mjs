// Dragging an obstacle replays the planner to the student's step on every frame, so the roadmap
// follows the drag. After a large run one replay takes longer than a frame; then the roadmap of
// the scene before the drag stays (faded) until the release, which replays once. Either way the
// roadmap after the release is the one a fresh planner in the new scene grows in as many steps
// (which may stop short of the end: the new scene's run can take more steps).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, worldToPage, waitFrames, keys, api, screenshot, hold, chord, expectView } from './lib/harness.mjs';

const DISK = { type: 'disk', center: [0.5, 0.5], radius: 0.1 };
const SCENE = { version: 1, start: [0.05, 0.05], goal: [0.95, 0.95], obstacles: [DISK] };

// The roadmap hash of a fresh planner for `scene` run to `steps` (a new scene starts at step 0).
async function freshHash(page, scene, steps) {
  await api(page, 'set_scene', { scene });
  await api(page, 'run_to', { steps });
  const s = await api(page, 'state');
  return (s.prm || s).roadmap_hash;
}

async function startRun(page, params) {
  await api(page, 'select_lesson', { id: 'step-prm' });
  await api(page, 'set_scene', { scene: SCENE });
  await api(page, 'set_params', { params });
  await api(page, 'run');
  await keys(page, 'v');  // the select tool: a press on the disk moves it
  await waitFrames(page, 2);
  return api(page, 'state');
}

// The torus lesson after 5000 samples (over the live-replay budget), the select tool on.
async function startTorusRun(page) {
  await api(page, 'select_lesson', { id: 'torus' });
  await api(page, 'set_params', { params: { samples: 5000, neighbors: 'k:10', seed: 2 } });
  await api(page, 'run');
  await keys(page, 'v');
  await waitFrames(page, 2);
  return { scene: await api(page, 'get_scene'), before: await api(page, 'state') };
}

test('after a large run, a drag keeps the old roadmap until the release, then replays once',
  () => withPage({ viewport: { width: 1100, height: 720 } }, async ({ page, browser }) => {
  const before = await startRun(page, { samples: 6000, neighbors: 'k:10', seed: 3 });
  assert.equal(before.done, true);
  assert.equal(before.replay_pending, false);
  const [from, to] = await worldToPage(page, [DISK.center, [0.62, 0.55]]);
  await hold(page, from, to, { steps: 4, frames: 2, each: async (i) => {
    const s = await api(page, 'state');
    assert.equal(s.replay_pending, true, `step ${i} of the drag: the replay waits`);
    assert.equal(s.roadmap_hash, before.roadmap_hash, 'the roadmap is the one from before the drag');
    const centre = (await api(page, 'get_scene')).obstacles[0].center;
    assert.ok(Math.abs(centre[0] - (0.5 + 0.12 * i / 4)) < 0.01, `the disk follows the mouse: ${centre}`);
  } });
  // The picture while the button is held: the old roadmap under a white veil, the disk drawn
  // where it is now (over the veil), and where it was, nothing (the roadmap went round it).
  const old = (await api(page, 'state', { roadmap: true })).vertices.slice(2)
    .filter((v) => Math.hypot(v[0] - 0.62, v[1] - 0.55) > 0.16 && Math.hypot(v[0] - 0.5, v[1] - 0.5) > 0.13 && v[1] < 0.85)
    .filter((_, i) => i % 97 === 0).slice(0, 12);
  assert.ok(old.length >= 8);
  await expectView(page, browser, 'drag-replay-pending.png', [
    { at: [0.62, 0.55], look: ([r, g, b]) => Math.min(r, g, b) < 170, why: 'the disk, where the mouse has it' },
    { at: [0.44, 0.47], look: 'canvas', why: 'where the disk was: no roadmap there' },
    ...old.map((v) => ({ at: v, look: 'faded', why: 'a vertex of the old roadmap, faded' })),
  ], 'workspace', { keepMouse: true });
  await page.mouse.up();
  await waitFrames(page, 2);

  const after = await api(page, 'state');
  assert.equal(after.replay_pending, false, 'replayed at the release');
  assert.ok(after.steps <= before.steps && (after.steps === before.steps || after.done), 'at the same step');
  assert.notEqual(after.roadmap_hash, before.roadmap_hash, 'the moved disk changed the roadmap');
  const moved = await api(page, 'get_scene');
  assert.ok(Math.abs(moved.obstacles[0].center[0] - 0.62) < 0.01, `the disk moved: ${moved.obstacles[0].center}`);
  assert.equal(await freshHash(page, moved, after.steps), after.roadmap_hash, 'the replay grew what a fresh run grows');

  // Undo in the middle of such a drag ends it, and replays at once (the button is still down)
  // the scene it restores; the mouse moving on moves nothing.
  const [back] = await worldToPage(page, [moved.obstacles[0].center]);
  await hold(page, back, from, { steps: 2, frames: 2 });
  assert.equal((await api(page, 'state')).replay_pending, true);
  await api(page, 'undo');
  await waitFrames(page, 2);
  const undone = await api(page, 'state');
  assert.equal(undone.replay_pending, false, 'replayed at the undo');
  assert.equal(undone.roadmap_hash, after.roadmap_hash, 'the roadmap of the restored scene');
  assert.deepEqual((await api(page, 'get_scene')).obstacles[0].center, moved.obstacles[0].center, 'the drag undone');
  await page.mouse.move(to.x, from.y);
  await waitFrames(page, 2);
  await page.mouse.up();
  await waitFrames(page, 2);
  assert.deepEqual((await api(page, 'get_scene')).obstacles[0].center, moved.obstacles[0].center, 'the drag stays ended');
  assert.equal((await api(page, 'state')).roadmap_hash, after.roadmap_hash);
}));

test('after a small run, the roadmap follows the drag live',
  () => withPage({ viewport: { width: 1100, height: 720 } }, async ({ page }) => {
  const before = await startRun(page, { samples: 400, neighbors: 'k:10', seed: 3 });
  const [from, to] = await worldToPage(page, [DISK.center, [0.62, 0.55]]);
  const seen = new Set([before.roadmap_hash]);
  await hold(page, from, to, { steps: 4, frames: 2, each: async () => {
    const s = await api(page, 'state');
    assert.equal(s.replay_pending, false, 'replayed on every frame');
    seen.add(s.roadmap_hash);
  } });
  await page.mouse.up();
  await waitFrames(page, 2);
  assert.ok(seen.size >= 3, `the roadmap changed during the drag: ${seen.size} roadmaps`);
  const moved = await api(page, 'get_scene');
  const after = await api(page, 'state');
  assert.equal(await freshHash(page, moved, after.steps), after.roadmap_hash);
}));

test('the torus lesson: the C-obstacles follow the drag, the replay waits for the release',
  () => withPage({ viewport: { width: 1280, height: 800 } }, async ({ page }) => {
  const { scene, before } = await startTorusRun(page);
  assert.equal(before.prm.replay_pending, false);
  const disk = scene.obstacles[0];
  const [from, to] = await worldToPage(page, [disk.center, [disk.center[0] - 0.12, disk.center[1] + 0.1]], 'workspace');
  const fractions = new Set([before.free_fraction]);
  await hold(page, from, to, { steps: 4, frames: 2, each: async () => {
    const s = await api(page, 'state');
    assert.equal(s.prm.replay_pending, true);
    assert.equal(s.prm.roadmap_hash, before.prm.roadmap_hash);
    fractions.add(s.free_fraction);
  } });
  assert.ok(fractions.size >= 2, 'the C-obstacle map changed during the drag');
  await page.mouse.up();
  await waitFrames(page, 2);
  const after = await api(page, 'state');
  assert.equal(after.prm.replay_pending, false);
  assert.notEqual(after.prm.roadmap_hash, before.prm.roadmap_hash);
  const moved = await api(page, 'get_scene');
  assert.equal(await freshHash(page, moved, after.prm.steps), after.prm.roadmap_hash, 'the replay grew what a fresh run grows');
}));

// What a drag moves follows the mouse's offset from the press, from where it was then: a press
// that does not move changes nothing, and coming back to the press point restores the scene bit
// for bit, so the planner that ran in it is kept rather than replayed.
test('a press without a move, or a drag back to where it was pressed, replays nothing',
  () => withPage({ viewport: { width: 1100, height: 720 } }, async ({ page, browser }) => {
  const before = await startRun(page, { samples: 6000, neighbors: 'k:10', seed: 3 });
  // Off the centre: the old editor moved a pressed disk's centre to the cursor.
  const [from, to] = await worldToPage(page, [[0.53, 0.48], [0.62, 0.55]]);
  const unchanged = async (what) => {
    const s = await api(page, 'state');
    assert.equal(s.replay_pending, false, `${what}: nothing waits`);
    assert.equal(s.planner_builds, before.planner_builds, `${what}: no planner built`);
    assert.equal(s.roadmap_hash, before.roadmap_hash);
    assert.deepEqual((await api(page, 'get_scene')).obstacles, [DISK], `${what}: the disk is where it was`);
  };
  await hold(page, from, from, { steps: 1, frames: 3 });
  await unchanged('pressed');
  await page.mouse.up();
  await waitFrames(page, 2);
  await unchanged('released');

  await hold(page, from, to, { steps: 3, frames: 2 });
  assert.equal((await api(page, 'state')).replay_pending, true, 'moved: the replay waits');
  await page.mouse.move(from.x, from.y, { steps: 3 });
  await waitFrames(page, 2);
  await unchanged('back at the press point');
  await page.mouse.up();
  await waitFrames(page, 2);
  await unchanged('released there');
  // The drags added no undo step: undo takes back the scene's loading, the last edit before them.
  assert.equal(await api(page, 'undo'), true);
  assert.notDeepEqual((await api(page, 'get_scene')).obstacles, [DISK], 'undo went past the drags');

  // A small run replays live; pressing without moving builds no planner there either.
  const small = await startRun(page, { samples: 400, neighbors: 'k:10', seed: 3 });
  await hold(page, from, from, { steps: 1, frames: 3 });
  await page.mouse.up();
  await waitFrames(page, 2);
  assert.equal((await api(page, 'state')).planner_builds, small.planner_builds);
}));

test('the torus lesson: a drag out and back keeps the planner; a press beside a C-space marker moves nothing',
  () => withPage({ viewport: { width: 1280, height: 800 } }, async ({ page }) => {
  const { scene, before } = await startTorusRun(page);
  const disk = scene.obstacles[0];
  const [from, to] = await worldToPage(page, [disk.center, [disk.center[0] - 0.12, disk.center[1] + 0.1]], 'workspace');
  await hold(page, from, to, { steps: 3, frames: 2 });
  assert.equal((await api(page, 'state')).prm.replay_pending, true);
  await page.mouse.move(from.x, from.y, { steps: 3 });
  await waitFrames(page, 2);
  await page.mouse.up();
  await waitFrames(page, 2);
  let s = await api(page, 'state');
  assert.equal(s.prm.replay_pending, false);
  assert.equal(s.prm.planner_builds, before.prm.planner_builds, 'no planner built: the scene is the one it ran in');
  assert.equal(s.prm.roadmap_hash, before.prm.roadmap_hash);
  assert.equal(s.free_fraction, before.free_fraction, 'the C-obstacle map of that scene again');
  assert.deepEqual(await api(page, 'get_scene'), scene);

  // A press 5 pixels beside the start marker in the C-space square, without moving.
  const [start] = await worldToPage(page, [scene.start], 'cspace');
  await hold(page, { x: start.x + 5, y: start.y }, { x: start.x + 5, y: start.y }, { steps: 1, frames: 3 });
  await page.mouse.up();
  await waitFrames(page, 2);
  s = await api(page, 'state');
  assert.deepEqual((await api(page, 'get_scene')).start, scene.start, 'the marker did not jump to the cursor');
  assert.equal(s.prm.planner_builds, before.prm.planner_builds, 'and the run was not restarted');
  assert.equal(s.prm.steps, before.prm.steps);
}));

// Issue 21: a finished run in the torus lesson, an obstacle dragged over the start arm (the start
// in collision ends every replay at step 1 while it is there) and on: the run comes back to its
// step after the drag, and Ctrl+Z gives back the run from before it, not a run of one step.
test('the torus lesson: a drag across the start keeps the student\'s step; undo brings the run back',
  () => withPage({ viewport: { width: 1280, height: 800 } }, async ({ page }) => {
  await api(page, 'select_lesson', { id: 'torus' });
  await api(page, 'run');
  const before = await api(page, 'state');
  assert.equal(before.prm.phase, 'done');
  await keys(page, 'v');
  await waitFrames(page, 2);
  const scene = await api(page, 'get_scene');
  const disk = scene.obstacles[0];
  // Over link 1 of the start pose (theta1 = 0.2 from the base at (0.5, 0.5), 0.25 long), then away.
  const elbow = [0.5 + 0.25 * Math.cos(0.2) * 0.6, 0.5 + 0.25 * Math.sin(0.2) * 0.6];
  const [from, over, away] = await worldToPage(page, [disk.center, elbow, [0.9, 0.95]], 'workspace');
  await hold(page, from, over, { steps: 4, frames: 2 });
  const crossing = await api(page, 'state');
  assert.equal(crossing.q_free !== undefined, true);
  assert.ok(crossing.prm.steps <= 2, `over the start arm the run ends at once (step ${crossing.prm.steps})`);
  await page.mouse.move(away.x, away.y, { steps: 4 });
  await waitFrames(page, 3);
  await page.mouse.up();
  await waitFrames(page, 3);
  const after = await api(page, 'state');
  assert.ok(after.prm.steps === before.prm.steps || after.prm.phase === 'done', `back at the student's step: ${after.prm.steps}`);
  assert.ok(after.prm.steps > 2, 'not the one-step run of the frames over the start');
  await chord(page, 'Control', 'z');
  const undone = await api(page, 'state');
  assert.deepEqual(await api(page, 'get_scene'), scene, 'the drag undone');
  assert.equal(undone.prm.steps, before.prm.steps, 'the whole run is back');
  assert.equal(undone.prm.roadmap_hash, before.prm.roadmap_hash);
}));
