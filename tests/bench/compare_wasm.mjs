// Runs the PRM benchmark (or another: prm, rrt, lazy, volume) natively and as wasm under node, and
// prints the wasm/native ratio of our time per milestone (rrt, lazy: per solved query; volume: per
// 3-D C-space volume) for every row: the ratio of the medians over the rounds, and of the fastest.
//   node tests/bench/compare_wasm.mjs [build/native] [build/wasm] [prm|rrt|lazy|volume]
// Both builds time CPU seconds (bench_common.hpp's Timer: natively the process's CPU clock, in
// wasm node's process.cpuUsage()), so that other work on a shared machine stays out of the ratio.
import { execFileSync } from 'node:child_process';
import path from 'node:path';

const native = process.argv[2] || 'build/native';
const wasm = process.argv[3] || 'build/wasm';
const bench = process.argv[4] || 'prm';
if (!['prm', 'rrt', 'lazy', 'volume'].includes(bench)) throw new Error(`no benchmark '${bench}' (prm, rrt, lazy or volume)`);
const unit = bench === 'rrt' || bench === 'lazy' ? 'us/query' : 'us/ms';
const run = (cmd, args, env = {}) =>
  JSON.parse(execFileSync(cmd, args, { encoding: 'utf8', env: { ...process.env, ...env } }));

// Native and wasm take turns, five rounds: this machine's speed drifts over a minute, and one run
// of each compared two different machines. (Three rounds still gave 1.16-1.34 in one run and
// 1.31-1.70 in the next, minutes apart: either side could miss every quiet spell.) Each row keeps
// its fastest round, and its median round's time: the machine is shared, and the median is what
// a load that comes and goes leaves of each side.
const time = bench === 'volume' ? (row) => row.ms : (row) => row.ours_us;
const fastest = (runs) => runs[0].map((row, i) => runs.reduce((best, r) => (time(r[i]) < time(best) ? r[i] : best), row));
const median = (runs) => runs[0].map((row, i) => {
  const times = runs.map((r) => time(r[i])).sort((a, b) => a - b);
  const m = times.length >> 1;
  return times.length % 2 ? times[m] : 0.5 * (times[m - 1] + times[m]);
});
const nativeRuns = [], wasmRuns = [];
for (let round = 0; round < 5; ++round) {
  nativeRuns.push(run(path.join(native, `tests/bench/cspacelab_bench_${bench}`), ['--json']));
  wasmRuns.push(run(process.execPath, [path.join(wasm, `tests/bench/cspacelab_bench_${bench}.js`), '--json'],
                    { NODE_OPTIONS: '--no-experimental-fetch' }));
}
const n = fastest(nativeRuns), w = fastest(wasmRuns);
const nMedian = median(nativeRuns), wMedian = median(wasmRuns);
if (bench === 'volume') {
  // Rows {scene, ms, brute_ms, free, differ}: the free fractions must be the same bits.
  console.log(`${'volume'.padEnd(20)} ${'native ms'.padStart(10)} ${'wasm ms'.padStart(10)}  wasm/native`);
  for (let i = 0; i < n.length; ++i) {
    console.log(`${n[i].scene.padEnd(20)} ${n[i].ms.toFixed(2).padStart(10)} ${w[i].ms.toFixed(2).padStart(10)} ` +
                `${(w[i].ms / n[i].ms).toFixed(2).padStart(11)}x`);
    if (n[i].free !== w[i].free) {
      console.log(`MISMATCH: free fraction ${n[i].free} natively, ${w[i].free} in wasm`);
      process.exitCode = 1;
    }
  }
  process.exit();
}
console.log(`${'scene'.padEnd(40)} samples ${('native ' + unit).padStart(15)} ${('wasm ' + unit).padStart(13)}  wasm/native` +
            '  (fastest: native, wasm, wasm/native)');
for (let i = 0; i < n.length; ++i) {
  const ratio = wMedian[i] / nMedian[i];
  console.log(`${n[i].scene.padEnd(40)} ${String(n[i].samples).padStart(7)} ${nMedian[i].toFixed(3).padStart(15)} ` +
              `${wMedian[i].toFixed(3).padStart(13)} ${ratio.toFixed(2).padStart(11)}x` +
              `  (${n[i].ours_us.toFixed(3)}, ${w[i].ours_us.toFixed(3)}, ${(w[i].ours_us / n[i].ours_us).toFixed(2)}x)`);
  if (n[i].milestones !== w[i].milestones || n[i].checks !== w[i].checks) {
    console.log(`MISMATCH: ${n[i].milestones} milestones (solved), ${n[i].checks} checks natively; ` +
                `${w[i].milestones}, ${w[i].checks} in wasm`);
    process.exitCode = 1;
  }
}
