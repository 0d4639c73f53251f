// web/lab-url.js under node (it runs unchanged there): strict parsing, exact round trips of
// parameters and scenes through links, and the limits.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import zlib from 'node:zlib';

const require = createRequire(import.meta.url);
const U = require('../../web/lab-url.js');

// A small deterministic generator (xorshift32) for the property tests.
function rng(seed) {
  let s = seed >>> 0 || 1;
  return () => {
    s ^= s << 13; s >>>= 0;
    s ^= s >>> 17;
    s ^= s << 5; s >>>= 0;
    return s / 4294967296;
  };
}

function randomScene(r) {
  const n = Math.floor(r() * 30);
  const num = () => (r() < 0.2 ? Math.round(r() * 100) / 100 : r() * 2 - 0.5);  // short and full-precision values
  const obstacles = [];
  for (let i = 0; i < n; ++i) {
    const k = r();
    if (k < 0.4) obstacles.push({ type: 'disk', center: [num(), num()], radius: r() * 0.2 });
    else if (k < 0.7) obstacles.push({ type: 'segment', a: [num(), num()], b: [num(), num()] });
    else obstacles.push({ type: 'polygon', vertices: [[num(), num()], [num(), num()], [num(), num()]] });
  }
  return { version: 1, name: 'scène ' + Math.floor(r() * 1e6) + ' ✓ "q" <b>', workspace: { min: [0, 0], max: [1, 1] },
           robot: { type: 'point' }, obstacles, start: [num(), num()], goal: [num(), num()] };
}

test('scenes survive encode/decode exactly, in both forms', async () => {
  const r = rng(7);
  for (let i = 0; i < 60; ++i) {
    const scene = randomScene(r);
    const z = await U.encodeScene(scene);
    assert.match(z, /^z\.[A-Za-z0-9_-]+$/);
    assert.deepEqual(await U.decodeScene(z), scene);
    const j = 'j.' + U.toBase64Url(new TextEncoder().encode(JSON.stringify(scene)));
    assert.deepEqual(await U.decodeScene(j), scene);
    assert.ok(z.length < j.length, 'deflate makes it shorter');
  }
});

test('decoding refuses what is not a scene, and stops zip bombs', async () => {
  const bomb = 'z.' + zlib.deflateRawSync(Buffer.alloc(4 << 20, 32)).toString('base64url');
  await assert.rejects(U.decodeScene(bomb), /more than 1\.0 MB once decompressed/);
  await assert.rejects(U.decodeScene('x.abc'), /neither a bundled scene nor an encoded one/);
  await assert.rejects(U.decodeScene('z.a'), /not base64url/);
  await assert.rejects(U.decodeScene('z.a+b'), /not base64url/);
  await assert.rejects(U.decodeScene('z.' + Buffer.from('junk').toString('base64url')), /not valid compressed data/);
  await assert.rejects(U.decodeScene('j.' + Buffer.from([0xff, 0xfe]).toString('base64url')), /not UTF-8/);
  await assert.rejects(U.decodeScene('j.' + Buffer.from('1').toString('base64url')), /not a JSON object/);
  await assert.rejects(U.decodeScene('j.' + Buffer.from('{"a":').toString('base64url')), /not JSON/);
  await assert.rejects(U.decodeScene('j.' + 'A'.repeat(70000)), /more than a link may carry/);
});

test('parseConfig: values by key, and every problem named', () => {
  const { values, problems } = U.parseConfig('?lesson=step-prm&neighbors=k%3A8&p=0.5,1e-3&seed=7&seed=8&Bad=1&x%ZZ=2&&scene=' +
                                              'z.' + 'A'.repeat(70000) + '&c=%E0%A4%A&name=a+b');
  assert.deepEqual([...values], [['lesson', 'step-prm'], ['neighbors', 'k:8'], ['p', '0.5,1e-3'], ['name', 'a b']]);
  assert.deepEqual(problems, ['seed is given more than once', '"Bad" is not a parameter', '"x%ZZ" is not a parameter',
                              'scene: 68 KB is more than a link may carry (64 KB)', 'c: "%E0%A4%A" is not properly escaped']);
  assert.deepEqual(U.parseConfig('').values.size, 0);
  assert.deepEqual(U.parseConfig(null).values.size, 0);
  const many = U.parseConfig(Array.from({ length: 100 }, (_, i) => `k${i}=1`).join('&'));
  assert.equal(many.values.size, 64);
  assert.match(many.problems[0], /100 parts; at most 64/);
  assert.equal(U.parseConfig('a=' + 'x'.repeat(300)).problems[0], 'a: 300 characters is more than a link may carry (256 characters)');
  assert.equal(U.hasState(U.parseConfig('ui=minimal&id=x').values), false);
  assert.equal(U.hasState(U.parseConfig('ui=minimal&steps=3').values), true);
});

