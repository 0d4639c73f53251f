// Runs the PRM benchmark natively and as wasm under node, and prints the wasm/native ratio
// of our time per milestone for every row.
//   node tests/bench/compare_wasm.mjs [build/native] [build/wasm]
import { execFileSync } from 'node:child_process';
import path from 'node:path';

const native = process.argv[2] || 'build/native';
const wasm = process.argv[3] || 'build/wasm';
const run = (cmd, args, env = {}) =>
  JSON.parse(execFileSync(cmd, args, { encoding: 'utf8', env: { ...process.env, ...env } }));

// Native and wasm take turns, five rounds, each row keeping its fastest: this machine's speed
// drifts over a minute, and one run of each compared two different machines. (Three rounds
// still gave 1.16-1.34 in one run and 1.31-1.70 in the next, minutes apart: either side could
// miss every quiet spell.)
const fastest = (runs) => runs[0].map((row, i) => runs.reduce((best, r) => (r[i].ours_us < best.ours_us ? r[i] : best), row));
const nativeRuns = [], wasmRuns = [];
for (let round = 0; round < 5; ++round) {
  nativeRuns.push(run(path.join(native, 'tests/bench/cspacelab_bench_prm'), ['--json']));
  wasmRuns.push(run(process.execPath, [path.join(wasm, 'tests/bench/cspacelab_bench_prm.js'), '--json'],
                    { NODE_OPTIONS: '--no-experimental-fetch' }));
}
const n = fastest(nativeRuns), w = fastest(wasmRuns);
console.log('scene                       samples  native us/ms  wasm us/ms  wasm/native');
for (let i = 0; i < n.length; ++i) {
  const ratio = w[i].ours_us / n[i].ours_us;
  console.log(`${n[i].scene.padEnd(27)} ${String(n[i].samples).padStart(7)} ${n[i].ours_us.toFixed(3).padStart(13)} ` +
              `${w[i].ours_us.toFixed(3).padStart(11)} ${ratio.toFixed(2).padStart(11)}x`);
  if (n[i].milestones !== w[i].milestones) {
    console.log(`MISMATCH: ${n[i].milestones} milestones natively, ${w[i].milestones} in wasm`);
    process.exitCode = 1;
  }
}
