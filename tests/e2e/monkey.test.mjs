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
      if (snapshot.scene) {
        const scene = await api(page, 'get_scene');
        assert.equal(typeof JSON.stringify(scene), 'string');
        await api(page, 'set_scene', { scene }).catch((e) => { throw new Error(`${status.lesson}: ${e.message}`); });
        assert.deepEqual(await api(page, 'get_scene'), scene);
      }
      await api(page, 'restore', snapshot);
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
  assert.equal(await refusal(page, 'setParams', { samples: 20001 }), 'samples: an integer in [0, 20000]');
  assert.equal((await api(page, 'state')).roadmap_hash, s.roadmap_hash, 'nothing changed');
}));
