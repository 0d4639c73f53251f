// The homework card (the app's, drawn on the canvas) in the lab's accessible DOM (lab-access.js),
// for a screen reader and the keyboard: the handout's problems P1-P13 in a list with "Open the
// problem" (not in a minimal lab, whose app has no Homework button either), and the open
// problem's card: its task, the exercise, an answer field with Check (Enter too), the verdict and
// what went wrong in a polite live region ("Show the solution" for the answer and its working, as
// on the card), "Show these numbers in the tool" and the 3-D picture once answered, New numbers,
// the visit's score and Close. It shows what the card shows, no more.
// lab.js loads it once the lab has started, so that no page waits for it (the single-file lab
// has it inline). It polls the app as lab-access.js does and makes its elements once (only
// their text changes), so that the focus stays where the student is.
'use strict';

(function (global) {
  /** Adds the homework to `access` (a CSpaceLabAccess) and keeps it in step with the app. */
  function mirrorHomework(access) {
    const el = (tag, props, parent) => access.el(tag, props, parent);
    const call = (cmd, args) => access.api.call(cmd, args);
    const problems = call('homework');
    const id = access.id + '-homework';
    let shown = null;  // the exercise on show ("P10:7"), or null
    let problem = null;  // its problem's id
    let said = '';     // the verdict last put in the live region

    // After the assignment's copy, before the lessons: the student's way in is by number.
    const g = el('div', { className: 'lab-access-homework', role: 'group', 'aria-labelledby': id });
    const nav = access.lessonList ? access.lessonList.parentNode : access.params.previousSibling;
    access.section.insertBefore(g, nav);
    el('h3', { id, text: 'Homework: the handout\'s problems' }, g);
    const button = (label, action, parent) => {
      const b = el('button', { type: 'button', text: label }, parent);
      b.addEventListener('click', () => { access.act(action); show(); });
      return b;
    };
    let pick = null;
    if (access.options.ui !== 'minimal') {
      const row = el('div', { className: 'lab-access-param' }, g);
      el('label', { for: id + '-pick', text: 'Problem' }, row);
      pick = el('select', { id: id + '-pick' }, row);
      for (const p of problems) el('option', { value: p.id }, pick);
      // Choosing in the list opens nothing (a change of context on a list's arrow keys would
      // move a reader away mid-list); the button does, and the focus goes to the problem.
      button('Open the problem', () => {
        call('open_problem', { id: pick.value });
        focusAfter = title;
      }, g);
    }
    const card = el('div', { className: 'lab-access-homework-card', role: 'group', 'aria-labelledby': id + '-title' }, g);
    const title = el('h4', { id: id + '-title', tabindex: '-1' }, card);
    const task = el('p', {}, card);
    // The exercise's number and prompt: focused after New numbers, so that they are read out.
    const exercise = el('div', { tabindex: '-1', role: 'group', 'aria-label': 'Exercise' }, card);
    const row = el('div', { className: 'lab-access-param' }, card);
    el('label', { for: id + '-answer', text: 'Your answer' }, row);
    const input = el('input', { id: id + '-answer', type: 'text', spellcheck: 'false',
                                'aria-describedby': id + '-hint' }, row);
    const hint = el('p', { id: id + '-hint' }, card);
    const check = button('Check', () => {
      call('check_answer', { answer: input.value });
      again = true;  // the same wrong answer twice is read twice
    }, card);
    input.addEventListener('keydown', (e) => { if (e.key === 'Enter') check.click(); });
    const verdict = el('p', { 'aria-live': 'polite' }, card);
    // A wrong try is told what went wrong; the answer and the worked solution only on request.
    const solution = button('Show the solution', () => {
      call('show_solution');
      again = true;
      focusAfter = input;  // the button goes; the solution is read out from the live region
    }, card);
    const tool = button('Show these numbers in the tool', () => call('show_exercise'), card);
    // The card goes with its lesson: the section's own live region says where the student is.
    const in3d = button('', () => {
      call('show_exercise', { in: '3d' });
      access.announce('The C-space is in the 3-D lesson now: "What the view shows" describes it.');
      focusAfter = access.description;
    }, card);
    button('New numbers', () => {
      call('exercise', { id: problem });
      focusAfter = exercise;
    }, card);
    const score = el('p', {}, card);
    button('Close', () => {
      call('close_problem');
      focusAfter = pick || access.description;
    }, card);
    let focusAfter = null;  // where an action sends the focus once the poll has shown its result
    let again = false;      // a check from here: its verdict is read even if the text is the same
    access.description.setAttribute('tabindex', '-1');

    const put = global.CSpaceLabAccess.put;  // text set only where it changed

    // Into the live region; `repeat`: an equal text is read again (emptied first, then set).
    function say(text, repeat) {
      if (text === said && !repeat) return;
      said = text;
      global.CSpaceLabAccess.say(verdict, text);
    }

    function show(status) {
      let st, lesson;
      try {
        st = call('homework_state');
        lesson = (status || access.api.status()).lesson;
      } catch {
        return;  // a lab that stopped: its shell shows why; the copy keeps its last state
      }
      if (pick) {
        problems.forEach((p, i) => {
          const s = st.scores[p.id];
          put(pick.options[i], `${p.id}: ${p.title}` + (!s ? '' : s.right ? ' (solved)' : ' (tried)'));
        });
        if (st.problem && document.activeElement !== pick) pick.value = st.problem;
      }
      const p = problems.find((x) => x.id === st.problem);
      const e = st.exercise;
      // As the app: the card stands above its problem's lesson only.
      card.hidden = !p || !e || e.id !== p.id || p.lesson !== lesson;
      // Hidden (another lesson on screen), it keeps its exercise and what was typed for it.
      if (!card.hidden) {
        const key = `${e.id}:${e.seed}`;
        put(title, `${p.id}: ${p.title}`);
        put(task, p.task);
        if (key !== shown) {
          exercise.textContent = '';
          el('p', { text: `Exercise ${e.id}, numbers no. ${e.seed}` }, exercise);
          for (const line of e.prompt.split('\n')) if (line.trim()) el('p', { text: line }, exercise);
          hint.textContent = 'Answer: ' + e.format_hint;
          // The field keeps what the student types until the exercise changes.
          input.value = st.answer;
          said = verdict.textContent = '';
          shown = key;
          problem = p.id;
        }
        const c = st.check;
        // As the card: what went wrong while the solution is offered, else the whole explanation.
        say([st.error, c ? (st.solution_offered ? c.feedback : c.explanation) : ''].filter(Boolean).join(' '), again);
        solution.hidden = !st.solution_offered;
        tool.hidden = !st.tool;
        in3d.hidden = !st.see_3d;
        put(in3d, st.see_3d || '');
        const s = st.scores[e.id];
        put(score, s ? `This visit: ${s.right} solved in ${s.tried} ${s.tried === 1 ? 'try' : 'tries'}.` : '');
      }
      if (focusAfter && !focusAfter.closest('[hidden]')) focusAfter.focus();
      focusAfter = null;
      again = false;
    }

    access.watch(show);  // on each of lab-access.js's polls (not while the page is hidden)
  }

  global.CSpaceLabHomeworkAccess = mirrorHomework;
})(typeof window !== 'undefined' ? window : globalThis);
