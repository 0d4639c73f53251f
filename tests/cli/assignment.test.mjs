// cspacelab assignment validate / grade / exercises: the contract of `cspacelab help
// assignment`. The example in docs/ validates; grades are checked against answers computed here
// from the exercises' given numbers; per-learner numbers differ between learners and stay the
// same on a rerun; bad files and options are one-line errors with exit status 2.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { json, fails, run, SOURCE } from './lib/cli.mjs';
import { s1, minGrid } from '../lib/homework-answers.mjs';

const EXAMPLE = path.join(SOURCE || path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..'), 'docs/assignment-example.json');

function temp(content, name = 'file.json') {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'csl-assign-'));
  const file = path.join(dir, name);
  fs.writeFileSync(file, typeof content === 'string' ? content : JSON.stringify(content));
  return file;
}

const example = JSON.parse(fs.readFileSync(EXAMPLE, 'utf8'));

test('the example assignment in docs/ validates, with its counts and points', () => {
  const out = json('assignment', 'validate', EXAMPLE);
  assert.equal(out.valid, true);
  assert.equal(out.items, example.items.length);
  assert.deepEqual(out.kinds, { exercise: 3, explore: 1, task: 1 });
  const points = example.items.reduce((s, i) => s + i.points, 0);
  assert.equal(out.max_points, points);
  assert.equal(out.pass, example.pass);
  // The normal form validates again to itself.
  const again = json('assignment', 'validate', temp(out.assignment));
  assert.deepEqual(again.assignment, out.assignment);
});

test('validate names every error, its item and field, on one line, and exits 2', () => {
  const bad = structuredClone(example);
  bad.items[1].points = -1;
  bad.items[3].lesson = 'step_prm';
  bad.items[4].check.all[1].pointer = 'params/samples';
  bad.extra = 1;
  const file = temp(bad);
  fails(new RegExp('^cspacelab: ' + file.replace(/[.*+?^${}()|[\]\\]/g, '\\$&') + ': 4 problems: "extra": unknown field .*; ' +
    'items\\[1\\] \\(P10\\): points: a number in \\[0, 1000\\], got -1; ' +
    'items\\[3\\] \\("A wall with a gap"\\): lesson: one of torus, .*got "step_prm"; ' +
    'items\\[4\\] \\("Find a path with at most 50 samples"\\): check\\.all\\[1\\]: pointer: a JSON pointer starts with \'/\''),
  'assignment', 'validate', file);
  // One error: no count.
  delete bad.extra;
  bad.items = [bad.items[1]];
  fails(/: items\[0\] \(P10\): points: a number in \[0, 1000\], got -1$/, 'assignment', 'validate', temp(bad));
});

test('exercises: each learner their own numbers, the same on a rerun, fixed seeds shared, no answers', () => {
  const ann = json('assignment', 'exercises', EXAMPLE, '--learner', 'ann@example.edu');
  const again = json('assignment', 'exercises', EXAMPLE, '--learner', 'ann@example.edu');
  const bob = json('assignment', 'exercises', EXAMPLE, '--learner', 'bob@example.edu');
  assert.deepEqual(ann, again);
  assert.equal(ann.learner, 'ann@example.edu');
  assert.equal(ann.items.length, 5);
  assert.equal(ann.items[1].seed_from, 'learner');
  assert.notEqual(ann.items[1].seed, bob.items[1].seed);
  assert.notDeepEqual(ann.items[1].given, bob.items[1].given);
  assert.equal(ann.items[2].seed_from, 'fixed');
  assert.equal(ann.items[2].seed, 4);
  assert.deepEqual(ann.items[2].given, bob.items[2].given);
  // P10's own tolerance (0.005) gives way to the assignment's: one tolerance, the one that counts.
  assert.equal(ann.items[1].format_hint, 'radians, e.g. 1.57 or pi/2 (within 0.01 in this assignment)');
  assert.equal(ann.items[3].lesson, 'step-prm');
  assert.equal(ann.items[3].scene.obstacles.length, 2);
  assert.equal(ann.items[4].check_text,
               'solved is true and the parameter samples is at most 50 and scene name is "A passage through a thick wall"');
  for (const item of ann.items) {
    assert.ok(!('answer' in item) && !('expected' in item) && !('worked' in item), JSON.stringify(item));
  }
  // The page's exercise for the same seed is the CLI's `exercise` command's.
  const ex = json('exercise', 'P10', '--seed', String(ann.items[1].seed));
  assert.deepEqual(ex.given, ann.items[1].given);
  // No learner: the documented default, the learner id "".
  assert.deepEqual(json('assignment', 'exercises', EXAMPLE), json('assignment', 'exercises', EXAMPLE, '--learner', ''));
});

