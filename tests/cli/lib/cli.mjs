// Running the CLI from tests: its JSON, its exit status, its one-line errors.
import { spawnSync } from 'node:child_process';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

export const CLI = process.env.CSPACELAB_CLI;
export const SOURCE = process.env.CSPACELAB_SOURCE;
export const scene = (name) => path.join(SOURCE, 'assets', 'scenes', name);

// Two minutes at most: a call that runs longer has failed (e.g. a budget check gone missing).
export function run(...args) {
  return spawnSync(CLI, args, { encoding: 'utf8', maxBuffer: 64 << 20, timeout: 120000 });
}

const timedOut = (r) => (r.error?.code === 'ETIMEDOUT' ? ' (timed out after 2 min)' : r.signal ? ` (${r.signal})` : '');

/** Runs the CLI, expects success, returns the parsed JSON. */
export function json(...args) {
  const r = run(...args);
  assert.equal(r.status, 0, `cspacelab ${args.join(' ')} failed${timedOut(r)}: ${r.stderr}`);
  assert.equal(r.stderr, '');
  return JSON.parse(r.stdout);
}

/** Runs the CLI, expects exit status 2 and exactly one stderr line matching `pattern`. */
export function fails(pattern, ...args) {
  const r = run(...args);
  assert.equal(r.status, 2, `expected exit 2 from cspacelab ${args.join(' ')}, got ${r.status}${timedOut(r)}: ${r.stdout}`);
  assert.equal(r.stdout, '');
  const lines = r.stderr.trimEnd().split('\n');
  assert.equal(lines.length, 1, `one line of error, got: ${r.stderr}`);
  assert.match(lines[0], /^cspacelab: /);
  assert.match(lines[0], pattern);
}

/** Writes a temporary scene file and returns its path. */
export function tempScene(content) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'csl-'));
  const file = path.join(dir, 'scene.json');
  fs.writeFileSync(file, typeof content === 'string' ? content : JSON.stringify(content));
  return file;
}