test('parseValue follows the type of the current value, strictly', () => {
  assert.equal(U.parseValue('7', 1), 7);
  assert.equal(U.parseValue('-0.25', 1), -0.25);
  assert.equal(U.parseValue('1e-3', 1), 0.001);
  for (const bad of ['', ' 7', '7 ', '0x10', '1e', '--1', 'NaN', 'Infinity', '1,2', '1'.repeat(41)])
    assert.throws(() => U.parseValue(bad, 1), /not a number/, JSON.stringify(bad));
  assert.throws(() => U.parseValue('1e999', 1), /out of range/);
  assert.deepEqual(U.parseValue('0.5,-1', [0, 0]), [0.5, -1]);
  assert.throws(() => U.parseValue('0.5', [0, 0]), /not 2 comma-separated numbers/);
  assert.equal(U.parseValue('true', false), true);
  assert.throws(() => U.parseValue('yes', false), /not true or false/);
  assert.equal(U.parseValue('<script>', 'k:10'), '<script>', 'strings go to the app, which checks them');
  assert.throws(() => U.parseValue('{}', { a: 1 }), /cannot be set from a link/);
});

test('buildQuery writes what parseConfig reads back, numbers to the last bit', async () => {
  const r = rng(99);
  for (let i = 0; i < 200; ++i) {
    const params = { seed: Math.floor(r() * 2 ** 40), p: [r() * 10 - 5, r() / 3], radius: r() * 1e-7, neighbors: 'radius:' + r(), on: r() < 0.5 };
    const snapshot = { lesson: 'step-prm', scene: null, params, steps: Math.floor(r() * 1e6) };
    const { query, problems } = await U.buildQuery(snapshot);
    assert.deepEqual(problems, []);
    const { values, problems: p2 } = U.parseConfig(query);
    assert.deepEqual(p2, []);
    assert.equal(values.get('lesson'), 'step-prm');
    assert.equal(Number(values.get('steps')), snapshot.steps);
    for (const [k, v] of Object.entries(params)) assert.deepEqual(U.parseValue(values.get(k), v), v, k);
  }
  const bundled = { p12: { version: 1, name: 'P12' } };
  assert.match((await U.buildQuery({ lesson: 'collision', scene: { version: 1, name: 'P12' }, params: {}, steps: 0 }, bundled)).query,
               /^lesson=collision&scene=p12&steps=0$/);
  const big = { version: 1, obstacles: Array.from({ length: 400 }, (_, i) => ({ type: 'disk', center: [Math.sin(i), Math.cos(i * 7)], radius: 0.01 + i / 1e4 })) };
  const { problems } = await U.buildQuery({ lesson: 'x', scene: big, params: { obj: { a: 1 } }, steps: 1 });
  assert.match(problems[0], /the scene takes \d+ KB in a link, more than the 6 KB links may hold/);
  assert.match(problems[1], /obj cannot be written in a link/);
});

test('buildQuery names a value too long for a link instead of writing one parseConfig refuses', async () => {
  // Found by tests/fuzz/fuzz_url.mjs: a long string parameter was written without a problem,
  // and the link then lost it ("description: 660 characters is more than a link may carry").
  const snapshot = { lesson: 'notation', scene: null, params: { description: 'joints=' + 'R'.repeat(300), mode: 'build' }, steps: 0 };
  const { query, problems } = await U.buildQuery(snapshot);
  assert.deepEqual(problems, ['the parameter description takes 309 characters in a link, more than the 256 characters a value may']);
  assert.equal(query, 'lesson=notation&mode=build&steps=0');
  const spaces = ' '.repeat(86);  // 86 characters, 258 once percent-encoded
  assert.match((await U.buildQuery({ ...snapshot, params: { description: spaces } })).problems[0], /258 characters in a link/);
  assert.deepEqual((await U.buildQuery({ ...snapshot, params: { description: ' '.repeat(85) } })).problems, []);
});

