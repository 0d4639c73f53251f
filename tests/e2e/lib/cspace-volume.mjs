// The exact C-space volume as the CLI computes it, for the 3-D lesson's tests to check the page's
// numbers against a computation that is not the page's.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { cli, tempJson } from './harness.mjs';

/** The free fraction of `scene`'s volume at R x R x K cells (`cspacelab cspace --out`): the share
 *  of 255 bytes (free cells) in the file it writes. */
export function cliFreeFraction(scene, [r, , k]) {
  const file = tempJson(scene);
  const out = file.replace(/scene\.json$/, 'volume.bin');
  cli('cspace', file, '--resolution', String(r), '--slices', String(k), '--out', out);
  const bytes = fs.readFileSync(out);
  assert.equal(bytes.length, r * r * k);
  let free = 0;
  for (const b of bytes) free += b === 255;
  return free / bytes.length;
}
