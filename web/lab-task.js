// The task text of one lab: what the student is asked to do, shown in the page's DOM above the
// canvas (a screen reader reads it; an LMS iframe often cannot carry the prose around it).
//
// It comes from a link's task= (index.html, embed.html), a data-lab configuration's task=, or a
// [data-lab] element's data-lab-task attribute (plain text, easier to write by hand; task= wins).
// Plain text only: it goes into the DOM as textContent, never as HTML, so "<b>" shows as "<b>".
// Each line is a paragraph (blank lines are dropped); control characters become spaces. At most
// MAX characters are shown; past that the first MAX are shown and the lab's notice says so.
'use strict';

(function (global) {
  const MAX = 1000;

  /**
   * The task as it is shown: {text, lines, length, problem}. `text` has its lines joined with
   * "\n" (what Share and Embed write back); `problem` is the sentence for the notice, or ''.
   */
  function normalise(raw) {
    const cleaned = String(raw == null ? '' : raw)
      .replace(/\r\n?/g, '\n')
      // C0 and C1 controls (but the line break and tab) and the bidi overrides would let a task
      // hide or reorder the text around it: spaces instead.
      .replace(/[\u0000-\u0008\u000b-\u001f\u007f-\u009f\u202a-\u202e\u2066-\u2069]/g, ' ')
      .replace(/\t/g, ' ');
    let lines = cleaned.split('\n').map((l) => l.replace(/ {2,}/g, ' ').trim()).filter(Boolean);
    const length = Array.from(lines.join('\n')).length;  // characters, not UTF-16 units
    let problem = '';
    if (length > MAX) {
      problem = `The task has ${length} characters; a task holds at most ${MAX}, so only the first ${MAX} are shown.`;
      const kept = [];
      let left = MAX;
      for (const line of lines) {
        if (left <= 0) break;
        const chars = Array.from(line);
        kept.push(chars.length <= left ? line : chars.slice(0, left).join('') + '…');
        left -= chars.length + 1;  // (the line break counts)
      }
      lines = kept;
    }
    return { text: lines.join('\n'), lines, length, problem };
  }

  /**
   * About how many CSS px the task takes above the canvas in a lab `width` px wide (lab.css: 20 px
   * lines, 14 px padding and border; some 7.5 px a character): what the Embed dialog adds to a
   * snippet's height so that the canvas keeps its 600 px.
   */
  function height(task, width = 700) {
    if (!task.lines.length) return 0;
    const perLine = Math.max(20, Math.floor((width - 26) / 7.5));
    const rows = task.lines.reduce((n, l, i) => n + Math.max(1, Math.ceil((Array.from(l).length + (i ? 0 : 6)) / perLine)), 0);
    return Math.min(Math.round(width * 0.4), 14 + 20 * rows + 2 * (task.lines.length - 1));
  }

  let count = 0;

  /**
   * Shows the task above the canvas of `root` (replacing any shown before); removes it for an
   * empty text. Returns the section, or null.
   */
  function show(root, canvas, task) {
    const old = root.querySelector(':scope > .lab-task');
    if (old) old.remove();
    root.classList.toggle('lab-has-task', task.lines.length > 0);
    if (!task.lines.length) return null;
    const id = 'lab-task-title-' + (++count);
    const section = document.createElement('section');
    section.className = 'lab-task';
    section.setAttribute('aria-labelledby', id);
    const title = document.createElement('h2');
    title.className = 'lab-task-title';
    title.id = id;
    title.textContent = 'Task';
    section.appendChild(title);
    for (const line of task.lines) {
      const p = document.createElement('p');
      p.textContent = line;  // never parsed as HTML
      section.appendChild(p);
    }
    root.insertBefore(section, canvas);
    // A long task scrolls within its share of the lab (lab.css's max-height, a percentage): held
    // to whole pixels, so that the canvas under it keeps whole CSS pixels too. The keyboard must
    // reach that scrolling, so the section takes the focus only while it overflows.
    const fit = () => {
      if (!section.isConnected) return;
      section.style.maxHeight = '';
      const h = section.getBoundingClientRect().height;
      if (h !== Math.floor(h)) section.style.maxHeight = Math.floor(h) + 'px';
      if (section.scrollHeight > section.clientHeight + 1) section.tabIndex = 0;
      else section.removeAttribute('tabindex');
    };
    if (typeof ResizeObserver === 'function') {
      const watch = new ResizeObserver(fit);
      watch.observe(root);
      watch.observe(section);
    }
    fit();
    return section;
  }

  global.CSpaceLabTask = Object.freeze({ MAX, normalise, height, show });
})(typeof window !== 'undefined' ? window : globalThis);
