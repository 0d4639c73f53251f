// cspacelab link: the link and the iframe for a lesson with a scene file, locked and hidden as
// asked. The scene in the link is decoded here as web/lab-url.js decodes it (base64url, then
// deflate-raw through node's zlib) and compared with the file's normalised scene; the errors
// are one line naming what is wrong. tests/e2e/lock-hide.test.mjs opens such a link in Chromium.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import zlib from 'node:zlib';
import { json, fails, run, scene, tempScene } from './lib/cli.mjs';

// The scene of a link's query, decoded as the page does (z. deflate-raw, j. plain JSON); its
// JSON text too.
function decodeText(text) {
  const m = /^([zj])\.([A-Za-z0-9_-]+)$/.exec(text);
  assert.ok(m, `an encoded scene: ${text.slice(0, 40)}`);
  const bytes = Buffer.from(m[2], 'base64url');
  return (m[1] === 'z' ? zlib.inflateRawSync(bytes) : bytes).toString('utf8');
}
const decodeScene = (text) => JSON.parse(decodeText(text));

function query(url) {
  return new URLSearchParams(url.slice(url.indexOf('?') + 1));
}

test('a scene file becomes a link whose scene decodes to the file\'s, bit for bit', () => {
  // Numbers that only survive a round trip written in full (no decimal shortening by hand).
  const file = tempScene({
    version: 1, name: 'Week 6: a gap',
    workspace: { min: [0, 0], max: [1, 1] },
    robot: { type: 'point' },
    obstacles: [{ type: 'disk', center: [0.1 + 0.2, 1 / 3], radius: Math.PI / 30 },
                { type: 'disk', center: [0.000001, 1e-7], radius: 0.5 },
                { type: 'polygon', vertices: [[0.6, 0.1], [0.9, 0.15000000000000002], [0.75, 0.4]] },
                { type: 'segment', a: [0.5, 0.5], b: [0.5, 0.95] }],
    start: [0.05, 0.05], goal: [0.95, 0.95],
  });
  const out = json('link', file, '--lesson', 'collision', '--params', '{"grid_n": 9, "p": [0.05, 0.05]}',
                   '--lock', 'scene,params', '--hide', 'min_n', '--reveal', 'after-answer', '--base', 'https://example.org/lab/');
  assert.deepEqual(Object.keys(out).sort(), ['iframe', 'url']);
  assert.match(out.url, /^https:\/\/example\.org\/lab\/index\.html\?lesson=collision&scene=z\./);
  const q = query(out.url);
  assert.equal(q.get('lesson'), 'collision');
  assert.equal(q.get('grid_n'), '9');
  assert.equal(q.get('p'), '0.05,0.05');
  assert.equal(q.get('lock'), 'scene,params');
  assert.equal(q.get('hide'), 'min_n');
  assert.equal(q.get('reveal'), 'after-answer');
  const normal = json('validate', file).scene;
  const decoded = decodeScene(q.get('scene'));
  assert.deepEqual(decoded, normal);
  // Bit for bit: every number's shortest text (JSON.stringify) is the same. And the text deflated
  // is JSON.stringify's own ("1" not "1.0", "1e-7" not "1e-07"), as the page's Share deflates it.
  assert.equal(JSON.stringify(decoded), JSON.stringify(normal));
  assert.equal(decodeText(q.get('scene')), JSON.stringify(normal));
  assert.equal(decoded.obstacles[0].center[0], 0.1 + 0.2);
  assert.equal(decoded.obstacles[0].radius, Math.PI / 30);
  // The iframe the Embed dialog writes: embed.html with the same query and an id, escaped.
  const m = /^<iframe src="([^"]*)" width="100%" height="600" style="border:0" title="C-Space Lab: Collision checking" allow="clipboard-write"><\/iframe>$/.exec(out.iframe);
  assert.ok(m, out.iframe);
  const src = m[1].replace(/&amp;/g, '&');
  assert.equal(src, out.url.replace('index.html', 'embed.html') + src.slice(src.lastIndexOf('&id=')));
  assert.match(src, /&id=lab-[0-9a-f]{6}$/);
});