test('grade: answers computed here earn their points; totals, completion and success as SCORM wants', () => {
  const learner = 'ann@example.edu';
  const view = json('assignment', 'exercises', EXAMPLE, '--learner', learner);
  const p10 = view.items[1].given, p12 = view.items[2].given;
  const answers = {
    learner,
    answers: [
      { item: 0, answer: 'R^3' },  // wrong on purpose: P3 is two joints' torus or cylinder
      { item: 1, answer: s1(p10.q1, p10.q2).toFixed(4) },
      { item: 2, answer: String(minGrid(p12.center, p12.radius)) },
      { item: 3, visited: true },
      { item: 4, state: { solved: true, nodes: 47, params: { samples: 45, seed: 9 }, scene_name: 'A passage through a thick wall' } },
    ],
  };
  const out = json('assignment', 'grade', EXAMPLE, '--answers', temp(answers));
  assert.equal(out.learner, learner);
  assert.deepEqual(out.items.map((i) => i.correct), [false, true, true, true, true]);
  assert.deepEqual(out.items.map((i) => i.points), [0, 2, 2, 0, 3]);
  assert.ok(Math.abs(out.items[1].expected - s1(p10.q1, p10.q2)) < 1e-9);
  assert.equal(out.items[2].expected, minGrid(p12.center, p12.radius));
  assert.deepEqual(out.score, { raw: 7, min: 0, max: 8, scaled: 7 / 8 });
  assert.equal(out.completed, true);
  assert.equal(out.passed, true);
  assert.match(out.items[4].explanation, /^Done: yes: solved is true/);

  // Another learner's numbers are not ann's: her answers, graded as bob's, miss P10.
  const asBob = json('assignment', 'grade', EXAMPLE, '--answers', temp({ ...answers, learner: undefined }), '--learner', 'bob@example.edu');
  assert.equal(asBob.items[1].correct, false);
  assert.equal(asBob.items[2].correct, true);  // a fixed seed: the same for everyone

  // Too many samples, the rest unanswered: not completed, not passed.
  const few = json('assignment', 'grade', EXAMPLE, '--answers',
    temp({ answers: [{ item: 4, state: { solved: true, params: { samples: 80 } } }] }));
  assert.equal(few.items[4].correct, false);
  assert.match(few.items[4].explanation, /the parameter samples is 80 \(wanted: the parameter samples is at most 50\)/);
  assert.deepEqual(few.score, { raw: 0, min: 0, max: 8, scaled: 0 });
  assert.equal(few.completed, false);
  assert.equal(few.passed, false);
});

test('bad files and options are one-line errors with exit status 2', () => {
  fails(/a subcommand: validate, grade or exercises/, 'assignment');
  fails(/unknown subcommand 'check'/, 'assignment', 'check', EXAMPLE);
  fails(/--answers FILE is required/, 'assignment', 'grade', EXAMPLE);
  fails(/cannot|No such|not/i, 'assignment', 'exercises', '/nonexistent/a.json');
  fails(/not valid JSON|JSON/, 'assignment', 'exercises', temp('{"format": '));
  fails(/2 problems: items\[1\] \(P10\): points: .*; items\[2\] \(P12\): seed: /, 'assignment', 'exercises',
    temp({ ...example, items: [example.items[0], { ...example.items[1], points: -1 }, { ...example.items[2], seed: 'x' }] }));
  fails(/answers\[0\]: item: an item's index, 0 to 4, got 7/, 'assignment', 'grade', EXAMPLE, '--answers', temp({ answers: [{ item: 7, answer: '1' }] }));
  fails(/answers\[0\]: "answer": item 3 \(explore\) is answered with "visited"/, 'assignment', 'grade', EXAMPLE, '--answers',
    temp({ answers: [{ item: 3, answer: '1', visited: true }] }));
  fails(/--learner 'bob' and the answers' learner 'ann' differ/, 'assignment', 'grade', EXAMPLE, '--answers',
    temp({ learner: 'ann', answers: [] }), '--learner', 'bob');
  fails(/--learner: a learner id has at most 4000 bytes/, 'assignment', 'exercises', EXAMPLE, '--learner', 'x'.repeat(4001));
  fails(/unknown option|unexpected/i, 'assignment', 'validate', EXAMPLE, '--learner', 'ann');
});

test('help assignment documents the contract', () => {
  const r = run('help', 'assignment');
  assert.equal(r.status, 0);
  for (const word of ['"format": "cspacelab-assignment"', '"kind": "exercise"', '"kind": "explore"', '"kind": "task"',
    '"pointer"', '"all"', '"any"', 'seed_key', '"visited"', 'scaled', 'completed', 'passed', '--learner']) {
    assert.ok(r.stdout.includes(word), word);
  }
  assert.match(run('--help').stdout, /assignment {4}check an assignment file/);
});
