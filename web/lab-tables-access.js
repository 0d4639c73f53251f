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
  // lesson -> [its state's table, the caption, the hidden answer that hides it]
  const TABLES = {
    collision: ['trace_table', 'The bisection, step by step: a piece is free when λ < η₀+η₁; ' +
                'else its midpoint t is checked (η(t) ≤ 0: in collision) and, free, the piece is split'],
    potential: ['forces_table', 'Forces at the control points', 'p13_forces'],
  };

  /** Adds the open lesson's table to `access` (a CSpaceLabAccess) and keeps it in step. */
  function mirrorTables(access) {
    const el = (tag, props, parent) => access.el(tag, props, parent);
    const id = access.id + '-table';
    const heading = el('h3', { id, text: 'Table' });
    const box = el('div', { className: 'lab-access-table', role: 'region', 'aria-labelledby': id });
    access.description.after(heading, box);
    let seen = null;

    function show() {
      let status, spec, table;
      try {
        status = access.api.status();
        spec = TABLES[status.lesson];
        table = spec && access.api.call('state')[spec[0]];
      } catch {
        return;  // a lab that stopped: its shell shows why; the copy keeps its last state
      }
      const hidden = !!(spec && spec[2] && ((status.restrictions || {}).hidden_now || []).includes(spec[2]));
      const key = JSON.stringify([status.lesson, hidden, table]);
      if (key === seen) return;  // rebuilt only when it changed: a reader keeps its place
      seen = key;
      // (A hidden table is not in the state either.)
      heading.hidden = box.hidden = !table && !hidden;
      box.textContent = '';
      if (hidden) {
        el('p', { text: `${spec[1]}: hidden by your instructor.` }, box);
        return;
      }
      if (!table) return;
      const t = el('table', {}, box);
      el('caption', { text: spec[1] }, t);
      const head = el('tr', {}, el('thead', {}, t));
      // The bisection's unnamed column holds < or ≥.
      for (const h of table.header) el('th', { scope: 'col', text: h || 'λ against η₀+η₁' }, head);
      const body = el('tbody', {}, t);
      for (const row of table.rows.concat(table.sum ? [table.sum] : [])) {
        const tr = el('tr', {}, body);
        for (const cell of row) el('td', { text: cell }, tr);
      }
      if (!table.rows.length) el('p', { text: 'No rows yet: step the check.' }, box);
      for (const line of (table.tau || []).concat(table.equations || [])) el('p', { text: line }, box);
    }

    // On a timer of its own, as lab-access.js's poll (and not while the page is hidden).
    const timer = setInterval(() => {
      if (!access.section.isConnected) clearInterval(timer);
      else if (!document.hidden) show();
    }, global.CSpaceLabAccess.POLL_MS);
    show();
  }

  global.CSpaceLabTablesAccess = mirrorTables;
})(typeof window !== 'undefined' ? window : globalThis);
