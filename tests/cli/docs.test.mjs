// The scene format's reference (docs/lessons.md) holds scenes that validate: every ```json block
// of it is given to `cspacelab validate`, which must take it and read back what the block says;
// and its table of fields names every field a normalised scene has, so a new field of the schema
// cannot go undocumented.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

const CLI = process.env.CSPACELAB_CLI;
const SOURCE = process.env.CSPACELAB_SOURCE || path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const DOC = path.join(SOURCE, 'docs/lessons.md');

function validate(scene) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'csl-doc-'));
  const file = path.join(dir, 'scene.json');
  fs.writeFileSync(file, scene);
  const r = spawnSync(CLI, ['validate', file], { encoding: 'utf8' });
  fs.rmSync(dir, { recursive: true });
  return r;
}

const text = fs.readFileSync(DOC, 'utf8');
const blocks = [...text.matchAll(/```json\n([\s\S]*?)```/g)].map((m) => m[1]);

test('every JSON example of docs/lessons.md is a scene cspacelab validate takes as written', () => {
  assert.ok(blocks.length >= 4, `the doc has its examples (${blocks.length} found)`);
  for (const block of blocks) {
    const r = validate(block);
    assert.equal(r.status, 0, `${block}\n${r.stderr}`);
    const out = JSON.parse(r.stdout);
    assert.equal(out.valid, true);
    // What the block gives comes back (the rest is the defaults the doc lists).
    const given = JSON.parse(block);
    for (const [key, value] of Object.entries(given)) {
      if (key === 'start' || key === 'goal') {
        value.forEach((v, i) => assert.ok(Math.abs(out.scene[key][i] - v) < 1e-12, `${key}[${i}]`));
      } else {
        assert.deepEqual(out.scene[key], value, key);
      }
    }
  }
});

test('the doc\'s table of fields names every field of a normalised scene', () => {
  const fields = new Set([...text.matchAll(/^\| `([a-z_]+)` \| /gm)].map((m) => m[1]));
  const full = JSON.parse(validate(blocks[1]).stdout).scene;
  for (const key of Object.keys(full)) assert.ok(fields.has(key), `the field ${key} has a row`);
  // And the defaults the doc gives for the smallest scene are the CLI's.
  const least = JSON.parse(validate('{"version": 1}').stdout).scene;
  assert.deepEqual(least.workspace, { min: [0, 0], max: [1, 1] });
  assert.deepEqual(least.robot, { type: 'point' });
  assert.deepEqual([least.obstacles, least.start, least.goal], [[], [0, 0], [1, 1]]);
});

test('every robot type and obstacle type the CLI knows has a row in the doc', () => {
  const r = spawnSync(CLI, ['help', 'validate'], { encoding: 'utf8' });
  const types = new Set([...r.stdout.matchAll(/"type": "([a-z0-9]+)"/g)].map((m) => m[1]));
  assert.ok(types.size >= 6, [...types].join(', '));
  for (const t of types) assert.match(text, new RegExp('^\\| `' + t + '` \\| ', 'm'), `the type ${t} has a row`);
});

test('the link keys lesson and hide name every lesson id and every hideable answer the core lists', () => {
  const r = spawnSync(CLI, ['link', '--list'], { encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  const list = JSON.parse(r.stdout);
  const row = (key) => {
    const m = text.match(new RegExp('^\\| `' + key + '` \\| (.*)$', 'm'));
    assert.ok(m, `the link key ${key} has a row`);
    return m[1];
  };
  const lessonRow = row('lesson');
  assert.ok(list.lessons.length >= 7, 'the core lists the lessons');
  for (const { id } of list.lessons) assert.ok(lessonRow.includes('`' + id + '`'), `lesson id ${id} in the lesson row`);
  const hideRow = row('hide');
  for (const { name } of list.answers) assert.ok(hideRow.includes('`' + name + '`'), `answer ${name} in the hide row`);
  for (const key of ['lock', 'reveal', 'task', 'camera', 'scheme', 'contrast']) row(key);
});
