// The parallel DOM (web/lab-access.js): the native HTML beside the canvas that a screen reader
// and the keyboard reach. Its lesson buttons switch lessons, its parameter controls set the
// app's parameters (and show the app's changes and refusals), its Step button's event reaches
// the live region, and its description states the path's length as state() has it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, api, waitFrames, screenshot } from './lib/harness.mjs';

const SEL = '.lab-access';

// The pixels that differ between two PNGs of the same size (decoded in a page of the browser).
async function changedPixels(browser, a, b) {
  const page = await browser.newPage();
  try {
    return await page.evaluate(async ([x, y]) => {
      const decode = async (b64) => {
        const img = new Image();
        img.src = 'data:image/png;base64,' + b64;
        await img.decode();
        const c = new OffscreenCanvas(img.width, img.height);
        const ctx = c.getContext('2d');
        ctx.drawImage(img, 0, 0);
        return ctx.getImageData(0, 0, img.width, img.height).data;
      };
      const [p, q] = [await decode(x), await decode(y)];
      let n = 0;
      for (let i = 0; i < p.length; i += 4) if (p[i] !== q[i] || p[i + 1] !== q[i + 1] || p[i + 2] !== q[i + 2]) ++n;
      return n;
    }, [a.toString('base64'), b.toString('base64')]);
  } finally {
    await page.close();
  }
}

// The workspace view's pixels (the roadmap), with the app's own mapping of its corners.
async function viewShot(page) {
  await waitFrames(page, 3);
  const v = await api(page, 'view', { view: 'workspace' });
  const box = await page.locator('canvas').boundingBox();
  const [x0, y0] = v.canvas_min, [x1, y1] = v.canvas_max;
  return page.screenshot({ clip: { x: box.x + x0, y: box.y + y0, width: x1 - x0, height: y1 - y0 } });
}

async function press(page, selector) {
  await page.locator(selector).focus();
  await page.keyboard.press('Enter');
}

