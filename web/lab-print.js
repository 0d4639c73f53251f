// One lab, printed: a worksheet instead of the screen. While the page prints (beforeprint, or
// the print media query, which is what a browser's print preview and Chromium's emulation
// switch), the lab's element holds a sheet: the lesson's name, the task text, a picture of the
// lesson's views, its parameters with their values, and what the view shows in words (the
// API's describe). Print CSS (lab.css) hides the canvas and every control; the sheet goes again
// after printing.
//
// The picture: the canvas is WebGL without preserveDrawingBuffer, so its pixels can be read only
// right after a frame is drawn, and a print handler must finish at once (the browser lays the
// page out for print when it returns). So after a frame, at most once a second, the views' part
// of the canvas is copied into a 2D canvas (a few milliseconds); the printed picture is that
// copy, at most a second old, drawn into a <canvas> of the sheet (a 2D canvas prints as it is;
// an <img> from a data URL would still be decoding when the page is laid out).
'use strict';

class CSpaceLabPrint {
  /** root: the [data-lab] element; canvas: its canvas; api: its CSpaceLabApi; shell: its CSpaceLabShell. */
  constructor(root, canvas, api, shell) {
    this.root = root;
    this.canvas = canvas;
    this.api = api;
    this.shell = shell;
    this.copy = null;          // the latest picture: a 2D canvas
    this.copiedAt = -Infinity;
    this.sheet = null;
    shell.onFrame = () => this.frame();
    const before = () => this.before();
    const after = () => this.after();
    window.addEventListener('beforeprint', before);
    window.addEventListener('afterprint', after);
    if (typeof matchMedia === 'function') {
      const media = matchMedia('print');
      if (media.addEventListener) media.addEventListener('change', (e) => (e.matches ? before() : after()));
    }
  }

  /** After a frame (Module.postMainLoop, while the drawing buffer holds it): the copy, once a second. */
  frame() {
    const now = performance.now();
    if (now - this.copiedAt < CSpaceLabPrint.COPY_MS || document.hidden || this.sheet) return;
    this.copiedAt = now;
    try {
      const c = this.canvas;
      const ratio = c.width / Math.max(1, c.clientWidth);
      const views = (this.api.status().layout || {}).views || [];
      let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
      for (const v of views) {
        x0 = Math.min(x0, v.x); y0 = Math.min(y0, v.y);
        x1 = Math.max(x1, v.x + v.w); y1 = Math.max(y1, v.y + v.h);
      }
      if (!views.length) [x0, y0, x1, y1] = [0, 0, c.clientWidth, c.clientHeight];  // no view: the whole canvas
      const x = Math.max(0, Math.floor(x0 * ratio)), y = Math.max(0, Math.floor(y0 * ratio));
      const w = Math.min(c.width - x, Math.ceil((x1 - x0) * ratio)), h = Math.min(c.height - y, Math.ceil((y1 - y0) * ratio));
      if (w < 1 || h < 1) return;
      const copy = this.copy || (this.copy = document.createElement('canvas'));
      if (copy.width !== w || copy.height !== h) [copy.width, copy.height] = [w, h];
      copy.getContext('2d').drawImage(c, x, y, w, h, 0, 0, w, h);
    } catch {
      // a lab that stopped: the last copy stands
    }
  }

  el(tag, props = {}, parent = null) {
    const node = document.createElement(tag);
    for (const [k, v] of Object.entries(props)) {
      if (k === 'text') node.textContent = v;  // never parsed as HTML
      else if (k === 'className') node.className = v;
      else node.setAttribute(k, v);
    }
    if (parent) parent.appendChild(node);
    return node;
  }

  static valueText(spec) {
    const v = spec.value;
    if (Array.isArray(v)) return v.join(', ');
    if (typeof v === 'boolean') return v ? 'yes' : 'no';
    return String(v);
  }

  /** Builds the sheet (once per print). */
  before() {
    if (this.sheet || this.shell.dead) return;
    let status, lessons, specs, text;
    try {
      status = this.api.status();
      lessons = this.api.lessons();
      specs = this.api.paramSpecs();
      text = this.api.describe();
    } catch {
      return;  // a lab that stopped prints as it is
    }
    const lesson = lessons.find((l) => l.id === status.lesson);
    const sheet = this.el('section', { className: 'lab-print-sheet' });
    this.el('h2', { className: 'lab-print-title', text: 'C-Space Lab: ' + (lesson ? lesson.name : status.lesson) }, sheet);
    const task = this.shell.options.task;
    if (task && task.lines.length) {
      const part = this.el('div', { className: 'lab-print-task' }, sheet);
      this.el('h3', { text: 'Task' }, part);
      for (const line of task.lines) this.el('p', { text: line }, part);
    }
    if (this.copy) {
      const picture = this.el('canvas', { className: 'lab-print-picture', role: 'img', 'aria-label': 'The lesson\'s picture' }, sheet);
      [picture.width, picture.height] = [this.copy.width, this.copy.height];
      picture.getContext('2d').drawImage(this.copy, 0, 0);
    }
    if (specs.length) {
      this.el('h3', { text: 'Parameters' }, sheet);
      const list = this.el('dl', { className: 'lab-print-params' }, sheet);
      for (const spec of specs) {
        const unit = spec.unit && !spec.label.includes(spec.unit) ? ` (${spec.unit})` : '';
        this.el('dt', { text: spec.label + unit }, list);
        this.el('dd', { text: CSpaceLabPrint.valueText(spec) }, list);
      }
    }
    this.el('h3', { text: 'What the view shows' }, sheet);
    this.el('p', { className: 'lab-print-description', text }, sheet);
    this.root.appendChild(sheet);
    this.root.classList.add('lab-printing');
    this.sheet = sheet;
  }

  after() {
    if (!this.sheet) return;
    this.sheet.remove();
    this.sheet = null;
    this.root.classList.remove('lab-printing');
  }
}

CSpaceLabPrint.COPY_MS = 1000;

if (typeof window !== 'undefined') window.CSpaceLabPrint = CSpaceLabPrint;
