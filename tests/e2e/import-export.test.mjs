// Import and export through the app's File menu (real clicks): the scene as JSON (download, then
// upload through the file picker and by dropping it on the canvas), a PNG of the view, and the
// roadmap with its path. Invalid files say why in the app and change nothing.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { withPage, click, waitFrames, api, pageButton, worldToPage, screenshot, inspectPng, expectView,
         sceneProbes } from './lib/harness.mjs';

async function menu(page, item) {
  await click(page, await pageButton(page, 'file'));
  const at = await pageButton(page, item);
  assert.ok(at, `the File menu shows ${item}`);
  await click(page, at);
}

async function download(page, item) {
  const [dl] = await Promise.all([page.waitForEvent('download'), menu(page, item)]);
  return { name: dl.suggestedFilename(), bytes: fs.readFileSync(await dl.path()) };
}

async function importByPicker(page, name, text) {
  const [chooser] = await Promise.all([page.waitForEvent('filechooser'), menu(page, 'import')]);
  await chooser.setFiles({ name, mimeType: 'application/json', buffer: Buffer.from(text) });
}

async function importByDrop(page, name, text) {
  const dt = await page.evaluateHandle(([n, t]) => {
    const d = new DataTransfer();
    d.items.add(new File([t], n, { type: 'application/json' }));
    return d;
  }, [name, text]);
  await page.dispatchEvent('canvas', 'dragenter', { dataTransfer: dt });
  await page.dispatchEvent('canvas', 'dragover', { dataTransfer: dt });
  await page.dispatchEvent('canvas', 'drop', { dataTransfer: dt });
}

const noticeAfter = async (page, re) => {
  await page.waitForFunction((src) => new RegExp(src).test(window.cspacelab.status().notice), re.source);
  return (await api(page, 'status')).notice;
};

const AT_DEMO = { deviceScaleFactor: 2, open: '?lesson=step-prm&scene=prm-demo&samples=60&seed=5' };

test('export and import scenes, PNG and roadmap; bad files change nothing', () => withPage(AT_DEMO, async ({ page, browser }) => {
  await api(page, 'run');
  const scene = await api(page, 'get_scene');

  // Scene JSON out.
  const sceneFile = await download(page, 'export-scene');
  assert.equal(sceneFile.name, 'prm-demo-disks-a-polygon-and-a-wall.json');
  assert.deepEqual(JSON.parse(sceneFile.bytes.toString('utf8')), scene);

  // The roadmap and path at this step.
  const roadmapFile = await download(page, 'export-state');
  const exported = JSON.parse(roadmapFile.bytes.toString('utf8'));
  const state = await api(page, 'state', { roadmap: true });
  assert.match(roadmapFile.name, /^cspacelab-step-prm-roadmap-step\d+\.json$/);
  assert.equal(exported.format, 'cspacelab-roadmap');
  assert.deepEqual(exported.state.vertices, state.vertices);
  assert.deepEqual(exported.state.edge_list, state.edge_list);
  assert.deepEqual(exported.state.path, state.path);
  assert.equal(exported.state.solved, true);
  assert.deepEqual(exported.scene, scene);

  // A PNG of the view, at device resolution, read right after a frame.
  await page.mouse.move(5, 5);
  await waitFrames(page, 2);
  const png = await download(page, 'export-png');
  fs.writeFileSync(`${process.env.CSPACELAB_ARTIFACTS || '/tmp'}/export-view.png`, png.bytes);
  const view = await api(page, 'view', { points: [[0.3, 0.3], [0.02, 0.5]] });
  const w = Math.ceil((view.canvas_max[0] - view.canvas_min[0]) * 2);
  const h = Math.ceil((view.canvas_max[1] - view.canvas_min[1]) * 2);
  const toPng = ([x, y]) => [(x - view.canvas_min[0]) * 2, (y - view.canvas_min[1]) * 2];
  const shot = await inspectPng(browser, png.bytes, [toPng(view.points[0]), toPng(view.points[1])]);
  assert.equal(shot.width, w, 'the view, cropped');
  assert.equal(shot.height, h);
  assert.ok(shot.colours > 20, `not blank: ${shot.colours} colours`);
  const [r, g, b] = shot.at[0];
  assert.ok(r < 190 && g < 190 && Math.abs(r - g) < 30, `a disk obstacle is grey in the PNG: ${shot.at[0]}`);

  // Bad files, by the picker and by drag and drop: a message, and the scene stays.
  await importByPicker(page, 'notes.json', 'this is not json');
  assert.match(await noticeAfter(page, /Import/), /Import: "notes\.json" is not JSON\. Nothing changed\./);
  await importByPicker(page, 'bad.json', JSON.stringify({ version: 1, obstacles: [{ type: 'disk', center: [0, 0], radius: -2 }] }));
  assert.match(await noticeAfter(page, /bad\.json/), /obstacles\[0\]\.radius: must be >= 0\. Nothing changed\./);
  await importByDrop(page, 'arm.json', JSON.stringify({ version: 1, robot: { type: 'arm2', base: [0.5, 0.5], lengths: [0.2, 0.2] } }));
  assert.match(await noticeAfter(page, /arm\.json/), /plans for a point robot; the scene has a 'arm2' robot\. Nothing changed\./);
  await importByDrop(page, 'big.json', ' '.repeat(3 * 1024 * 1024));
  assert.match(await noticeAfter(page, /big\.json/), /is 3\.0 MB; a scene file is at most 2\.0 MB/);
  await importByDrop(page, 'list.json', '[1, 2, 3]');
  assert.match(await noticeAfter(page, /list\.json/), /is not a scene/);
  assert.deepEqual(await api(page, 'get_scene'), scene, 'nothing changed');
  assert.equal((await api(page, 'state')).roadmap_hash, state.roadmap_hash, 'not even the roadmap');

  // Good files: the exported scene comes back, by picker and by drop (an exported roadmap
  // file works too: its scene is used).
  await api(page, 'set_scene', { scene: { version: 1, start: [0.1, 0.1], goal: [0.9, 0.9] } });
  await importByPicker(page, sceneFile.name, sceneFile.bytes.toString('utf8'));
  await noticeAfter(page, /Imported/);
  assert.deepEqual(await api(page, 'get_scene'), scene);
  await api(page, 'set_scene', { scene: { version: 1, start: [0.1, 0.1], goal: [0.9, 0.9] } });
  await importByDrop(page, roadmapFile.name, roadmapFile.bytes.toString('utf8'));
  await page.waitForFunction(() => window.cspacelab.getScene().obstacles.length === 5);
  assert.deepEqual(await api(page, 'get_scene'), scene);
  // The imported scene is the one drawn.
  await expectView(page, browser, 'import-export.png', sceneProbes(scene, { free: 8 }));
}));
