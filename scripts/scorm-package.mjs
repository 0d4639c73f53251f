// Turns an assignment file into SCORM packages an LMS imports (Moodle, Canvas, Blackboard,
// Brightspace): the built site, the assignment, a launch page and imsmanifest.xml, zipped.
//   node scripts/scorm-package.mjs ASSIGNMENT.json --dist DIST --out DIR [--version 1.2|2004|both]
// writes DIR/NAME-scorm12.zip and/or DIR/NAME-scorm2004.zip (NAME: the file's name without
// .json) and prints {"packages": [{version, file, bytes, files}]}.
//
// The assignment is checked first with `cspacelab assignment validate` (the CLI at
// $CSPACELAB_CLI, else build/native/src/cli/cspacelab; a .js CLI, the wasm build's, runs under
// node): an invalid one is refused with the CLI's message, which names each item and field.
// DIST is the built site (build/wasm/dist); its single-file page is left out (it repeats the wasm).
// The launch page is the site's index.html with the lab configured as
// data-lab="assignment=assignment.json" (web/lab-assignment.js then finds the LMS's API object,
// web/lab-url.js, docs/web.md, Assignments): same scripts, same Content-Security-Policy.
// The 1.2 manifest sets adlcp:masteryscore (the assignment's pass as a percentage; the lab reports
// 1.2's raw score as a percentage); 2004 (4th edition) a primary objective satisfied by measure
// with minNormalizedMeasure = pass, which the LMS gives the lab as cmi.scaled_passing_score.
// All of that is web/lab-scorm-package.js, shared with the page's Author view.
import fs from 'node:fs';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { createRequire } from 'node:module';
import { writeZip } from './zip.mjs';
import { listFiles } from './list-files.mjs';

const HERE = path.dirname(fileURLToPath(import.meta.url));
// The manifests, the launch page and the entries' order: the same code as the page's Author
// view (web/lab-author.js) packages with.
const P = createRequire(import.meta.url)('../web/lab-scorm-package.js');

const USAGE = 'usage: node scripts/scorm-package.mjs ASSIGNMENT.json --dist DIST --out DIR [--version 1.2|2004|both]';
const HELP = `${USAGE}

Writes DIR/NAME-scorm12.zip and/or DIR/NAME-scorm2004.zip (NAME: the assignment file's name
without .json), SCORM packages an LMS imports, and prints {"packages": [{version, file, bytes,
files}]}. Each holds the built site DIST (build/wasm/dist, without cspacelab-single.html), the
assignment as assignment.json, launch.html (the lab in assignment mode) and imsmanifest.xml.

  --dist DIST      the built site (cspacelab.wasm, index.html, the scripts)
  --out DIR        where the zips go (made if missing)
  --version V      1.2, 2004 (4th edition) or both (default)

The assignment is checked with 'cspacelab assignment validate' first: $CSPACELAB_CLI, else
build/native/src/cli/cspacelab. An invalid one is refused (exit status 2) with the CLI's
message naming each item and field. docs/web.md, "Assignments in an LMS (SCORM)", has the rest.`;

function fail(message, code = 2) {
  process.stderr.write(`scorm-package: ${message}\n`);
  process.exit(code);
}

function parseArgs(argv) {
  const opts = { version: 'both' };
  const rest = [];
  for (let i = 0; i < argv.length; ++i) {
    const a = argv[i];
    if (a === '--help' || a === '-h') {
      process.stdout.write(HELP + '\n');
      process.exit(0);
    }
    if (a === '--dist' || a === '--out' || a === '--version') {
      if (i + 1 >= argv.length) fail(`${a} needs a value\n${USAGE}`);
      opts[a.slice(2)] = argv[++i];
    } else if (a.startsWith('--')) {
      fail(`unknown option ${a}\n${USAGE}`);
    } else {
      rest.push(a);
    }
  }
  if (rest.length !== 1 || !opts.dist || !opts.out) fail(USAGE);
  if (!['1.2', '2004', 'both'].includes(opts.version)) fail(`--version: 1.2, 2004 or both, not '${opts.version}'`);
  opts.assignment = rest[0];
  return opts;
}

/** `cspacelab assignment validate FILE`'s JSON, or exits with the CLI's own message. */
function validate(file) {
  const cli = process.env.CSPACELAB_CLI || path.resolve(HERE, '../build/native/src/cli/cspacelab');
  if (!fs.existsSync(cli)) fail(`no cspacelab CLI at ${cli}: build it or set CSPACELAB_CLI`);
  const [cmd, args] = cli.endsWith('.js') ? [process.execPath, [cli]] : [cli, []];
  const run = spawnSync(cmd, [...args, 'assignment', 'validate', file], {
    encoding: 'utf8', env: { ...process.env, NODE_OPTIONS: '--no-experimental-fetch' } });
  if (run.error) fail(`could not run ${cli}: ${run.error.message}`);
  if (run.status !== 0) fail(`the assignment is not valid: ${(run.stderr || run.stdout).trim().replace(/^cspacelab: /, '')}`);
  return JSON.parse(run.stdout);
}

async function main() {
  const opts = parseArgs(process.argv.slice(2));
  if (!fs.existsSync(opts.assignment)) fail(`${opts.assignment}: no such file`);
  if (!fs.existsSync(path.join(opts.dist, 'cspacelab.wasm')) || !fs.existsSync(path.join(opts.dist, 'index.html')))
    fail(`${opts.dist} is not the built site (no cspacelab.wasm or index.html): build cspacelab_app and cspacelab_web for wasm`);
  const checked = validate(opts.assignment);
  const name = path.basename(opts.assignment).replace(/\.json$/i, '') || 'assignment';
  const site = listFiles(opts.dist).filter(P.packaged).map((f) => ({ name: f, data: fs.readFileSync(path.join(opts.dist, f)) }));
  const indexHtml = fs.readFileSync(path.join(opts.dist, 'index.html'), 'utf8');
  const assignmentBytes = fs.readFileSync(opts.assignment);
  fs.mkdirSync(opts.out, { recursive: true });
  const packages = [];
  for (const version of opts.version === 'both' ? ['1.2', '2004'] : [opts.version]) {
    const entries = P.packageEntries({ version, checked, name, assignmentBytes, indexHtml, site });
    const file = path.join(opts.out, P.zipName(name, version));
    const zip = await writeZip(entries);
    fs.writeFileSync(file, zip);
    packages.push({ version, file, bytes: zip.length, files: entries.length });
  }
  process.stdout.write(JSON.stringify({ packages }, null, 2) + '\n');
}

main().catch((e) => fail(e && e.message ? e.message : String(e), 1));
