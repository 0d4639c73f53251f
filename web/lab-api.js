// The JS-visible API of one C-Space Lab instance: JSON commands into the wasm app.
// Strings cross through malloc'd memory (not the stack), so large scenes are fine.
// Nothing received is evaluated; results are parsed with JSON.parse only.
'use strict';

class CSpaceLabApi {
  constructor(module) {
    this._module = module;
  }

  /** The Emscripten module of this instance (its canvas, its memory). */
  get module() { return this._module; }

  /** Runs a command of the app; returns its result or throws an Error with the app's message. */
  call(cmd, args = {}) {
    const m = this._module;
    const request = JSON.stringify({ cmd, args });
    const size = m.lengthBytesUTF8(request) + 1;
    const ptr = m._malloc(size);
    if (!ptr) throw new Error('C-Space Lab: out of memory for a request of ' + size + ' bytes');
    let response;
    try {
      m.stringToUTF8(request, ptr, size);
      response = JSON.parse(m.UTF8ToString(m._csl_call(ptr)));
    } finally {
      try {
        m._free(ptr);
      } catch {
        // the wasm trapped in the call: the error that matters is that one, not this
      }
    }
    if (!response.ok) throw new Error(response.error);
    return response.result;
  }

  /** The commands the app offers, with one line of help each. */
  help() { return this.call('help'); }
  /** Frames drawn, frame times, version, pixel ratio, current lesson, current notice and their count. */
  status() { return this.call('status'); }
  lessons() { return this.call('lessons'); }
  selectLesson(id) { return this.call('select_lesson', { id }); }
  /** The current lesson's state; state({roadmap: true}) adds a PRM lesson's vertices and edges. */
  state(args = {}) { return this.call('state', args); }
  setParams(params) { return this.call('set_params', { params }); }
  /** The lesson's parameters for native controls: [{name, label, kind, min, max, step, unit, help, value, choices?, list?}]. */
  paramSpecs() { return this.call('param_specs'); }
  /** What the lesson shows now, in sentences: the scene and the main view's result. */
  describe() { return this.call('describe'); }
  step(count = 1) { return this.call('step', { count }); }
  stepBack(count = 1) { return this.call('step_back', { count }); }
  runTo(steps) { return this.call('run_to', { steps }); }
  run() { return this.call('run'); }
  finishPhase() { return this.call('finish_phase'); }
  /** Stops long work (a run, a replay) where it is; status().busy is null after it. */
  cancel() { return this.call('cancel'); }
  reset() { return this.call('reset'); }
  getScene() { return this.call('get_scene'); }
  setScene(scene) { return this.call('set_scene', { scene }); }
  /**
   * {lesson, scene, params, steps}: enough to restore exactly this view (share links, autosave);
   * snapshot('collision') gives another open lesson's.
   */
  snapshot(lesson) { return this.call('snapshot', lesson === undefined ? {} : { lesson }); }
  /** Restores a snapshot; every part is checked first, and a bad one changes nothing. */
  restore(snapshot) { return this.call('restore', snapshot); }
  undo() { return this.call('undo'); }
  redo() { return this.call('redo'); }
  log() { return this.call('log'); }
  /** Shows a one-line notice in the app for `seconds` (default 8). */
  notify(text, seconds) { return this.call('notify', seconds === undefined ? { text } : { text, seconds }); }
  /** The bundled scenes by name: what ?scene=NAME loads. */
  bundledScenes() { return this.call('bundled_scenes'); }
  /** The colours that carry meaning, by role, and text colours on their backgrounds. */
  theme() { return this.call('theme'); }
  /** The page state the app shows ({attached, minimal, reduced_motion, previous, scheme, contrast, look, ...}); pageState({...}) changes it. */
  pageState(changes = {}) { return this.call('page_state', changes); }
  /** Homework P1-P13: the list, a problem opened, an exercise (seed optional), an answer checked. */
  homework() { return this.call('homework'); }
  openProblem(id, seed) { return this.call('open_problem', { id, seed }); }
  exercise(id, seed) { return this.call('exercise', { id, seed }); }
  checkAnswer(answer) { return this.call('check_answer', { answer }); }
  /** Canvas-relative CSS pixel positions of world points in a view ('workspace', 'cspace', 'circle'). */
  view(points = [], view = 'workspace') { return this.call('view', { points, view }); }
}

if (typeof window !== 'undefined') window.CSpaceLabApi = CSpaceLabApi;
