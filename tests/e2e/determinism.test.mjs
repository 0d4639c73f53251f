// One roadmap, three builds: for a table of (scene, parameters, seed), the roadmap hash from
// the native CLI, from the CLI compiled to wasm and run by node, and from the app in Chromium
// must all be equal (and so must the path).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { withPage, api, cli, DIST } from './lib/harness.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const source = path.resolve(here, '../..');
const wasmCli = path.resolve(DIST, '..', 'src', 'cli', 'cspacelab.js');
const scene = (name) => path.join(source, 'assets', 'scenes', `${name}.json`);

function wasm(...args) {
  const r = spawnSync(process.execPath, [wasmCli, ...args], {
    encoding: 'utf8', maxBuffer: 256 << 20, env: { ...process.env, NODE_OPTIONS: '--no-experimental-fetch' } });
  if (r.status !== 0) throw new Error(`wasm cspacelab ${args.join(' ')}: ${r.stderr}`);
  return JSON.parse(r.stdout);
}

// [scene, lesson that can show it (or null), samples, neighbour rule, checker, seed]
const TABLE = [
  ['p12', 'step-prm', 150, 'k:10', 'bisection', 1],
  ['prm-demo', 'step-prm', 400, 'k:10', 'bisection', 7],
  ['prm-demo', 'step-prm', 400, 'radius:0.12', 'bisection', 8],
  ['wall-gap', 'step-prm', 500, 'prm*', 'bisection', 2],
  ['narrow-passage', 'step-prm', 600, 'k:12', 'grid:7', 3],
  ['arm-2link', 'torus', 400, 'k:10', 'bisection', 3],
  ['arm-2link', 'torus', 300, 'prm*', 'grid:9', 11],
  ['polygon-robot', null, 400, 'k:10', 'bisection', 5],
];

const flags = (rule) => rule === 'prm*' ? ['--prm-star'] : rule.startsWith('k:') ? ['--k', rule.slice(2)] : ['--radius', rule.slice(7)];

test('the same roadmap natively, in wasm under node, and in the browser', () => withPage(async ({ page, browser }) => {
  const rows = [];
  for (const [name, lesson, samples, rule, checker, seed] of TABLE) {
    const args = ['plan', scene(name), '--samples', String(samples), ...flags(rule), '--checker', checker, '--seed', String(seed)];
    const native = cli(...args), inWasm = wasm(...args);
    let browserHash = '-';
    if (lesson) {
      const sceneJson = JSON.parse((await import('node:fs')).readFileSync(scene(name), 'utf8'));
      await api(page, 'restore', { lesson, scene: sceneJson, params: { samples, neighbors: rule, checker, seed } });
      await api(page, 'run');
      const s = await api(page, 'state');
      const st = lesson === 'torus' ? s.prm : s;
      browserHash = st.roadmap_hash;
      assert.equal(browserHash, native.roadmap_hash, `${name} ${rule} ${checker} seed ${seed}: browser`);
      assert.deepEqual(st.path, native.path);
    }
    assert.equal(inWasm.roadmap_hash, native.roadmap_hash, `${name} ${rule} ${checker} seed ${seed}: wasm`);
    assert.deepEqual(inWasm.path, native.path);
    rows.push(`${name.padEnd(15)} ${String(samples).padStart(4)} ${rule.padEnd(12)} ${checker.padEnd(10)} seed ${String(seed).padEnd(3)} ` +
              `native ${native.roadmap_hash}  wasm ${inWasm.roadmap_hash}  browser ${browserHash}`);
  }
  console.log(rows.join('\n'));
}));
