// The lesson's tables in the page's copy (web/lab-tables-access.js), as a screen reader reads
// them: the collision lesson's bisection step by step (P12), each row's λ and η(t) checked against
// a computation here (a point robot among disks: λ of a piece is its length, η the distance to
// the nearest disk's rim), and the potential lesson's forces table (P13), which an instructor's
// hide=p13_forces hides here as on the canvas. No table in a lesson without one.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, api } from './lib/harness.mjs';

const T = '.lab-access-table';
const cells = (page) => page.locator(`${T} table`).evaluate((t) =>
  ({ caption: t.caption.textContent,
     header: [...t.tHead.rows[0].cells].map((c) => c.textContent),
     rows: [...t.tBodies[0].rows].map((r) => [...r.cells].map((c) => c.textContent)) }));

test('the bisection table: a row per step, its λ and η(t) as computed here', () =>
  withPage({ open: 'index.html?lesson=collision' }, async ({ page }) => {
    const disks = [{ center: [0.5, 0.56], radius: 0.05 }, { center: [0.42, 0.38], radius: 0.04 }];
    await api(page, 'set_scene', { scene: { version: 1, start: [0.3, 0.5], goal: [0.7, 0.5],
                                            obstacles: disks.map((d) => ({ type: 'disk', ...d })) } });
    await api(page, 'set_params', { params: { p: [0.3, 0.5], q: [0.7, 0.5] } });
    await page.waitForSelector(`${T} p`, { state: 'attached' });
    assert.match(await page.locator(T).textContent(), /No rows yet/, 'before the first step');
    // Step by the copy's own button, as a keyboard user would.
    const step = page.locator('.lab-access-steps button:text-is("Step")');
    await step.focus();
    for (let i = 0; i < 9; ++i) await page.keyboard.press('Enter');
    await page.waitForFunction((t) => document.querySelector(`${t} tbody`)?.rows.length === 9, T);
    const table = await cells(page);
    assert.match(table.caption, /a piece is free when λ < η₀\+η₁/);
    assert.deepEqual(table.header, ['#', 'piece', 'λ', 'λ against η₀+η₁', 'η₀+η₁', 't', 'η(t)']);

    const [p, q] = [[0.3, 0.5], [0.7, 0.5]];
    const at = (t) => [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
    const eta = ([x, y]) => Math.min(...disks.map((d) => Math.hypot(x - d.center[0], y - d.center[1]) - d.radius));
    const length = Math.hypot(q[0] - p[0], q[1] - p[1]);
    let checked = 0;
    for (const [n, piece, lambda, rel, sum, t, e] of table.rows) {
      if (t !== '') assert.ok(Math.abs(Number(e) - eta(at(Number(t)))) < 6e-5, `η(${t}) = ${e}, here ${eta(at(Number(t)))}`);
      if (piece === 'end') continue;
      const [t0, t1] = piece.slice(1, -1).split(', ').map(Number);
      assert.ok(Math.abs(Number(lambda) - (t1 - t0) * length) < 6e-5, `λ of ${piece} = ${lambda}`);
      const etas = eta(at(t0)) + eta(at(t1));
      assert.ok(Math.abs(Number(sum) - etas) < 1e-4, `η₀+η₁ of ${piece} = ${sum}, here ${etas}`);
      assert.equal(rel, Number(lambda) < etas ? '<' : '≥', `the comparison of ${piece}`);
      assert.equal(t === '', rel === '<', 'a certified piece has no midpoint; a split one has');
      ++checked;
      assert.ok(n === '' || Number(n) > 0);
    }
    assert.ok(checked >= 6, `pieces checked: ${checked}`);
    assert.ok(table.rows.some((r) => r[3] === '<') && table.rows.some((r) => r[3] === '≥'), 'both outcomes are in nine steps');

    // A lesson without a table has none in the copy.
    await api(page, 'select_lesson', { id: 'distances' });
    await page.waitForFunction((t) => document.querySelector(t).hidden, T);
  }));

test('the forces table of P13, and hidden when the instructor hides P13\'s forces', () =>
  withPage({ open: 'index.html?lesson=potential' }, async ({ page, browser, url }) => {
    await page.waitForSelector(`${T} table`, { state: 'attached' });
    const table = await cells(page);
    const state = (await api(page, 'state')).forces_table;
    assert.equal(table.caption, 'Forces at the control points');
    assert.deepEqual(table.header, state.header);
    assert.deepEqual(table.rows, state.rows.concat([state.sum]), 'each control point, then the sums');
    assert.equal(table.rows.length, 5);
    assert.deepEqual(table.rows.map((r) => r[0]), ['a₁', 'a₂', 'a₃', 'a₄', 'Σ'], 'named as the handout names them');
    const text = await page.locator(T).textContent();
    assert.ok(text.includes(state.tau[0]), 'τ');
    for (const line of state.equations) assert.ok(text.includes(line), line);

    const hidden = await browser.newPage();
    await hidden.goto(url + 'index.html?lesson=potential&hide=p13_forces');
    await hidden.waitForSelector(`${T} p`, { state: 'attached' });
    assert.equal(await hidden.locator(T).textContent(), 'Forces at the control points: hidden by your instructor.');
    assert.equal(await hidden.locator(`${T} table`).count(), 0);
    await hidden.close();
  }));