test('the same file gives the same link; the bundled scenes deflate to well under their JSON', () => {
  for (const name of ['p12.json', 'wall-gap.json', 'narrow-passage.json', 'prm-demo.json']) {
    const a = json('link', scene(name), '--lesson', 'step-prm');
    assert.deepEqual(json('link', scene(name), '--lesson', 'step-prm'), a, 'deterministic');
    const text = query(a.url).get('scene');
    assert.deepEqual(decodeScene(text), json('validate', scene(name)).scene, name);
    const plain = Buffer.from(JSON.stringify(json('validate', scene(name)).scene)).toString('base64url').length + 2;
    assert.ok(text.length < plain, `${name}: ${text.length} characters deflated, ${plain} as plain JSON`);
  }
  // Relative by default: the course page sits next to index.html and embed.html.
  const rel = json('link', scene('p12.json'), '--lesson', 'collision');
  assert.match(rel.url, /^index\.html\?lesson=collision&scene=z\./);
  assert.match(rel.iframe, /^<iframe src="embed\.html\?lesson=collision&amp;scene=z\./);
});

test('lessons without a scene, parameters and a task as the page writes them', () => {
  const out = json('link', '--lesson', 'distances', '--params', '{"tool": "segment", "r": 0.25, "q": [1e-7, -2]}',
                   '--hide', 'answers', '--task', 'How far is the disk? (P11, 2 marks)');
  const q = query(out.url);
  assert.equal(q.get('scene'), null);
  assert.equal(q.get('tool'), 'segment');
  assert.equal(Number(q.get('r')), 0.25);
  assert.deepEqual(q.get('q').split(',').map(Number), [1e-7, -2]);
  assert.equal(q.get('hide'), 'answers');
  assert.equal(q.get('task'), 'How far is the disk? (P11, 2 marks)');
  assert.match(out.url, /&task=How%20far%20is%20the%20disk%3F%20\(P11,%202%20marks\)$/, 'encoded as encodeURIComponent, : and , left');
  assert.match(out.iframe, /title="C-Space Lab: Distances"/);
  // The Embed dialog's iframe: the task after the state, and taller by the task's height over the
  // canvas (web/lab-task.js: one line of 35 + 6 characters is one row, 14 + 20 px).
  assert.match(out.iframe, /embed\.html\?lesson=distances&amp;q=1e-7,-2&amp;r=0\.25&amp;tool=segment&amp;hide=answers&amp;task=How%20far[^"]*&amp;id=lab-[0-9a-f]{6}" width="100%" height="634"/);
  // Normalised as the page shows it: lines trimmed, spaces squeezed, controls gone, empty lines dropped.
  const messy = json('link', '--lesson', 'notation', '--task', '  Write   Q\t for\r\n\n\u0007 P1.  ');
  assert.equal(query(messy.url).get('task'), 'Write Q for\nP1.');
  fails(/unexpected argument 'x\.json'/, 'link', 'x.json', '--lesson', 'notation');
});

test('--list: the lessons and what a link may lock and hide in each', () => {
  const list = json('link', '--list');
  assert.deepEqual(list.lessons.map((l) => l.id), ['torus', 'notation', 'cspace-3d', 'collision', 'compare', 'distances', 'analysis', 'potential', 'step-prm']);
  const collision = list.lessons.find((l) => l.id === 'collision');
  assert.deepEqual(collision, { id: 'collision', name: 'Collision checking', params: ['grid_n', 'p', 'q'], robots: ['point', 'arm2'] });
  assert.deepEqual(list.lessons.find((l) => l.id === 'step-prm').params, ['samples', 'neighbors', 'checker', 'seed', 'sampler']);
  for (const k of ['sampler_a', 'sampler_b']) assert.ok(list.lessons.find((l) => l.id === 'compare').params.includes(k), k);
  const minN = list.answers.find((a) => a.name === 'min_n');
  assert.deepEqual([minN.lesson, minN.problems, minN.fields], ['collision', ['P12'], ['/min_grid', '/min_grid_interior', '/min_grid_one_end']]);
  assert.match(minN.what, /the smallest N/);
  // Every problem of the homework is some answer's.
  const problems = new Set(list.answers.flatMap((a) => a.problems));
  for (const p of json('homework')) assert.ok(problems.has(p.id), p.id);
  fails(/unexpected argument/, 'link', '--list', 'x.json');
});

test('bad input: one line naming what is wrong, exit 2', () => {
  const p12 = scene('p12.json');
  fails(/--lesson is missing \(torus, notation, cspace-3d, collision, compare, distances, analysis, potential, step-prm\)/, 'link', p12);
  fails(/--lesson: 'collisions' is not a lesson \(torus, notation, cspace-3d, collision/, 'link', p12, '--lesson', 'collisions');
  fails(/--lock: "sceen" is not scene, params, lesson or a parameter of collision \(grid_n, p, q\)/,
        'link', p12, '--lesson', 'collision', '--lock', 'sceen,params');
  fails(/--hide: "min_n" is not answers, none or an answer of step-prm \(path_length\)/, 'link', p12, '--lesson', 'step-prm', '--hide', 'min_n');
  fails(/--reveal: "later" is not never or after-answer/, 'link', p12, '--lesson', 'collision', '--reveal', 'later');
  fails(/--params: "seed" is not a parameter of collision \(grid_n, p, q\)/, 'link', p12, '--lesson', 'collision', '--params', '{"seed": 3}');
  fails(/--params: grid_n: an integer in \[2, 100000\]/, 'link', p12, '--lesson', 'collision', '--params', '{"grid_n": 1}');
  fails(/--params: not JSON/, 'link', p12, '--lesson', 'collision', '--params', '{grid_n: 4}');
  // A configuration of the 3-D lesson has three coordinates (its robots' ranges are the lab's to check).
  fails(/--params: q: 3 numbers \[a, b, \.\.\.\]/, 'link', scene('polygon-robot.json'), '--lesson', 'cspace-3d', '--params', '{"q": [1, 2]}');
  fails(/--params: q: 3 numbers/, 'link', scene('polygon-robot.json'), '--lesson', 'cspace-3d', '--params', '{"q": [1, 2, 3, 4]}');
  assert.deepEqual(query(json('link', scene('polygon-robot.json'), '--lesson', 'cspace-3d', '--params', '{"q": [0.5, 0.5, 1]}').url)
    .get('q').split(',').map(Number), [0.5, 0.5, 1]);
  // The samplers as the lab takes them: the CLI's syntax, sigma within the lab's range.
  fails(/--params: sampler: sigma: a number in \[0\.001, 1\] in the lab/, 'link', p12, '--lesson', 'step-prm',
        '--params', '{"sampler": "bridge:5"}');
  fails(/--params: sampler_b: unknown sampler 'sobol'/, 'link', p12, '--lesson', 'compare', '--params', '{"sampler_b": "sobol"}');
  // A hybrid's uniform share within the lab's 0 to 0.9, and the link spells it so that the page
  // reads it back (a ',' survives a query; a '+' would become a space).
  fails(/--params: sampler: uniform share: a number in \[0, 0\.9\]/, 'link', p12, '--lesson', 'step-prm',
        '--params', '{"sampler": "bridge:0.05,uniform:0.95"}');
  assert.equal(query(json('link', p12, '--lesson', 'step-prm', '--params', '{"sampler": "bridge:0.05,uniform:0.3"}').url)
    .get('sampler'), 'bridge:0.05,uniform:0.3');
  fails(/--params: the parameters must be a JSON object/, 'link', p12, '--lesson', 'collision', '--params', '[4]');
  fails(/SCENE\.json: the step-prm lesson takes scenes with robot point; this one has 'arm2'/, 'link', scene('arm-2link.json'), '--lesson', 'step-prm');
  fails(/missing SCENE\.json/, 'link', '--lesson', 'collision');
  fails(/scene\.json: .*radius/, 'link', tempScene({ version: 1, obstacles: [{ type: 'disk', center: [0.5, 0.5], radius: -1 }] }), '--lesson', 'collision');
  fails(/scene\.json: /, 'link', tempScene('{"version": 1,'), '--lesson', 'collision');
  fails(/cannot read file/, 'link', '/no/such/scene.json', '--lesson', 'collision');
  fails(/--base: 'https:\/\/x\.org\/lab' is not the lab's folder/, 'link', p12, '--lesson', 'collision', '--base', 'https://x.org/lab');
  fails(/--base: 'javascript:alert\(1\)\/' is not the lab's folder/, 'link', p12, '--lesson', 'collision', '--base', 'javascript:alert(1)/');
  fails(/--task: 1001 characters; a task holds at most 1000/, 'link', p12, '--lesson', 'collision', '--task', 'é'.repeat(1001));
  fails(/--task: an empty text/, 'link', p12, '--lesson', 'collision', '--task', '');
  // Nothing on stdout for any of them (fails() checks), and help on --help.
  const help = run('link', '--help');
  assert.equal(help.status, 0);
  assert.match(help.stdout, /--hide WORDS/);
});
