// docs/lessons.md stays what the app says: its generated parts (each lesson's parameters with
// their ranges and defaults, from the API's param_specs; the bundled scenes) are made again from
// the built lab and must equal the committed text, and every lesson has its picture.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { DIST } from './lib/harness.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

test('docs/lessons.md matches the running app', () => {
  const r = spawnSync(process.execPath, [path.join(root, 'scripts/lesson-shots.mjs'), '--check', DIST],
                      { encoding: 'utf8', timeout: 240000 });
  assert.equal(r.status, 0, `${r.stdout}${r.stderr}(node scripts/lesson-shots.mjs makes it again)`);
});
