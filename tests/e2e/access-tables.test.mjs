// The lesson's tables in the page's copy (web/lab-tables-access.js), as a screen reader reads
// them: the collision lesson's bisection step by step (P12), each row's λ and η(t) checked against
// a computation here (a point robot among disks: λ of a piece is its length, η the distance to
// the nearest disk's rim), and the potential lesson's forces table (P13), which an instructor's
// hide=p13_forces hides here as on the canvas. No table in a lesson without one.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withPage, api } from './lib/harness.mjs';

const T = '.lab-access-table';
// The table as a reader meets it: its heading, caption, column headers, rows (each led by a row
// header) and the sums' row in its footer.
const cells = (page) => page.locator(`${T} table`).evaluate((t) => {
  const text = (r) => [...r.cells].map((c) => c.textContent);
  const rows = [...t.tBodies[0].rows, ...(t.tFoot ? t.tFoot.rows : [])];
  return { heading: document.getElementById(t.parentNode.getAttribute('aria-labelledby')).textContent,
           caption: t.caption.textContent,
           header: [...t.tHead.rows[0].cells].filter((c) => c.tagName === 'TH' && c.scope === 'col').map((c) => c.textContent),
           rowHeaders: rows.every((r) => r.cells[0].tagName === 'TH' && r.cells[0].scope === 'row'),
           rows: [...t.tBodies[0].rows].map(text), foot: t.tFoot ? [...t.tFoot.rows].map(text) : [] };
});

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
    assert.equal(table.heading, 'The bisection, step by step');
    assert.match(table.caption, /piece is free when λ < η₀\+η₁/);
    assert.ok(table.rowHeaders, 'each row is led by its row header');
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

    // A step adds a row; the rows before it are the same elements (a reader keeps its place).
    await page.evaluate((t) => { window.__row = document.querySelector(`${t} tbody`).rows[8]; }, T);
    await page.keyboard.press('Enter');
    await page.waitForFunction((t) => document.querySelector(`${t} tbody`).rows.length === 10, T);
    assert.ok(await page.evaluate((t) => document.querySelector(`${t} tbody`).rows[8] === window.__row, T), 'not rebuilt');

    // A lesson without a table has none in the copy.
    await api(page, 'select_lesson', { id: 'distances' });
    await page.waitForFunction((t) => document.querySelector(t).hidden, T);
  }));

test('the forces table of P13, and hidden when the instructor hides P13\'s forces', () =>
  withPage({ open: 'index.html?lesson=potential' }, async ({ page, browser, url }) => {
    await page.waitForSelector(`${T} table`, { state: 'attached' });
    const table = await cells(page);
    const state = (await api(page, 'state')).forces_table;
    assert.equal(table.heading, 'Forces at the control points');
    assert.deepEqual(table.header, state.header);
    assert.deepEqual(table.rows, state.rows, 'each control point');
    assert.deepEqual(table.foot, [state.sum], 'then the sums, in the footer');
    assert.ok(table.rowHeaders);
    assert.deepEqual(table.rows.map((r) => r[0]), ['a₁', 'a₂', 'a₃', 'a₄'], 'named as the handout names them');
    const text = await page.locator(T).textContent();
    assert.ok(text.includes(state.tau[0]), 'τ');
    for (const line of state.equations) assert.ok(text.includes(line), line);
    // A wider ρ₀ pushes harder: the cells change in place, the table element is the same one.
    const F_rep = () => page.evaluate((t) => [...document.querySelector(`${t} tbody`).rows].map((r) => r.cells[3].textContent).join('|'), T);
    const before = await F_rep();
    await page.evaluate((t) => { window.__table = document.querySelector(`${t} table`); }, T);
    await api(page, 'set_params', { params: { rho0: 0.3 } });
    await page.waitForFunction(([t, b]) => [...document.querySelector(`${t} tbody`).rows].map((r) => r.cells[3].textContent).join('|') !== b, [T, before]);
    const moved = (await api(page, 'state')).forces_table;
    assert.deepEqual((await cells(page)).rows, moved.rows);
    assert.deepEqual((await cells(page)).foot, [moved.sum]);
    assert.ok(await page.evaluate((t) => document.querySelector(`${t} table`) === window.__table, T), 'not rebuilt');

    const hidden = await browser.newPage();
    await hidden.goto(url + 'index.html?lesson=potential&hide=p13_forces');
    await hidden.waitForSelector(`${T} p`, { state: 'attached' });
    assert.equal(await hidden.locator(T).textContent(), 'Forces at the control points: hidden by your instructor.');
    assert.equal(await hidden.locator(`${T} table`).count(), 0);
    await hidden.close();
  }));