test('camera: the views\' zoom, pan and turn round-trip through a link exactly', async () => {
  const r = rng(5);
  for (let i = 0; i < 200; ++i) {
    const camera = { workspace: [r() * 4 - 2, r() * 1e-6, 0.5 + r() * 199.5] };
    if (r() < 0.5) camera.cspace = [-r() * 3, r() * 3, 1 + Math.round(r() * 100)];
    if (r() < 0.5) camera.torus = [r() * 6 - 3, r() * 3 - 1.5];
    const { query, problems } = await U.buildQuery({ lesson: 'torus', scene: null, params: { seed: 3 }, steps: 7, camera });
    assert.deepEqual(problems, []);
    const { values, problems: p2 } = U.parseConfig(query);
    assert.deepEqual(p2, []);
    assert.deepEqual(U.parseCamera(values.get('camera')), camera, query);
    assert.match(query, /&steps=7&camera=workspace:[^&]+$/, 'after the step, readable (":" and "," unescaped)');
  }
  // No camera, or an empty one (every view as it starts): no key, the link as before.
  assert.equal((await U.buildQuery({ lesson: 'x', scene: null, params: {}, steps: 0 })).query, 'lesson=x&steps=0');
  assert.equal((await U.buildQuery({ lesson: 'x', scene: null, params: {}, steps: 0, camera: {} })).query, 'lesson=x&steps=0');
  assert.equal(U.formatCamera({ workspace: [0.31, 0.62, 4], torus: [1.2, 0.4] }), 'workspace:0.31,0.62,4~torus:1.2,0.4');
  assert.ok(U.RESERVED.has('camera'), 'no lesson parameter can take the name');
});

test('camera: its syntax is checked strictly, each fault named', () => {
  const fault = (text) => {
    try {
      U.parseCamera(text);
    } catch (e) {
      return e.message;
    }
    return null;
  };
  assert.equal(fault('workspace:0.5,0.5,2'), null);
  assert.equal(fault('workspace'), '"workspace" is not view:numbers');
  assert.equal(fault('Workspace:1,2,3'), '"Workspace" is not a view\'s name');
  assert.equal(fault('work space:1,2,3'), '"work space" is not a view\'s name');
  assert.equal(fault('workspace:1,2,3~workspace:1,2,3'), 'workspace is given twice');
  assert.equal(fault('workspace:1,x,3'), 'workspace: "1,x,3" is not comma-separated numbers');
  assert.equal(fault('workspace:1,Infinity,3'), 'workspace: "1,Infinity,3" is not comma-separated numbers');
  assert.equal(fault('workspace:1e999,1,3'), 'workspace: "1e999,1,3" is not comma-separated numbers');
  assert.equal(fault('workspace:1,2,3,4'), 'workspace: x,y,zoom (a plane) or yaw,pitch[,zoom] (a 3-D view), not 4 numbers');
  assert.equal(fault('workspace:'), 'workspace: "" is not comma-separated numbers');
  assert.equal(fault(Array.from({ length: 9 }, (_, i) => `v${i}:1,2`).join('~')), 'more than 8 views');
  // The app knows which view is a plane: it refuses a plane given two numbers ("is a plane").
  assert.deepEqual(U.parseCamera('torus:0.1,-0.2~workspace:1,2,3'), { torus: [0.1, -0.2], workspace: [1, 2, 3] });
});

test('messages quote untrusted text short and printable', () => {
  assert.equal(U.excerpt('abc'), '"abc"');
  assert.equal(U.excerpt('a\u0000b\nc\u202e'), '"a?b?c\u202e"');
  assert.equal(U.excerpt('x'.repeat(30)), '"' + 'x'.repeat(24) + '…"');
  // FNV-1a, 32 bits: the published test vectors (Fowler, Noll, Vo: "a" and "foobar"), and one
  // of the lab's own keys worked by hand over its bytes; then a character past one byte (the
  // hash reads UTF-16 code units: 'é' is 0xE9, '€' is 0x20AC).
  assert.equal(U.hash(''), '811c9dc5');
  assert.equal(U.hash('a'), 'e40c292c');
  assert.equal(U.hash('foobar'), 'bf9cf968');
  assert.equal(U.hash('lesson=p12'), '747a752f');
  const fnv = (units) => units.reduce((h, u) => Number((BigInt(h ^ u) * 0x01000193n) & 0xffffffffn), 0x811c9dc5);
  assert.equal(U.hash('é€'), fnv([0xe9, 0x20ac]).toString(16).padStart(8, '0'));
  assert.notEqual(U.hash('a'), U.hash('b'));
});

