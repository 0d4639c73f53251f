// The assignment card (the app's, drawn on the canvas) in the lab's accessible DOM (lab-access.js),
// for a screen reader and the keyboard: the title, progress and score, the items as buttons with
// their status (the current one aria-current), the current item's prompt, an answer field with
// Check (Enter too), "Open in the lab", "Check my lab", Previous, Next, Submit with a confirmation
// (what is still open, Yes or Cancel), the feedback in a polite live region, and the review.
// Loaded by lab.js with lab-assignment.js, only for a lab in assignment mode, so that no other lab
// pays for it. It follows the app's cspacelab:assignment events rather than a poll, and makes its
// elements once (only their text changes), so that the focus stays where the student is.
'use strict';

(function (global) {
  const WORDS = { open: 'to do', answered: 'unreadable', correct: 'right', incorrect: 'not right', viewed: 'viewed' };

  /** Adds the assignment to `access` (a CSpaceLabAccess) and keeps it in step with the app. */
  function mirrorAssignment(access) {
    const el = (tag, props, parent) => access.el(tag, props, parent);
    const call = (cmd, args) => access.api.call(cmd, args);
    let state = null, shownItem = null;

    // First in the section, right after its heading: the answer field is the first Tab after the
    // canvas, not after every lesson and parameter (it was 27).
    const g = el('div', { className: 'lab-access-assignment', role: 'group' });
    access.section.insertBefore(g, access.title.nextSibling);
    g.hidden = true;
    const title = el('h3', { id: access.id + '-assignment' }, g);
    g.setAttribute('aria-labelledby', title.id);
    const progress = el('p', {}, g);
    const prompt = el('p', {}, g);
    const row = el('div', { className: 'lab-access-param' }, g);
    el('label', { for: access.id + '-answer', text: 'Your answer' }, row);
    const input = el('input', { id: access.id + '-answer', type: 'text', spellcheck: 'false' }, row);
    const button = (label, action, parent = g) => {
      const b = el('button', { type: 'button', text: label }, parent);
      b.addEventListener('click', () => access.act(() => action(state.current)));
      return b;
    };
    // Moves to item i as the card's Previous/Next/list do; an explore item counts as viewed.
    const go = (i) => {
      if (state.submitted || i < 0 || i >= state.items.length) return;  // aria-disabled: nothing to do
      call('assignment_go', { index: i });
      if (state.items[i].kind === 'explore') call('assignment_answer', { index: i });
    };
    const check = button('Check', (i) => call('assignment_answer', { index: i, answer: input.value }));
    input.addEventListener('keydown', (e) => { if (e.key === 'Enter') check.click(); });
    const open = button('Open in the lab', go);
    const lab = button('Check my lab', (i) => call('assignment_answer', { index: i }));
    const prev = button('Previous', (i) => go(i - 1));
    const next = button('Next', (i) => go(i + 1));
    // Submit asks first, as the card's button does: what is still open, then Yes or Cancel; the
    // focus goes to Yes, and after it to the review (else it would fall to the page's body).
    const submit = button('Submit...', () => {
      const left = state.items.filter((it) => it.status === 'open').length;
      warn.textContent = (left ? `${left} of ${state.items.length} items have no answer yet. ` : '') +
        'Your answers become final, and the review shows the right ones.';
      asking.hidden = false;
      sure.focus();
    });
    const asking = el('div', { role: 'group', 'aria-label': 'Submit the assignment?' }, g);
    const warn = el('p', { id: access.id + '-submit-warn' }, asking);
    const sure = button('Yes, submit my answers', () => {
      call('assignment_submit');
      show(call('assignment_state'));
      reviewHead.focus();
    }, asking);
    const cancel = button('Cancel', () => { asking.hidden = true; submit.focus(); }, asking);
    // Yes is read with what is still open; Escape is Cancel, as in any dialog.
    sure.setAttribute('aria-describedby', warn.id);
    asking.addEventListener('keydown', (e) => { if (e.key === 'Escape') { e.stopPropagation(); cancel.click(); } });
    const feedback = el('p', { 'aria-live': 'polite' }, g);
    el('h4', { text: 'All items' }, g);
    const items = el('ol', {}, g);
    const reviewHead = el('h4', { text: 'Review: your answers and the right ones', tabindex: '-1' }, g);
    const review = el('ol', {}, g);

    function show(st) {
      state = st;
      g.hidden = !st;
      if (!st) return;
      const done = st.items.filter((it) => it.status !== 'open').length;
      title.textContent = 'Assignment: ' + st.title;
      const score = `score ${st.grade.raw} of ${st.grade.max}`;
      progress.textContent = st.submitted ? `submitted: ${score}, ${st.grade.passed ? '' : 'not '}passed`
        : `${done} of ${st.items.length} answered, ${score}`;
      if (items.children.length !== st.items.length) {
        items.textContent = '';
        for (const it of st.items) {
          const b = el('button', { type: 'button' }, el('li', {}, items));
          b.addEventListener('click', () => access.act(() => go(it.index)));
        }
      }
      st.items.forEach((it, i) => {
        const b = items.children[i].firstChild;
        b.textContent = `${it.title} (${it.points} point${it.points === 1 ? '' : 's'}): ${WORDS[it.status]}`;
        if (i === st.current) b.setAttribute('aria-current', 'true');
        else b.removeAttribute('aria-current');
        b.setAttribute('aria-disabled', String(st.submitted));
      });
      const cur = st.items[st.current];
      const kind = st.submitted ? '' : cur.kind;
      prompt.textContent = st.submitted ? '' : `${st.current + 1}. ${cur.title}: ${cur.prompt}` +
        (cur.format_hint ? ` Answer: ${cur.format_hint}.` : '') + (cur.check_text ? ` What counts: ${cur.check_text}.` : '') +
        ` ${cur.tries_text}`;
      // Tries used up: the answer is final (core refuses another check; this says so first).
      input.readOnly = cur.tries_left === 0;
      for (const b of [check, lab]) b.setAttribute('aria-disabled', String(input.readOnly));
      row.hidden = check.hidden = kind !== 'exercise';
      // The field keeps what the student types until they move to another item.
      if (kind === 'exercise' && shownItem !== st.current) input.value = cur.answer || '';
      shownItem = st.current;
      lab.hidden = kind !== 'task';
      open.hidden = !kind;
      prev.hidden = next.hidden = submit.hidden = st.submitted;
      asking.hidden = true;
      prev.setAttribute('aria-disabled', String(st.current === 0));
      next.setAttribute('aria-disabled', String(st.current + 1 >= st.items.length));
      feedback.textContent = [cur.feedback, st.note].filter(Boolean).join(' ');
      reviewHead.hidden = !st.submitted;
      review.textContent = '';
      for (const it of st.submitted ? st.items : []) {
        const answer = it.kind === 'exercise' ? ` Your answer: ${it.answer === null ? '(none)' : it.answer}. ` +
          `The right answer: ${it.expected_text}.` : '';
        el('li', { text: `${it.title}: ${it.score} of ${it.max} (${WORDS[it.status]}).${answer} ${it.tries_text} ${it.explanation || ''}` }, review);
      }
    }

    access.root.addEventListener('cspacelab:assignment', (e) => show(e.detail));
    try {
      show(call('assignment_state'));
    } catch {
      // none open yet: the first event shows it
    }
  }

  global.CSpaceLabAssignmentAccess = mirrorAssignment;
})(typeof window !== 'undefined' ? window : globalThis);
