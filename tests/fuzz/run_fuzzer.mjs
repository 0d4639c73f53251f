// Runs one libFuzzer target for a bounded time, from a seed corpus copied into a scratch
// directory (the sources stay untouched), and reports its executions.
//   node tests/fuzz/run_fuzzer.mjs FUZZER SECONDS [libFuzzer flags, which win over the defaults]
// Seeds: tests/fuzz/corpus/<target>/* (valid inputs and regression inputs of past findings),
// for fuzz_scene also assets/scenes/*.json. A finding's input is kept under
// $CSPACELAB_ARTIFACTS/fuzz/ and the run fails.
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

const [fuzzer, seconds = '30', ...extra] = process.argv.slice(2);
const source = process.env.CSPACELAB_SOURCE;
const name = path.basename(fuzzer);
const corpus = fs.mkdtempSync(path.join(os.tmpdir(), `${name}-`));
// Per target: more seed folders, and libFuzzer flags. fuzz_cli: a command line of 2 KB already
// holds hundreds of options (Args erases per option, quadratic in their number: fine for real
// command lines, not for 64 KB of them); a capped run takes milliseconds, so 5 s is a hang.
const targets = {
  fuzz_scene: { seeds: ['assets/scenes'], flags: [] },
  fuzz_cli: { seeds: [], flags: ['-max_len=2048', '-timeout=5'] },
};
const target = targets[name] || { seeds: [], flags: [] };
const seeds = [...target.seeds.map((d) => path.join(source, d)), path.join(source, 'tests', 'fuzz', 'corpus', name)];
for (const dir of seeds)
  if (fs.existsSync(dir))
    for (const f of fs.readdirSync(dir)) fs.copyFileSync(path.join(dir, f), path.join(corpus, `${path.basename(dir)}-${f}`));
const artifacts = path.join(process.env.CSPACELAB_ARTIFACTS || os.tmpdir(), 'fuzz') + path.sep;
fs.mkdirSync(artifacts, { recursive: true });
const args = [`-max_total_time=${seconds}`, `-artifact_prefix=${artifacts}${name}-`, '-print_final_stats=1',
              '-max_len=65536', '-timeout=10', '-rss_limit_mb=2048', ...target.flags, ...extra, corpus];
const dict = path.join(source, 'tests', 'fuzz', `${name.replace(/^fuzz_/, '')}.dict`);
if (fs.existsSync(dict)) args.unshift(`-dict=${dict}`);
const r = spawnSync(fuzzer, args, { encoding: 'utf8', maxBuffer: 256 << 20,
                                    env: { ...process.env, ASAN_OPTIONS: 'detect_leaks=1' } });
const log = r.stderr || '';
const runs = /stat::number_of_executed_units:\s*(\d+)/.exec(log);
const cov = [...log.matchAll(/cov: (\d+)/g)].pop();
console.log(`${name}: ${runs ? runs[1] : '?'} executions in ${seconds} s, coverage ${cov ? cov[1] : '?'} edges, ` +
            `corpus ${fs.readdirSync(corpus).length} inputs`);
if (r.status !== 0) {
  console.log(log.split('\n').slice(-60).join('\n'));
  console.log(`FINDING: see ${artifacts}`);
}
fs.rmSync(corpus, { recursive: true, force: true });
process.exit(r.status ?? 1);
