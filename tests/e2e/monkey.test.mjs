// Thousands of seeded random mouse and keyboard events over every lesson: no console error, no
// wasm abort, the app answers throughout, and each lesson's scene is still exportable and
// importable afterwards. The seed is printed: CSPACELAB_MONKEY_SEED=... replays a run.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, withPage, collectErrors, openLab, api, waitFrames, screenshot, refusal } from './lib/harness.mjs';

const SEED = Number(process.env.CSPACELAB_MONKEY_SEED || 20261121);
const EVENTS_PER_LESSON = Number(process.env.CSPACELAB_MONKEY_EVENTS || 400);

// mulberry32: a tiny seeded generator, so a failing run can be replayed exactly.
function rng(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = Math.imul(a ^ (a >>> 15), 1 | a);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const KEYS = ['v', 'd', 'p', 'w', 'Escape', 'Enter', 'Backspace', 'Delete', '.', ',', ' ', '?', 'f', 'Tab', 'ArrowUp',
              'ArrowDown', 'x', '1', '-', '0'];

test(`monkey: ${EVENTS_PER_LESSON} random events per lesson, seed ${SEED}`,
  () => withBrowser(async ({ browser, url }) => {
  const W = 1280, H = 800;
  const page = await browser.newPage({ viewport: { width: W, height: H } });
  const errors = collectErrors(page);
  await openLab(page, url);
  const random = rng(SEED);
  const pick = (list) => list[Math.floor(random() * list.length)];
  const point = () => ({ x: 5 + random() * (W - 10), y: 5 + random() * (H - 10) });
  let total = 0;
  let where = 'opening';
  try {
    for (const lesson of await api(page, 'lessons')) {
      await api(page, 'select_lesson', { id: lesson.id });
      for (let i = 0; i < EVENTS_PER_LESSON; ++i, ++total) {
        where = `lesson ${lesson.id}, event ${i}`;
        const r = random();
        if (r < 0.30) {
          const p = point();
          await page.mouse.move(p.x, p.y);
        } else if (r < 0.50) {
          const p = point();
          await page.mouse.click(p.x, p.y, { button: random() < 0.85 ? 'left' : 'right' });
        } else if (r < 0.65) {
          const a = point(), b = point();
          await page.mouse.move(a.x, a.y);
          await page.mouse.down();
          await page.mouse.move((a.x + b.x) / 2, (a.y + b.y) / 2);
          await page.mouse.move(b.x, b.y);
          await page.mouse.up();
        } else if (r < 0.72) {
          await page.mouse.wheel(0, (random() - 0.5) * 600);
        } else if (r < 0.80) {
          const p = point();
          await page.mouse.dblclick(p.x, p.y);
        } else if (r < 0.95) {
          await page.keyboard.press(pick(KEYS));
        } else {
          const mod = random() < 0.5 ? 'Control' : 'Shift';
          await page.keyboard.down(mod);
          await page.keyboard.press(pick(['z', 'y', 'a', 'Tab']));
          await page.keyboard.up(mod);
        }
        if (i % 25 === 0) await waitFrames(page, 1);
      }
      await page.mouse.up();
      await waitFrames(page, 3);
      // Still alive, still answering, and its work still exportable and importable.
      // The monkey may have clicked another lesson's button: check whichever is on screen.
      const status = await api(page, 'status');
      assert.ok(status.frames > 0 && typeof status.lesson === 'string');
      const snapshot = await api(page, 'snapshot');
      // Every lesson has a scene but the notation and distances lessons, whose work is their
      // parameters: a lesson that lost its scene must not skip the round trip below unnoticed.
      assert.equal(snapshot.scene === null, ['notation', 'distances'].includes(status.lesson),
                   `${status.lesson}: a scene where one belongs`);
      if (snapshot.scene) {
        const scene = await api(page, 'get_scene');
        assert.equal(typeof JSON.stringify(scene), 'string');
        await api(page, 'set_scene', { scene }).catch((e) => { throw new Error(`${status.lesson}: ${e.message}`); });
        assert.deepEqual(await api(page, 'get_scene'), scene);
      }
      await api(page, 'restore', snapshot);
      assert.deepEqual(await api(page, 'snapshot'), snapshot, `${status.lesson}: its work restores exactly`);
      await screenshot(page, `monkey-${lesson.id}.png`);
    }
  } catch (e) {
    // Say where the run was, and keep a picture of it: a replay needs both.
    await screenshot(page, 'monkey-failure.png').catch(() => {});
    // A wasm abort stops the frames, so a timeout may really be an error: show them too.
    e.message = `${where}: ${e.message}${errors.length ? `; page errors: ${errors.join(' | ')}` : ''}`;
    throw e;
  }
  console.log(`monkey: ${total} events over ${(await api(page, 'lessons')).length} lessons, seed ${SEED}`);
  assert.deepEqual(errors, [], 'no console errors and no aborts');
}));

test('limits in the app: the most samples work, one more is refused and changes nothing',
  () => withPage(async ({ page }) => {
  await api(page, 'select_lesson', { id: 'step-prm' });
  await api(page, 'set_params', { params: { samples: 20000, neighbors: 'k:10' } });
  await api(page, 'run');
  const s = await api(page, 'state');
  assert.equal(s.params.samples, 20000);
  assert.equal(s.done, true);
  assert.equal(await refusal(page, 'setParams', { samples: 20001 }), 'samples: an integer in [0, 20000] in the lab');
  assert.equal((await api(page, 'state')).roadmap_hash, s.roadmap_hash, 'nothing changed');
}));

// Issue 27: links and imports from the hostile families of its round (workspaces too small or too
// thin to draw, absurd and heavy parameters, deep and broken JSON, control characters, steps past
// the limit), seeded. Each must leave a lab that starts, keeps drawing, says what it did not
// use, and never shows the crash panel; a plain start afterwards is clean.
test(`monkey links and imports: hostile families, seed ${SEED}`, () => withBrowser(async ({ browser, url }) => {
  const random = rng(SEED + 27);
  const pick = (list) => list[Math.floor(random() * list.length)];
  const b64 = (text) => Buffer.from(text).toString('base64').replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
  const nested = (n) => '['.repeat(n) + ']'.repeat(n);
  const scenes = [
    () => ({ version: 1, workspace: { min: [0, 0], max: [pick([1e-15, 1e-100, 5e-324, 1e-4]), 1] } }),
    () => ({ version: 1, workspace: { min: [0, 0], max: [pick([1000, 1e6]), 1] } }),
    () => ({ version: 1, obstacles: [{ type: 'disk', center: [0.5, 0.5], radius: pick([-1, 0, 1e6, 1e-300]) }] }),
    () => ({ version: 1, obstacles: [{ type: 'disk', center: [0, 0], radius: 0.3 }] }),  // start inside
    () => ({ version: 1, name: 'a\u001b[31m\n' + 'x'.repeat(pick([10, 199, 201])) }),
    () => ({ version: 1, ['k\ney\u0007']: 1 }),
    () => ({ version: 1, robot: { type: 'arm2', base: [0.5, 0.5], lengths: [pick([1e-300, 0.3]), 0.2] } }),
  ];
  const sceneText = () => random() < 0.15 ? '{"version":1,"name":' + nested(pick([70, 2000])) + '}' : JSON.stringify(pick(scenes)());
  const parts = [
    () => 'scene=j.' + b64(sceneText()),
    () => 'samples=' + pick(['20000', '20001', '1e9', '-5', '1e999', '0x10', ' 5']),
    () => 'neighbors=' + pick(['k:1000', 'k:0', 'k:50', 'radius:1e300', 'radius:0.3', 'prm*', 'k:%0A5']),
    () => 'checker=' + pick(['grid:1000000', 'grid:2', 'step:0.0000001', 'step:0x1p-3', 'bisection', 'grid:%1B']),
    () => 'steps=' + pick(['999999999', '99999999', '100000001', '-1', '7']),
    () => 'seed=' + pick(['1', '9007199254740993', 'nan']),
    () => 'grid_n=' + pick(['100000', '100001', '3']),
  ];
  const lessons = ['step-prm', 'torus', 'collision', 'potential', 'analysis', 'notation', 'distances', 'nosuch'];
  const LINKS = Number(process.env.CSPACELAB_MONKEY_LINKS || 24);
  const ctx = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await ctx.newPage();
  const errors = collectErrors(page);
  let where = '';
  try {
    for (let i = 0; i < LINKS; ++i) {
      const query = ['lesson=' + pick(lessons)];
      for (let k = 1 + Math.floor(random() * 3); k > 0; --k) query.push(pick(parts)());
      where = `link ${i}: ?${query.join('&').slice(0, 300)}`;
      await openLab(page, url + '?' + query.join('&'));
      await waitFrames(page, 3);  // it keeps drawing (a trap stops the frames)
      assert.equal(await page.locator('.lab-crash').count(), 0, 'no crash panel');
      // Half the time, an import of a hostile file too, through the page's own import.
      if (random() < 0.5) {
        where += ' + import';
        const text = pick([sceneText(), sceneText() + '\u0000garbage', '{"version":1} trailing', 'x'.repeat(3 << 20)]);
        await page.evaluate((t) => window.cspacelab.shell.importFile(new File([t], 'hostile.json')), text);
        await waitFrames(page, 3);
        assert.equal(await page.locator('.lab-crash').count(), 0, 'no crash panel after the import');
      }
      // Long work from a link runs in slices: wait for it, the frames going on meanwhile.
      await page.waitForFunction(() => window.cspacelab.status().busy === null, null, { timeout: 120000 });
    }
    where = 'a plain start afterwards';
    await openLab(page, url);
    await waitFrames(page, 3);
    assert.equal(await page.locator('.lab-crash').count(), 0);
  } catch (e) {
    await screenshot(page, 'monkey-links-failure.png').catch(() => {});
    e.message = `${where}: ${e.message}${errors.length ? `; page errors: ${errors.join(' | ')}` : ''}`;
    throw e;
  }
  assert.deepEqual(errors, [], `no console errors and no traps (${where})`);
  await ctx.close();
}));
