// The lesson's tables, which the app draws in its panel where a screen reader cannot read them,
// in the lab's accessible DOM (lab-access.js), after "What the view shows": the collision
// lesson's bisection step by step (each piece's λ against η₀+η₁, each evaluated configuration's
// η(t): homework P12) and the potential lesson's forces at the control points (ρ, ∇ρ, the forces
// and Jᵀ F per point, their sums, τ, and one point's worked equations: P13). The text is the
// panel's own, from the lesson's `state` (trace_table, forces_table), read only while such a
// lesson is on screen. A table the instructor hid (hide=p13_forces) says so, as the panel does.
// lab.js loads it once the lab has started, as the homework's copy (the single-file lab has it
// inline).
'use strict';

(function (global) {
  // lesson -> [its state's table, the heading, the caption, the hidden answer that hides it]
  const TABLES = {
    collision: ['trace_table', 'The bisection, step by step', 'A piece is free when λ < η₀+η₁; else its ' +
                'midpoint t is checked (η(t) ≤ 0: in collision) and, free, the piece is split'],
    potential: ['forces_table', 'Forces at the control points', 'ρ, ∇ρ and the forces at each control point, ' +
                'its Jᵀ F, and their sums', 'p13_forces'],
  };

  /** Adds the open lesson's table to `access` (a CSpaceLabAccess) and keeps it in step. */
  function mirrorTables(access) {
    const el = (tag, props, parent) => access.el(tag, props, parent);
    const put = global.CSpaceLabAccess.put;  // text set only where it changed
    const id = access.id + '-table';
    const heading = el('h3', { id });
    const box = el('div', { className: 'lab-access-table', role: 'region', 'aria-labelledby': id });
    access.description.after(heading, box);
    let built = null;  // what the table's frame was built for: lesson, hidden, header
    let body, foot, notes;

    // A row's cells: the first a row header (the point, Σ, the step's number), set where changed.
    function fill(section, at, row) {
      const tr = section.rows[at] || el('tr', {}, section);
      row.forEach((cell, c) => put(tr.cells[c] || el(c ? 'td' : 'th', c ? {} : { scope: 'row' }, tr), cell));
    }

    function show(status) {
      let spec, table;
      try {
        status = status || access.api.status();
        spec = TABLES[status.lesson];
        table = spec && access.api.call('state')[spec[0]];
      } catch {
        return;  // a lab that stopped: its shell shows why; the copy keeps its last state
      }
      const hidden = !!(spec && spec[3] && ((status.restrictions || {}).hidden_now || []).includes(spec[3]));
      // (A hidden table is not in the state either.)
      heading.hidden = box.hidden = !table && !hidden;
      const frame = JSON.stringify([status.lesson, hidden, table && table.header]);
      if (frame !== built) {
        built = frame;
        box.textContent = '';
        if (spec) put(heading, spec[1]);
        if (hidden) el('p', { text: `${spec[1]}: hidden by your instructor.` }, box);
        if (hidden || !table) return;
        const t = el('table', {}, box);
        el('caption', { text: spec[2] }, t);
        const head = el('tr', {}, el('thead', {}, t));
        // The bisection's unnamed column holds < or ≥.
        for (const h of table.header) el('th', { scope: 'col', text: h || 'λ against η₀+η₁' }, head);
        body = el('tbody', {}, t);
        foot = el('tfoot', {}, t);
        notes = el('div', {}, box);
      }
      if (hidden || !table) return;
      // Cells change in place and rows are added or dropped at the end, so that a reader in the
      // table keeps its place while the student steps or drags.
      table.rows.forEach((row, i) => fill(body, i, row));
      while (body.rows.length > table.rows.length) body.lastChild.remove();
      if (table.sum) fill(foot, 0, table.sum);
      const lines = (table.rows.length ? [] : ['No rows yet: step the check.'])
        .concat(table.tau || [], table.equations || []);
      lines.forEach((line, i) => put(notes.children[i] || el('p', {}, notes), line));
      while (notes.children.length > lines.length) notes.lastChild.remove();
    }

    access.watch(show);  // on each of lab-access.js's polls (not while the page is hidden)
  }

  global.CSpaceLabTablesAccess = mirrorTables;
})(typeof window !== 'undefined' ? window : globalThis);
