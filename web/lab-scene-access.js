// Start, goal and obstacles in the accessible DOM (lab-access.js): the canvas's editor tells a
// screen reader nothing. A change is one set_scene, one undoable edit (the top bar copy's Undo).
'use strict';

(function (global) {
const f4 = (v) => +v.toPrecision(4);
const pt = (p) => `(${p.map(f4).join(', ')})`;
const get = (s, path) => path.reduce((o, k) => o?.[k], s);
const seg = ([x, y], [ax, ay], [bx, by]) => {  // (x, y)'s distance to the segment ab
  const dx = bx - ax, dy = by - ay, l = dx * dx + dy * dy, t = l && Math.max(0, Math.min(1, ((x - ax) * dx + (y - ay) * dy) / l));
  return Math.hypot(x - ax - t * dx, y - ay - t * dy);
};
const inside = ([x, y], vs) => vs.reduce((c, [ax, ay], i) => {
  const [bx, by] = vs[(i + 1) % vs.length];
  return (ay > y) !== (by > y) && x < ax + (y - ay) * (bx - ax) / (by - ay) ? !c : c;
}, false);
const PART = { center: 'centre', radius: 'radius', a: 'end a', b: 'end b', vertices: 'vertices ("x y, x y, …")' };

// A scene's rows {key, name, i, fields: [[label, path, text?]], say}
function rowsOf(s) {
  const r = s.robot.type, n = s.start.length, arm = r.startsWith('arm');
  const rows = ['Start', 'Goal'].map((name) => {
    const q = name.toLowerCase();
    return { key: q + r + n, name, say: `${name}: ${pt(s[q])}.`, fields: s[q].map((_, k) => [!arm && k < 2 ? 'xy'[k] +
      ' (position)' : `${arm ? 'joint ' + (k + 1) : 'angle'} θ (radians)`, [q, k]]) };
  });
  s.obstacles.forEach((o, i) => {
    const name = { disk: 'Disk ', polygon: 'Polygon ', segment: 'Wall ' }[o.type] + (i + 1), fields = [], say = [];
    for (const [k, v] of Object.entries(o)) {
      const at = ['obstacles', i, k], l = PART[k];
      if (!l) continue;
      if (v.length && !v[0].length) fields.push([l + ' x', [...at, 0]], [l + ' y', [...at, 1]]);
      else fields.push([l, at, v.length]);
      say.push(l.split(' (')[0] + ' ' + (v.length ? v[0].length ? v.map(pt).join(', ') : pt(v) : f4(v)));
    }
    rows.push({ key: o.type + i, name, i, fields, say: `${name}: ${say.join(', ')}.` });
  });
  return rows;
}

function mirrorScene(access) {
  const el = (tag, props, parent) => access.el(tag, props, parent);
  const api = access.api, id = access.id + 's';
  const heading = el('h3', { id, text: 'Scene: start, goal and obstacles' });
  const g = el('div', { className: 'lab-access-scene', role: 'group', 'aria-labelledby': id });
  access.stepHeading.before(heading, g);  // after the parameters
  const lock = el('p', { id: id + 'l', className: 'lab-access-fixed' }, g);
  const add = el('button', { text: 'Add a disk' }, g);
  const live = el('p', { className: 'lab-access-notice', 'aria-live': 'polite' }, g);
  const say = (text) => global.CSpaceLabAccess.say(live, text);
  let rows = [], built = '', scene, n = 0;

  const value = (f, s, v = get(s, f.path)) => (v == null ? v : f.text ? v.map((p) => p.join(' ')).join(', ') : '' + v);
  // NaN goes as null: the app refuses it with its message.
  const num = (x) => (x.trim() ? +x : NaN);
  // One set_scene, if the row is still there
  const edit = (row, change) => {
    const s = api.getScene();
    if (row.key && !rowsOf(s).some((r) => r.key === row.key)) throw new Error(row.name + ' is gone.');
    change(s);
    return (scene = api.setScene(s));
  };
  const press = (b, run) => b.addEventListener('click', () => {
    try { say(run()); } catch (e) { say(e.message); }
    access.poll();
  });

  function change(row, f) {
    const t = f.input.value, p = f.path;
    let msg = '';
    f.typing = false;
    try {
      const v = f.text ? t.split(',').map((q) => q.trim().split(/\s+/).map(num)) : num(t);
      edit(row, (s) => { get(s, p.slice(0, -1))[p[p.length - 1]] = v; });
    } catch (e) {
      msg = e.message;  // the app's refusal: it kept its value
      f.input.value = value(f, scene) ?? f.input.value;
    }
    f.error.textContent = msg;
    f.input.setAttribute('aria-invalid', !!msg);
    say(msg || rowsOf(scene).find((r) => r.key === row.key).say);
    access.poll();
  }

  function makeRow(spec) {
    const row = { ...spec, el: el('fieldset'), fields: [] };
    el('legend', { text: spec.name }, row.el);
    for (const [label, path, text] of spec.fields) {
      const fid = `${id}-${++n}`, line = el('div', { className: 'lab-access-param' }, row.el);
      el('label', { for: fid, text: label }, line);
      const input = el('input', { id: fid, type: text ? 'text' : 'number', step: 'any', 'aria-describedby': `${fid}e ${lock.id}` }, line);
      const f = { path, text, input, error: el('span', { id: fid + 'e', className: 'lab-access-error' }, line) };
      input.oninput = () => { f.typing = true; };
      input.onblur = () => { f.typing = false; };  // (left unchanged)
      input.onchange = () => change(row, f);
      // Up and Down (a screen reader's spin keys too) step a little: the browser's step would be
      // 1, out of a unit workspace. An angle by 0.05 rad; a length by 1% of the workspace.
      input.onkeydown = (e) => {
        const d = !text && { ArrowUp: 1, ArrowDown: -1 }[e.key];
        if (!d) return;
        e.preventDefault();
        const w = scene.workspace, unit = 0.01 * Math.min(w.max[0] - w.min[0], w.max[1] - w.min[1]);
        input.value = f4(+input.value + d * (label.includes('θ') ? 0.05 : unit));
        change(row, f);
      };
      row.fields.push(f);
    }
    if (spec.i !== undefined) {
      press(el('button', { text: 'Delete ' + spec.name.toLowerCase() }, row.el), () => {
        edit(row, (s) => s.obstacles.splice(row.i, 1));
        add.focus();  // before the row goes
        return `Deleted ${row.name.toLowerCase()}.`;
      });
    }
    return row;
  }

  // A small disk furthest from the robot (at start and goal) and the obstacles
  press(add, () => {
    const s = api.getScene(), lo = s.workspace.min, hi = s.workspace.max, rb = s.robot;
    const r = +(0.05 * Math.min(hi[0] - lo[0], hi[1] - lo[1])).toPrecision(2);
    const away = [];  // [a, b, m]: clear of the segment ab by m
    for (const q of [s.start, s.goal]) {
      if (!rb.type.startsWith('arm')) away.push([q, q, rb.vertices ? Math.max(...rb.vertices.map((v) => Math.hypot(...v))) : 0]);
      else {
        let p = rb.base, a = 0;
        rb.lengths.forEach((l, k) => away.push([p, p = [p[0] + l * Math.cos(a += q[k]), p[1] + l * Math.sin(a)], 0]));
      }
    }
    for (const o of s.obstacles) {
      if (o.center) away.push([o.center, o.center, o.radius]);
      else (o.vertices || [o.a, o.b]).forEach((v, i, vs) => away.push([v, vs[(i + 1) % vs.length], 0]));
    }
    let c, room = -Infinity;
    for (let i = 0; i < 81; ++i) {
      const p = [i % 9, i / 9 | 0].map((t, k) => +(lo[k] + 2 * r + (hi[k] - lo[k] - 4 * r) * t / 8).toPrecision(3));
      const gap = s.obstacles.some((o) => o.vertices && inside(p, o.vertices)) ? -1e9
        : Math.min(...away.map(([a, b, m]) => seg(p, a, b) - m));
      if (gap > room) [c, room] = [p, gap];
    }
    edit({}, (t) => t.obstacles.push({ type: 'disk', center: c, radius: r }));
    show();  // its row, to focus now (press() then polls the whole copy, once)
    const row = rows[rows.length - 1];
    row.fields[0].input.focus();
    return 'Added. ' + row.say;
  });

  function show(status) {
    let s;
    try {
      status = status || api.status();
      s = api.getScene();
    } catch { /* no scene, or a lab that stopped */ }
    // A lesson without a scene: the focus, if it was here, goes to the lesson's button.
    if (!s && g.contains(document.activeElement)) access.section.querySelector('[aria-current="true"], button')?.focus();
    heading.hidden = g.hidden = !s;
    if (!s) return;
    const specs = rowsOf(scene = s), keys = specs.map((r) => r.key).join();
    const keep = rows.map((r, i) => specs[i]?.key === r.key);
    // Rows whose shape changed are made again, but not one with the focus (a reader keeps its
    // place; a later poll).
    if (keys !== built && !rows.some((r, i) => !keep[i] && r.el.contains(document.activeElement))) {
      built = keys;
      rows.forEach((r, i) => keep[i] || r.el.remove());
      rows = specs.map((sp, i) => (keep[i] ? rows[i] : makeRow(sp)));
      // New rows go before the next kept one: a kept row never moves (it would lose focus).
      rows.reduceRight((next, r) => (r.el.isConnected || g.insertBefore(r.el, next), r.el), add);
    }
    const locked = !!status.restrictions?.scene;
    const why = locked ? 'Fixed by your instructor (lock=scene).' : '';
    global.CSpaceLabAccess.put(lock, why);
    rows.forEach((r, i) => specs[i]?.key === r.key && r.fields.forEach((f) => {
      const v = value(f, s);
      if (!f.typing && f.input.value !== v) {
        f.input.value = v;  // changed elsewhere (Undo, the mouse): an old refusal no longer holds
        f.error.textContent = '';
        f.input.setAttribute('aria-invalid', false);
      }
      if (f.input.readOnly !== locked) f.input.readOnly = locked;
    }));
    for (const b of g.querySelectorAll(`button:not([aria-disabled="${locked}"])`)) b.setAttribute('aria-disabled', locked);
  }

  access.watch(show);  // on lab-access.js's poll
}

global.CSpaceLabSceneAccess = mirrorScene;
})(globalThis);
