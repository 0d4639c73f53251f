// Fuzzing of web/lab-url.js, the page's link parser, under node: JavaScript is out of
// libFuzzer's reach, so this is a seeded, time-bounded mutation loop with property checks.
//   node tests/fuzz/fuzz_url.mjs [SECONDS=30] [SEED=from the clock, printed] [MIN_EXECUTIONS=0]
// (CI runs a fixed seed and fails a run of fewer than MIN_EXECUTIONS inputs, or with a kind of
// input left out: a slow or broken generator must not pass as a fuzz run: tests/CMakeLists.txt.)
//   node tests/fuzz/fuzz_url.mjs --replay FILE      (a finding saved by an earlier run)
// Inputs: links built from the bundled scenes (by name, z. and j. encoded), every lesson id and
// parameters of every type, mutated; random text; corrupted scene payloads; random valid states.
// Properties (web/lab-url.js's comments and docs/web.md): parseConfig never throws and returns
// its shape within the limits; parseValue and decodeScene either return the documented type or
// throw a plain Error with one of their messages; messages quote untrusted text printably; and
// a state that buildQuery writes without a problem reads back exactly.
// A broken property prints the input, saves it under $CSPACELAB_ARTIFACTS/fuzz/ and exits 1.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const U = createRequire(import.meta.url)(path.join(root, 'web/lab-url.js'));
const { LIMITS, NAME, STEPS, ID, RESERVED } = U;
const KEY = /^[a-z][a-z0-9_]{0,31}$/;  // a parameter's name, as lab-url.js documents it
const CONTROL = /[\u0000-\u001f\u007f-\u009f]/;
// A number in a link: plain decimal, at most 40 characters (no hex, spaces, NaN or Infinity).
const DECIMAL = /^-?(\d+(\.\d*)?|\.\d+)([eE][-+]?\d{1,3})?$/;
const SCENE_ERRORS = [/ is more than a link may carry$/, /^".*" is neither a bundled scene nor an encoded one/s,
  /^is not base64url$/, /^is more than [\d.]+ [KM]B once decompressed$/, /^is not valid compressed data$/,
  /^is more than [\d.]+ [KM]B$/, /^is not UTF-8 text$/, /^is not JSON$/, /^is not a JSON object$/,
  /^is nested more than \d+ levels deep$/];
const VALUE_ERRORS = [/^not a number$/, /^out of range$/, /^not true or false$/, /^not \d+ comma-separated numbers$/,
  /^cannot be set from a link$/];

// --- seeded randomness (mulberry32): the same seed gives the same inputs, in the same order.
let rng = 1;
const next = () => {
  rng = (rng + 0x6d2b79f5) >>> 0;
  let t = Math.imul(rng ^ (rng >>> 15), 1 | rng);
  t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
  return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
};
const int = (n) => Math.floor(next() * n);
const pick = (a) => a[int(a.length)];

// --- the corpus: bundled scenes, lessons and their parameters (as src/app/lesson_*.cpp report
// them; only the types matter here), and links the app writes for them.
const bundled = {};
for (const f of fs.readdirSync(path.join(root, 'assets/scenes')).sort())
  bundled[path.basename(f, '.json')] = JSON.parse(fs.readFileSync(path.join(root, 'assets/scenes', f), 'utf8'));
const prm = { samples: 200, neighbors: 'k:10', checker: 'bisection', seed: 1 };
const lessons = {
  'step-prm': prm,
  torus: { ...prm, q: [0.5, -1], view: 'both' },
  collision: { grid_n: 4, p: [0, 0], q: [1, 0] },
  analysis: { sample_counts: [50, 100, 200], trials: 100, tab: 'bound', point: [0.5, 0.5], gap: 0.1, mc_trials: 1000 },
  notation: { description: 'base=planar joints=RRR wrist=spherical', mode: 'build', exercise: 0 },
};
const TEMPLATES = [1, false, 'k:10', [0, 0], [0, 0, 0], [1], { a: 1 }];
const DICT = ['&', '=', '?', '%', '%25', '%ZZ', '%E0%A4%A', '%00', '%C3%A9', '%F0%9F%98%80', '%ED%A0%80', '+', ',', ':',
  'lesson=', 'scene=', 'steps=', 'ui=minimal', 'id=', 'samples=', 'seed=', 'neighbors=k:', 'checker=grid:', 'z.', 'j.',
  'p12', 'step-prm', 'collision', '1e999', '-0', 'NaN', 'Infinity', '0x10', '1e-400', '9007199254740993', 'true', '\u0000',
  '\ud800', '😀', '<script>', 'A'.repeat(300), '&'.repeat(70), 'x=1&'.repeat(20)];