test('task=: its own length limit, and no part of the state', () => {
  // 1000 characters of an emoji (4 UTF-8 bytes, 12 escaped characters each) still fit a link.
  const long = encodeURIComponent('😀'.repeat(1000));
  assert.equal(long.length, 12000);
  const { values, problems } = U.parseConfig('lesson=collision&task=' + long);
  assert.deepEqual(problems, []);
  assert.equal(values.get('task'), '😀'.repeat(1000));
  assert.equal(U.parseConfig('task=' + 'x'.repeat(13000)).problems[0], 'task: 13 KB is more than a link may carry (12 KB)');
  assert.equal(U.parseConfig('lesson=x&note=' + 'x'.repeat(300)).problems.length, 1, 'other keys keep their 256');
  assert.ok(U.RESERVED.has('task'), 'never taken for a lesson parameter');
  // A new task text keeps the same state (and so a student's saved work and autosave slot).
  assert.equal(U.hasState(U.parseConfig('task=Find+a+path&ui=minimal').values), false);
  assert.equal(U.stateKey(U.parseConfig('lesson=collision&task=A').values), U.stateKey(U.parseConfig('lesson=collision&task=B').values));
  assert.notEqual(U.stateKey(U.parseConfig('lesson=collision').values), U.stateKey(U.parseConfig('lesson=step-prm').values));
});

test('buildQuery writes a task that parses back to the same text', async () => {
  const task = 'Find the smallest N.\nThen: explain, with "quotes" & <b>tags</b>, 100 % sure?';
  const { query } = await U.buildQuery({ lesson: 'collision', params: {}, steps: 0 }, {}, { task });
  assert.doesNotMatch(query, /[\n "<>]/, 'escaped');
  assert.equal(U.parseConfig(query).values.get('task'), task);
});

test('lock, hide and reveal: reserved keys, read as words, written again by buildQuery', async () => {
  for (const key of ['lock', 'hide', 'reveal']) assert.ok(U.RESERVED.has(key), key);
  const { values } = U.parseConfig('lesson=collision&lock=scene,params&hide=min_n&reveal=after-answer&grid_n=4');
  assert.deepEqual(U.restrictionsOf(values), {
    restrictions: { lock: 'scene,params', hide: 'min_n', reveal: 'after-answer' }, problems: [] });
  // Not words: named and left out (the app names bad words itself).
  const bad = U.restrictionsOf(U.parseConfig('lock=scene%3Cb%3E&hide=answers').values);
  assert.deepEqual(bad.restrictions, { hide: 'answers' });
  assert.equal(bad.problems.length, 1);
  assert.match(bad.problems[0], /^lock "scene<b>" \(comma-separated words/);
  // Share writes them after the state; a parameter of the same name is never written as one.
  const { query, problems } = await U.buildQuery({ lesson: 'collision', scene: null, params: { grid_n: 4, lock: 'x' }, steps: 2 },
                                                 {}, { lock: 'scene,params', hide: 'min_n' });
  assert.equal(query, 'lesson=collision&grid_n=4&steps=2&lock=scene,params&hide=min_n');
  assert.deepEqual(problems, ['the parameter lock cannot be written in a link']);
});

test('author= is a key of its own, not part of the state', () => {
  // author=1 opens the Author view (lab.js); it must not become a lesson parameter or change the autosave slot.
  assert.ok(U.RESERVED.has('author') && U.PRESENTATION.has('author'));
  assert.equal(U.hasState(U.parseConfig('author=1').values), false);
  const { values, problems } = U.parseConfig('lesson=step-prm&author=1');
  assert.equal(values.get('author'), '1');
  assert.deepEqual(problems, []);
  assert.equal(U.stateKey(values), U.stateKey(U.parseConfig('lesson=step-prm').values));
});

test('assignment= is a key of its own, not part of the state', () => {
  // An assignment lab's autosave slot does not depend on it; the shell does not take it for a parameter.
  assert.ok(U.RESERVED.has('assignment') && U.PRESENTATION.has('assignment'));
  assert.equal(U.hasState(U.parseConfig('assignment=a.json').values), false);
  assert.equal(U.parseConfig('assignment=week3%2Fa.json').values.get('assignment'), 'week3/a.json');
});