test('parallel DOM: lessons, parameters both ways, steps into the live region, the path described',
  () => withPage({ open: 'index.html?lesson=step-prm&scene=prm-demo&samples=150&seed=3' }, async ({ page, browser }) => {
    await page.waitForSelector(`${SEL} input[name="samples"]`, { state: 'attached' });

    // The keyboard: Tab from the canvas enters the section, which then shows over the lab.
    await page.locator('canvas').focus();
    assert.equal((await page.locator(SEL).boundingBox()).height <= 1, true, 'hidden until focused');
    await page.keyboard.press('Tab');
    assert.equal(await page.evaluate((s) => document.querySelector(s).contains(document.activeElement), SEL), true,
                 'Tab from the canvas lands in the section');
    const shown = await page.locator(SEL).boundingBox();
    // Over the app's side panel, whose controls it repeats: the views a step changes stay in sight.
    const canvas = await page.locator('canvas').boundingBox();
    const views = (await api(page, 'status')).layout.views;
    const left = canvas.x + Math.min(...views.map((v) => v.x));
    assert.ok(shown.height > 400 && shown.width > 250 && shown.x + shown.width <= left,
              `shown while focused, beside the views (from x = ${left}): ${JSON.stringify(shown)}`);
    await screenshot(page, 'access-dom-focused.png');

    // (a) The lesson buttons switch lessons; the current one is aria-current.
    await press(page, `${SEL} button[data-lesson="collision"]`);
    assert.equal((await api(page, 'status')).lesson, 'collision');
    await page.waitForFunction((s) => document.querySelector(`${s} button[data-lesson="collision"]`)
      .getAttribute('aria-current') === 'true', SEL);
    assert.equal(await page.locator(`${SEL} button[data-lesson="step-prm"]`).getAttribute('aria-current'), null);
    // The collision lesson's N is its spec's range.
    const gridN = page.locator(`${SEL} input[name="grid_n"]`);
    await gridN.waitFor({ state: 'attached' });
    assert.deepEqual([await gridN.getAttribute('min'), await gridN.getAttribute('max')], ['2', '100000']);
    await press(page, `${SEL} button[data-lesson="step-prm"]`);
    assert.equal((await api(page, 'status')).lesson, 'step-prm');

    // (b) A parameter changed in the DOM changes params() and the roadmap drawn.
    const seed = page.locator(`${SEL} input[name="seed"]`);
    await page.waitForFunction((s) => document.querySelector(`${s} input[name="seed"]`).value === '3', SEL);
    await api(page, 'run');
    const before = await viewShot(page);
    await seed.focus();
    await seed.fill('8');
    await seed.dispatchEvent('change');
    assert.equal((await api(page, 'snapshot')).params.seed, 8);
    await api(page, 'run');
    const after = await viewShot(page);
    const changed = await changedPixels(browser, before, after);
    assert.ok(changed > 500, `another roadmap drawn: ${changed} pixels changed`);
    // The app's change shows in the control (even while it has the focus, once nothing is typed).
    await api(page, 'set_params', { params: { seed: 11 } });
    await page.waitForFunction((s) => document.querySelector(`${s} input[name="seed"]`).value === '11', SEL);
    // A refused value: the app's message beside the control, aria-invalid, the app's value back.
    const samples = page.locator(`${SEL} input[name="samples"]`);
    await samples.focus();
    await samples.fill('999999');
    await samples.dispatchEvent('change');
    assert.equal(await samples.getAttribute('aria-invalid'), 'true');
    const error = await page.locator(`${SEL} #${await samples.getAttribute('id')}-error`).textContent();
    assert.match(error, /^samples: an integer in \[0, 20000\]/);
    assert.match(await samples.getAttribute('aria-describedby'), /-error/);
    assert.equal(await samples.inputValue(), '150');
    assert.equal((await api(page, 'snapshot')).params.samples, 150);
    await screenshot(page, 'access-dom-refused.png');

    // (c) The DOM's Step: the step's event text reaches the live region.
    await press(page, `${SEL} .lab-access-steps button:text-is("Reset")`);
    assert.equal((await api(page, 'status')).stepping.steps, 0);
    assert.equal(await page.locator(`${SEL} .lab-access-steps button:text-is("Back")`).getAttribute('aria-disabled'), 'true');
    await press(page, `${SEL} .lab-access-steps button:text-is("Step")`);
    await page.waitForFunction(() => window.cspacelab.log().some((l) => l.step === 1));
    const newest = (await api(page, 'log')).at(-1);
    assert.equal(newest.step, 1);
    await page.waitForFunction(([s, text]) => document.querySelector(`${s} .lab-access-log`).textContent === text,
                               [SEL, newest.text], { timeout: 5000 });
    // Steps a student takes one after another are each read, at once: the one-line-a-second
    // limit is Play's (a walk by screen reader lost step 3 of 4 pressed half a second apart).
    const heardNow = await page.evaluate((s) => {
      const step = [...document.querySelectorAll(`${s} .lab-access-steps button`)].find((b) => b.textContent === 'Step');
      const out = [];
      for (let i = 0; i < 3; ++i) {
        step.click();
        out.push([window.cspacelab.log().at(-1).text, document.querySelector(`${s} .lab-access-log`).textContent]);
      }
      return out;
    }, SEL);
    for (const [line, live] of heardNow) assert.equal(live, line, 'the step\'s line is in the live region as the click returns');

    // (c') Play from the DOM: a toggle (aria-pressed), at the speed typed beside it; while it
    // plays the live region changes at most once a second however fast the steps come.
    const speed = page.locator(`${SEL} input[id$="-speed"]`);
    await speed.fill('200');
    await speed.dispatchEvent('change');
    assert.equal((await api(page, 'status')).stepping.speed, 200);
    const play = page.locator(`${SEL} .lab-access-steps button:text-is("Play")`);
    // Timed in the page, where the region changes (a binding's call to node arrives later).
    await page.evaluate((s) => {
      const live = document.querySelector(`${s} .lab-access-log`);
      window.__heard = [];
      new MutationObserver(() => window.__heard.push([performance.now(), live.textContent]))
        .observe(live, { childList: true, characterData: true, subtree: true });
    }, SEL);
    const atStart = (await api(page, 'status')).stepping.steps;
    await press(page, `${SEL} .lab-access-steps button:text-is("Play")`);
    await page.waitForFunction(() => window.cspacelab.status().stepping.playing === true);
    await page.waitForFunction((s) => document.querySelector(`${s} .lab-access-steps button[aria-pressed]`).getAttribute('aria-pressed') === 'true', SEL);
    await page.waitForTimeout(2500);
    // Paused, a step's line is read at once again: what the pause's poll finds may come sooner
    // than a second after the last line read while playing, and is not counted here.
    const pausedAt = await page.evaluate(() => performance.now());
    await play.click();  // pause
    await page.waitForFunction(() => window.cspacelab.status().stepping.playing === false);
    const played = (await api(page, 'status')).stepping.steps - atStart;
    assert.ok(played > 50, `it played: ${played} steps in about 2.5 s`);
    const heard = (await page.evaluate(() => window.__heard)).filter(([t]) => t < pausedAt);
    assert.ok(heard.length >= 2, `the live region spoke while playing: ${heard.length}`);
    for (let i = 1; i < heard.length; ++i)
      assert.ok(heard[i][0] - heard[i - 1][0] >= 900, `at most one announcement a second (${heard[i][0] - heard[i - 1][0]} ms)`);
    assert.equal(await play.getAttribute('aria-pressed'), 'false');

    // (d) Run all: the description states the path and its length as state() has it.
    await press(page, `${SEL} .lab-access-steps button:text-is("Run all")`);
    await page.waitForFunction(() => { const s = window.cspacelab.status(); return !s.busy && s.stepping.finished; });
    const state = await api(page, 'state');
    assert.equal(state.solved, true);
    const length = String(Number(state.path_length.toPrecision(4)));
    await page.waitForFunction(([s, l]) => document.querySelector(`${s} .lab-access-description`).textContent.includes(
      `Path found: ${l}`), [SEL, `${state.path.length - 1} edges, length ${length}.`]);
    await page.waitForFunction((s) => document.querySelector(`${s} .lab-access-steps button:nth-child(2)`)
      .getAttribute('aria-disabled') === 'true', SEL);
    await screenshot(page, 'access-dom-run.png');

    // (e) Another lesson: Step PRM's last line does not stay under "Latest event". Distances
    // logs nothing, so the region empties; back on Step PRM it reads that lesson's newest line.
    assert.notEqual(await page.locator(`${SEL} .lab-access-log`).textContent(), '');
    await press(page, `${SEL} button[data-lesson="distances"]`);
    assert.deepEqual(await api(page, 'log'), []);
    await page.waitForFunction((s) => document.querySelector(`${s} .lab-access-log`).textContent === '', SEL);
    await press(page, `${SEL} button[data-lesson="step-prm"]`);
    const back = (await api(page, 'log')).at(-1).text;
    await page.waitForFunction(([s, t]) => document.querySelector(`${s} .lab-access-log`).textContent === t, [SEL, back]);

    // Tab leaves the lab from the section's last control: no trap.
    const focusable = await page.locator(`${SEL} :is(button, input, select)`).all();
    await focusable.at(-1).focus();  // the last: Display's contrast
    assert.match(await page.evaluate(() => document.activeElement.id), /-contrast$/);
    await page.keyboard.press('Tab');
    assert.equal(await page.evaluate(() => document.querySelector('.lab').contains(document.activeElement)), false);
  }));