const NUMBERS = [0, -0, 1, -1, 0.1, 1 / 3, 5e-324, -5e-324, 2.2250738585072014e-308, Number.MAX_VALUE, -Number.MAX_VALUE,
  2 ** 53, 2 ** 53 + 2, 1e21, 1e-7, 123456789.125];

const links = [];
// Scene payloads (bytes before base64url): JSON, deflated JSON, JSON that is no object, a zip bomb.
const payloads = [zlib.deflateRawSync(Buffer.alloc(2 << 20, 32)), Buffer.from('[1]'), Buffer.from('null'),
                  Buffer.alloc(LIMITS.sceneParam, 65)];
for (const [name, scene] of Object.entries(bundled)) {
  const json = Buffer.from(JSON.stringify(scene));
  payloads.push(json, zlib.deflateRawSync(json));
  for (const lesson of Object.keys(lessons)) {
    const snap = { lesson, scene, params: lessons[lesson], steps: int(500) };
    links.push((await U.buildQuery(snap, bundled)).query, (await U.buildQuery(snap)).query);
  }
  links.push(`lesson=collision&scene=j.${U.toBase64Url(json)}&grid_n=5&ui=full&id=${name}`);
}
links.push('?lesson=no-such-lesson&scene=%%%25&steps=12abc&ui=huge&id=a%20b&bogus=1&x%ZZ=1&BAD=2&&=&grid_n=3', '');

// --- mutations
const randomNumber = () => {
  if (next() < 0.5) return pick(NUMBERS);
  const v = new DataView(new ArrayBuffer(8));
  v.setUint32(0, int(2 ** 32));
  v.setUint32(4, int(2 ** 32));
  const x = v.getFloat64(0);
  return Number.isFinite(x) ? x : next() * 10 - 5;
};
const TEXT = ['a', 'Z', '7', ' ', '&', '=', '%', '+', '#', '?', '/', ',', ':', 'é', '✓', '😀', '"', '<', '\\', '\n', '\u0000'];
const text = (n = int(12)) => Array.from({ length: n }, () => pick(TEXT)).join('');  // well-formed UTF-16
const codeUnits = (n) => String.fromCharCode(...Array.from({ length: n }, () => (next() < 0.7 ? 32 + int(95) : int(0x10000))));

function mutate(s) {
  for (let k = 1 + int(4); k > 0; --k) {
    const i = int(s.length + 1), j = i + int(Math.min(40, s.length - i) + 1);
    switch (int(9)) {
      case 0: s = s.slice(0, i) + pick(DICT) + s.slice(i); break;
      case 1: s = s.slice(0, i) + codeUnits(1 + int(4)) + s.slice(i); break;
      case 2: s = s.slice(0, i) + s.slice(j); break;
      case 3: s = s.slice(0, i) + s.slice(i, j).repeat(2 + int(next() < 0.1 ? 3000 : 3)) + s.slice(j); break;
      case 4: { const o = pick(links), a = int(o.length + 1); s = s.slice(0, i) + o.slice(a, a + int(200)) + s.slice(j); break; }
      case 5: try { s = s.slice(0, i) + encodeURIComponent(s.slice(i, j)) + s.slice(j); } catch { /* lone surrogate */ } break;
      case 6: s = s.replace(/-?\d+(\.\d+)?(e-?\d+)?/, () => String(randomNumber())); break;
      case 7: { const p = s.split('&'); p.splice(int(p.length), 0, ...p.splice(int(p.length), 1 + int(3))); s = p.join('&'); break; }
      default: s = s.slice(0, i) + String.fromCharCode(s.charCodeAt(i) ^ (1 << int(8)) || 65) + s.slice(i + 1);
    }
  }
  return s;
}

function mutateBytes(bytes) {
  const b = [...bytes];
  for (let k = 1 + int(6); k > 0; --k) {
    const i = int(b.length + 1);
    if (next() < 0.4) b[i] = (b[i] ?? 0) ^ (1 << int(8));
    else if (next() < 0.5) b.splice(i, int(8));
    else b.splice(i, 0, ...Array.from({ length: 1 + int(4) }, () => int(256)));
  }
  return Uint8Array.from(b, (x) => x & 255);
}

