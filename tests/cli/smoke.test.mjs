// The CLI answers --help and --version, and fails cleanly on bad input.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

const CLI = process.env.CSPACELAB_CLI;
const run = (...args) => spawnSync(CLI, args, { encoding: 'utf8' });

test('--help lists the commands', () => {
  const r = run('--help');
  assert.equal(r.status, 0);
  assert.match(r.stdout, /^cspacelab \d+\.\d+\.\d+/);
  assert.match(r.stdout, /validate/);
});

test('--version prints JSON', () => {
  const r = run('--version');
  assert.equal(r.status, 0);
  assert.match(JSON.parse(r.stdout).version, /^\d+\.\d+\.\d+$/);
});

test('unknown commands and options are one-line errors with exit status 2', () => {
  for (const args of [[], ['frobnicate'], ['validate'], ['validate', 'x.json', '--bogus'], ['--version', 'x'],
                      ['help', 'plan', 'x'], ['--help', 'x'], ['visibility', '--x', '0.1', '--y', '0.5', '--gap', '0.1', '--help', '--help']]) {
    const r = run(...args);
    assert.equal(r.status, 2, args.join(' '));
    assert.equal(r.stdout, '');
    assert.equal(r.stderr.trim().split('\n').length, 1);
    assert.match(r.stderr, /^cspacelab: /);
  }
});

test('validate names the offending field of a bad scene', () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'csl-'));
  const bad = path.join(dir, 'bad.json');
  fs.writeFileSync(bad, JSON.stringify({ version: 1, obstacles: [{ type: 'disk', center: [0, 0], radius: -1 }] }));
  let r = run('validate', bad);
  assert.equal(r.status, 2);
  assert.match(r.stderr, /obstacles\[0\]\.radius: must be >= 0/);

  fs.writeFileSync(bad, '{"version": 1,');
  r = run('validate', bad);
  assert.equal(r.status, 2);
  assert.match(r.stderr, /not valid JSON/);

  r = run('validate', path.join(dir, 'missing.json'));
  assert.equal(r.status, 2);
  assert.match(r.stderr, /cannot read file/);

  r = run('validate', dir);
  assert.equal(r.status, 2);
  assert.match(r.stderr, /is a directory, not a scene file/);

  // Past 64 MB no scene is within the limits: refused without reading it all (its valid JSON
  // would otherwise parse).
  const huge = path.join(dir, 'huge.json');
  fs.writeFileSync(huge, ' '.repeat(65 << 20) + '{"version": 1}');
  r = run('validate', huge);
  assert.equal(r.status, 2);
  assert.match(r.stderr, /larger than 64 MB/);
  fs.rmSync(huge);

  const good = path.join(dir, 'good.json');
  fs.writeFileSync(good, JSON.stringify({ version: 1, obstacles: [{ type: 'disk', center: [0.2, 0.05], radius: 0.1 }] }));
  r = run('validate', good);
  assert.equal(r.status, 0, r.stderr);
  assert.equal(JSON.parse(r.stdout).scene.obstacles[0].radius, 0.1);
});
