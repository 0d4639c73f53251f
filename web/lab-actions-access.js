// The canvas's top bar in the lab's accessible DOM (lab-access.js), for the keyboard and a screen
// reader: Undo and Redo, Share, Embed and the File menu (import, the three exports, the Author
// view or, in a minimal embed, the full lab; reset to the default with its confirmation; previous
// work), as native buttons that call what the canvas's buttons call (the shell's action()). And
// the app's notices ("Link copied", an import's error, the LMS's refusal), which the canvas shows
// for a few seconds and a reader would never hear, in a polite live region.
// lab.js loads it once the lab has started, as the homework's copy (the single-file lab has it
// inline). A dialog it opens (Share, Embed) gives the focus back to its button, not the canvas.
'use strict';

(function (global) {
  /** Adds the lab's actions to `access` (a CSpaceLabAccess) and reads out the app's notices. */
  function mirrorActions(access) {
    const el = (tag, props, parent) => access.el(tag, props, parent);
    const api = access.api;
    const shell = api.shell;
    const id = access.id + '-actions';
    const minimal = access.options.ui === 'minimal';

    // Before Display, as on the canvas: Share, Embed, File (whose menu ends with Display).
    const display = access.display.scheme.closest('[role=group]').previousSibling;
    const heading = el('h3', { id, text: 'Share, file and undo' });
    const g = el('div', { className: 'lab-access-actions', role: 'group', 'aria-labelledby': id });
    access.section.insertBefore(heading, display);
    access.section.insertBefore(g, display);
    const notice = el('p', { className: 'lab-access-notice', 'aria-live': 'polite' }, g);
    const say = (text) => global.CSpaceLabAccess.say(notice, text);

    let opener = null;  // the last button pressed here; when one that opens a dialog was; the dialog
    let pressed = -Infinity;
    let dialog = null;
    const button = (label, run, parent = g) => {
      const b = el('button', { type: 'button', text: label }, parent);
      b.addEventListener('click', () => {
        try {
          opener = b;
          const done = run();
          if (done && done.then) done.then(() => show(), () => show());
        } catch (e) {
          say(e.message);
        }
        show();
      });
      return b;
    };
    const action = (name) => () => shell.action(name);
    const dialogAction = (name) => () => {
      pressed = performance.now();
      return shell.action(name);
    };
    const edit = (cmd, done, none) => () => say(api.call(cmd) ? done : none);

    button('Undo', edit('undo', 'Undone: the last scene edit.', 'Nothing to undo.'));
    button('Redo', edit('redo', 'Redone.', 'Nothing to redo.'));
    button('Share a link to this state', dialogAction('share'));
    button('Embed this lab in a page', dialogAction('embed'));
    // The file picker opens in the click's own turn: a browser opens it only for a user's press.
    button('Import a scene (JSON)', action('import'));
    button('Export the scene (JSON)', action('export-scene'));
    button('Export the view (PNG)', action('export-png'));
    button('Export the roadmap or path (JSON)', action('export-state'));
    if (minimal) button('Open in the full lab', action('open-full'));
    else button('Author an assignment', action('author'));

    // Reset asks first, as the canvas's File menu does; Escape or Cancel keeps everything.
    const resetButton = button('Reset the lesson to its default', () => {
      ask.hidden = false;
      question.focus();
    });
    const ask = el('div', { role: 'group', 'aria-label': 'Reset the lesson?', hidden: '' }, g);
    const question = el('p', { tabindex: '-1' }, ask);
    const close = () => {
      ask.hidden = true;
      resetButton.focus();
    };
    button('Reset', () => {
      close();
      return shell.action('reset');
    }, ask);
    button('Cancel', close, ask);
    ask.addEventListener('keydown', (e) => { if (e.key === 'Escape') close(); });

    // Previous work the page kept (links, resets, other tabs), newest first: any comes back.
    const row = el('div', { className: 'lab-access-param' }, g);
    el('label', { for: id + '-history', text: 'Previous work' }, row);
    const history = el('select', { id: id + '-history' }, row);
    // By the entry's id (an option's value): the list may have changed since it was shown.
    button('Restore', () => {
      const i = shell.historyIds.indexOf(history.value);
      if (i < 0) return say('That previous work is not there any more (another tab may have restored it).');
      return shell.action('restore-history:' + i);
    }, row);

    // A dialog (Share, Embed) closes by focusing the canvas; one opened from here (within a few
    // seconds of the press: a link is built first) gives the focus back to its button.
    new MutationObserver(() => {
      const open = shell.dialog && shell.dialog.isConnected ? shell.dialog : null;
      if (dialog && !open && opener.isConnected) opener.focus();
      // One that replaced ours (a dialog's button may open the next) is ours as well.
      dialog = open && (dialog || performance.now() - pressed < 5000) ? open : null;
      if (dialog) pressed = -Infinity;
    }).observe(access.root, { childList: true });

    const seen = { notices: undefined, history: null };
    function show(status, page) {
      try {
        status = status || api.status();
        page = page || api.pageState();
      } catch {
        return;  // a lab that stopped: its shell shows why
      }
      // A notice is read once: each has its number, so the same words again are news again.
      if (status.notices !== seen.notices && status.notice) say(status.notice);
      seen.notices = status.notices;
      const q = `Reset ${shell.lessonName(status.lesson)} to its default scene and parameters? ` +
        'What you have now is kept: Previous work brings it back.';
      global.CSpaceLabAccess.put(question, q);  // focused, it is not rewritten
      // The labels and the ids are set together (the shell's refreshHistory).
      const labels = (page.history || []).map((h, i) => [shell.historyIds[i], h.label]);
      const key = JSON.stringify(labels);
      if (key !== seen.history && document.activeElement !== history) {
        seen.history = key;
        const chosen = history.value;
        history.textContent = '';
        for (const [value, text] of labels) el('option', { value, text }, history);
        if (labels.some(([v]) => v === chosen)) history.value = chosen;
        // The last entry restored: the focus, on Restore, goes to Reset rather than nowhere.
        if (!labels.length && row.contains(document.activeElement)) resetButton.focus();
        row.hidden = !labels.length;
      }
    }

    access.watch(show);  // on each of lab-access.js's polls (not while the page is hidden)
  }

  global.CSpaceLabActionsAccess = mirrorActions;
})(typeof window !== 'undefined' ? window : globalThis);