// --- properties
const printable = (m) => typeof m === 'string' && !CONTROL.test(m) && m.length < 400;

function checkValue(raw, template) {
  let r;
  try {
    r = U.parseValue(raw, template);
  } catch (e) {
    assert.equal(e.constructor, Error, `parseValue threw ${e}`);
    assert.ok(VALUE_ERRORS.some((x) => x.test(e.message)), `parseValue: undocumented error "${e.message}"`);
    return;
  }
  const number = (x, text) => Number.isFinite(x) && Object.is(x, Number(text)) && DECIMAL.test(text) && text.length <= 40;
  if (typeof template === 'number') assert.ok(number(r, raw), `number ${r} from ${JSON.stringify(raw)}`);
  else if (typeof template === 'boolean') assert.ok(['true', '1', 'false', '0'].includes(raw) && r === (raw === 'true' || raw === '1'));
  else if (typeof template === 'string') assert.equal(r, raw);
  else if (Array.isArray(template))
    assert.ok(Array.isArray(r) && r.length === template.length && r.every((x, i) => number(x, raw.split(',')[i])), `list ${r}`);
  else assert.fail(`parseValue accepted ${JSON.stringify(r)} for an object`);
}

async function checkScene(text) {
  const t0 = Date.now();
  let scene;
  try {
    scene = await U.decodeScene(text);
  } catch (e) {
    assert.equal(e.constructor, Error, `decodeScene threw ${e}`);
    assert.ok(SCENE_ERRORS.some((x) => x.test(e.message)) && printable(e.message), `decodeScene: "${e.message}"`);
  }
  if (scene !== undefined) assert.ok(scene !== null && typeof scene === 'object' && !Array.isArray(scene), 'not an object');
  assert.ok(Date.now() - t0 < 5000, 'decodeScene took over 5 s');
}

async function checkLink(s) {
  const { values, problems } = U.parseConfig(s);
  assert.ok(values instanceof Map && Array.isArray(problems), 'shape');
  assert.ok(values.size <= LIMITS.entries && problems.length <= LIMITS.entries + 1, 'counts');
  assert.ok(problems.every(printable), `unprintable problem ${JSON.stringify(problems)}`);
  const query = s.startsWith('?') ? s.slice(1) : s;
  const keys = query.split('&').slice(0, LIMITS.entries).map((p) => {  // each piece's key, as documented
    const raw = p.split('=')[0];
    try { return raw.length <= 64 ? decodeURIComponent(raw.replace(/\+/g, ' ')) : null; } catch { return null; }
  });
  for (const [k, v] of values) {
    assert.ok(KEY.test(k) && typeof v === 'string', `key ${k}`);
    assert.ok(v.length <= (k === 'scene' ? LIMITS.sceneParam : LIMITS.value), `${k}: ${v.length} characters`);
    assert.equal(keys.filter((x) => x === k).length, 1, `${k} read although given ${keys.filter((x) => x === k).length} times`);
    if (k === 'scene' && !NAME.test(v)) await checkScene(v);
    else if (k === 'steps' && STEPS.test(v)) assert.ok(Number.isSafeInteger(Number(v)) && Number(v) >= 0);
    else if (k === 'id') {
      // The autosave slot's name, against the documented rule written out without a regex.
      const rule = v.length >= 1 && v.length <= 40 && [...v].every((c) => /^[A-Za-z0-9_-]$/.test(c));
      assert.equal(ID.test(v), rule, `id ${JSON.stringify(v)}`);
    }
    else if (!RESERVED.has(k)) for (const t of TEMPLATES) checkValue(v, t);
  }
  assert.equal(typeof U.hasState(values), 'boolean');
  assert.match(U.stateKey(values), /^\d+:[0-9a-f]{8}$/);
}

function randomState() {
  const lesson = pick(Object.keys(lessons));
  let scene = next() < 0.3 ? null : structuredClone(pick(Object.values(bundled)));
  if (scene && next() < 0.5) {
    scene = JSON.parse(JSON.stringify(scene), (k, v) => (typeof v === 'number' && next() < 0.3 ? randomNumber() : v));
    if (next() < 0.5) scene.name = text(int(40));
  }
  const params = {};
  for (const [k, v] of Object.entries(lessons[lesson])) {
    if (next() < 0.3) continue;
    if (typeof v === 'number') params[k] = randomNumber();
    else if (typeof v === 'string') params[k] = next() < 0.1 ? text(100 + int(100)) : text();
    else params[k] = v.map(randomNumber);
  }
  if (next() < 0.2) params[pick(['on', 'flag'])] = next() < 0.5;
  return { lesson, scene, params, steps: int(next() < 0.9 ? 1000 : 1e9) };
}

async function checkRoundTrip(snap) {
  const { query, problems } = await U.buildQuery(snap, bundled);
  assert.ok(typeof query === 'string' && problems.every(printable), 'buildQuery shape');
  await checkLink(query);
  if (problems.length) return;  // the link says it is inexact
  const back = U.parseConfig(query);
  assert.deepEqual(back.problems, [], 'a link buildQuery wrote without a problem has problems');
  const v = back.values;
  assert.equal(v.get('lesson'), snap.lesson);
  assert.equal(Number(v.get('steps')), snap.steps);
  // Exactly as JSON text: every number to the last bit, types, key order. Not the sign of a zero:
  // the page hands states to the app as JSON (lab-api.js), where JSON.stringify writes -0 as 0.
  const same = (a, b, what) => assert.equal(JSON.stringify(a), JSON.stringify(b), what);
  if (snap.scene) {
    const raw = v.get('scene');
    same(NAME.test(raw) ? bundled[raw] : await U.decodeScene(raw), snap.scene, 'scene');
  }
  for (const [k, x] of Object.entries(snap.params)) same(U.parseValue(v.get(k), x), x, `parameter ${k}`);
  assert.equal(v.size, 2 + (snap.scene ? 1 : 0) + Object.keys(snap.params).length, 'extra keys');
}

// --- the loop
const kinds = {
  link: (x) => checkLink(x),
  scene: (x) => checkScene(x),
  value: ([raw, t]) => checkValue(raw, t),
  roundtrip: (x) => checkRoundTrip(x),
};
function generate() {
  const r = next();
  if (r < 0.45) return ['link', mutate(pick(links))];
  if (r < 0.55) return ['link', codeUnits(int(200))];
  if (r < 0.7) {
    const bytes = mutateBytes(pick(payloads));
    return ['scene', (bytes[0] === 123 || next() < 0.3 ? 'j.' : 'z.') + U.toBase64Url(bytes)];
  }
  if (r < 0.8) return ['value', [mutate(pick([String(randomNumber()), text(), '1,2', 'true', pick(DICT)])), pick(TEMPLATES)]];
  return ['roundtrip', randomState()];
}

async function run(kind, input, where) {
  try {
    await kinds[kind](input);
  } catch (e) {
    const dir = path.join(process.env.CSPACELAB_ARTIFACTS || os.tmpdir(), 'fuzz');
    fs.mkdirSync(dir, { recursive: true });
    const file = path.join(dir, `fuzz_url-${Date.now()}.json`);
    fs.writeFileSync(file, JSON.stringify({ kind, input }));
    console.log(`FINDING (${where}): ${e.message}\n${kind} input: ${JSON.stringify(input).slice(0, 2000)}\nsaved: ${file}` +
                `\nreplay: node tests/fuzz/fuzz_url.mjs --replay ${file}`);
    process.exit(1);
  }
}

if (process.argv[2] === '--replay') {
  const { kind, input } = JSON.parse(fs.readFileSync(process.argv[3], 'utf8'));
  await run(kind, input, 'replay');
  console.log('fuzz_url: the input passes');
} else {
  const seconds = Number(process.argv[2] || 30);
  const seed = Number(process.argv[3] || Date.now() % 2 ** 31);
  rng = seed >>> 0;
  const counts = { link: 0, scene: 0, value: 0, roundtrip: 0 };
  const t0 = Date.now();
  let n = 0;
  while (Date.now() - t0 < seconds * 1000) {
    const [kind, input] = generate();
    await run(kind, input, `seed ${seed}, execution ${n}`);
    ++counts[kind];
    ++n;
  }
  console.log(`fuzz_url: ${n} executions in ${seconds} s (seed ${seed}): ` +
              Object.entries(counts).map(([k, c]) => `${c} ${k}`).join(', '));
  const least = Number(process.argv[4] || 0);
  const starved = Object.entries(counts).filter(([, c]) => c < least / 20).map(([k]) => k);
  if (n < least || starved.length) {
    console.error(`fuzz_url: too little fuzzing: ${n} executions (at least ${least} asked)` +
                  (starved.length ? `, too few of ${starved.join(', ')} (at least ${least / 20} each)` : ''));
    process.exitCode = 1;
  }
}
