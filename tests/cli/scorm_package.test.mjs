// scripts/scorm-package.mjs: each package's imsmanifest.xml has the structure its version's
// schemas require (parsed here, checked element by element), lists exactly the files in the zip,
// launches a page configured for the assignment, and an invalid assignment is refused with the
// CLI's message naming the item and field. The site is a stand-in made from web/ (no wasm build
// needed: the packager copies files, it does not run them).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { readZip } from '../../scripts/zip.mjs';
import { SOURCE } from './lib/cli.mjs';

const ROOT = SOURCE || path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const PACKAGER = path.join(ROOT, 'scripts/scorm-package.mjs');
const EXAMPLE = path.join(ROOT, 'docs/assignment-example.json');

function tempDir() {
  return fs.mkdtempSync(path.join(os.tmpdir(), 'csl-scorm-'));
}

/** A stand-in for the built site: web/'s files, a fake wasm and the single file that is left out. */
function fakeDist() {
  const dist = tempDir();
  fs.cpSync(path.join(ROOT, 'web'), dist, { recursive: true });
  fs.writeFileSync(path.join(dist, 'cspacelab.wasm'), Buffer.from([0, 0x61, 0x73, 0x6d, 1, 0, 0, 0]));
  fs.writeFileSync(path.join(dist, 'cspacelab.js'), '// the module\n');
  fs.writeFileSync(path.join(dist, 'cspacelab-single.html'), '<!doctype html>');
  return dist;
}

function pack(assignment, dist, out, ...extra) {
  return spawnSync(process.execPath, [PACKAGER, assignment, '--dist', dist, '--out', out, ...extra], { encoding: 'utf8' });
}

/** A small XML parser (elements, attributes, text; what a manifest holds): {name, attrs, children, text}. */
function parseXml(text) {
  const body = text.replace(/^<\?xml[^?]*\?>\s*/, '').replace(/<!--[\s\S]*?-->/g, '');
  const root = { name: '#document', attrs: {}, children: [], text: '' };
  const stack = [root];
  const re = /<(\/?)([A-Za-z_][\w:.-]*)((?:\s+[\w:.-]+\s*=\s*"[^"]*")*)\s*(\/?)>|([^<]+)/g;
  const unescape = (s) => s.replace(/&lt;/g, '<').replace(/&gt;/g, '>').replace(/&quot;/g, '"').replace(/&amp;/g, '&');
  let m;
  let consumed = 0;
  while ((m = re.exec(body))) {
    assert.equal(m.index, consumed, `XML: unexpected text at ${consumed}: ${body.slice(consumed, consumed + 40)}`);
    consumed = re.lastIndex;
    if (m[5] !== undefined) {
      stack.at(-1).text += unescape(m[5]);
      continue;
    }
    if (m[1]) {
      const open = stack.pop();
      assert.equal(open.name, m[2], 'XML: mismatched end tag');
      continue;
    }
    const attrs = {};
    for (const a of m[3].matchAll(/([\w:.-]+)\s*=\s*"([^"]*)"/g)) {
      assert.ok(!(a[1] in attrs), `XML: attribute ${a[1]} twice`);
      attrs[a[1]] = unescape(a[2]);
    }
    const el = { name: m[2], attrs, children: [], text: '' };
    stack.at(-1).children.push(el);
    if (!m[4]) stack.push(el);
  }
  assert.equal(consumed, body.length, 'XML: trailing text');
  assert.equal(stack.length, 1, 'XML: unclosed elements');
  assert.equal(root.children.length, 1, 'XML: one root element');
  return root.children[0];
}

const kids = (el, name) => el.children.filter((c) => c.name === name);
const one = (el, name) => {
  const found = kids(el, name);
  assert.equal(found.length, 1, `exactly one <${name}> in <${el.name}>`);
  return found[0];
};
const all = (el) => [el, ...el.children.flatMap(all)];

const NS = {
  '1.2': { cp: 'http://www.imsproject.org/xsd/imscp_rootv1p1p2', adlcp: 'http://www.adlnet.org/xsd/adlcp_rootv1p2',
           schemaversion: '1.2', scormtype: 'adlcp:scormtype', zip: 'scorm12' },
  2004: { cp: 'http://www.imsglobal.org/xsd/imscp_v1p1', adlcp: 'http://www.adlnet.org/xsd/adlcp_v1p3',
          schemaversion: '2004 4th Edition', scormtype: 'adlcp:scormType', zip: 'scorm2004' },
};
const NCNAME = /^[A-Za-z_][\w.-]*$/;

const dist = fakeDist();
const out = tempDir();
const run = pack(EXAMPLE, dist, out);

test('both packages are written, with the figures printed', () => {
  assert.equal(run.status, 0, run.stderr);
  const printed = JSON.parse(run.stdout).packages;
  assert.deepEqual(printed.map((p) => [p.version, path.basename(p.file)]),
                   [['1.2', 'assignment-example-scorm12.zip'], ['2004', 'assignment-example-scorm2004.zip']]);
  for (const p of printed) assert.equal(fs.statSync(p.file).size, p.bytes);
});

for (const version of ['1.2', '2004']) {
  const ns = NS[version];
  test(`SCORM ${version}: the manifest's required structure, and every file listed and present`, () => {
    const zip = fs.readFileSync(path.join(out, `assignment-example-${ns.zip}.zip`));
    const entries = readZip(zip);  // checks each entry's CRC-32
    const names = entries.map((e) => e.name);
    const m = parseXml(entries.find((e) => e.name === 'imsmanifest.xml').data.toString('utf8'));

    assert.equal(m.name, 'manifest');
    assert.equal(m.attrs.xmlns, ns.cp);
    assert.equal(m.attrs['xmlns:adlcp'], ns.adlcp);
    assert.equal(m.attrs['xmlns:xsi'], 'http://www.w3.org/2001/XMLSchema-instance');
    if (version === '2004') {
      assert.equal(m.attrs['xmlns:imsss'], 'http://www.imsglobal.org/xsd/imsss');
      assert.equal(m.attrs['xmlns:adlseq'], 'http://www.adlnet.org/xsd/adlseq_v1p3');
      assert.equal(m.attrs['xmlns:adlnav'], 'http://www.adlnet.org/xsd/adlnav_v1p3');
    }
    // schemaLocation: namespace/location pairs, one for each namespace the manifest uses.
    const loc = m.attrs['xsi:schemaLocation'].trim().split(/\s+/);
    assert.equal(loc.length % 2, 0);
    const located = new Map();
    for (let i = 0; i < loc.length; i += 2) located.set(loc[i], loc[i + 1]);
    for (const [k, v] of Object.entries(m.attrs))
      if (k === 'xmlns' || (k.startsWith('xmlns:') && k !== 'xmlns:xsi')) assert.ok(located.has(v), `schemaLocation names ${v}`);
    for (const file of located.values()) assert.match(file, /\.xsd$/);

    const meta = one(m, 'metadata');
    assert.equal(one(meta, 'schema').text, 'ADL SCORM');
    assert.equal(one(meta, 'schemaversion').text, ns.schemaversion);
    assert.deepEqual(m.children.map((c) => c.name), ['metadata', 'organizations', 'resources'], 'the order the schema requires');

    const ids = all(m).filter((e) => e.attrs.identifier).map((e) => e.attrs.identifier);
    assert.equal(new Set(ids).size, ids.length, 'identifiers are unique');
    for (const id of ids) assert.match(id, NCNAME, 'an identifier is an xs:ID');

    const orgs = one(m, 'organizations');
    const org = kids(orgs, 'organization').find((o) => o.attrs.identifier === orgs.attrs.default);
    assert.ok(org, 'organizations/@default names an organization');
    assert.equal(one(org, 'title').text, 'Week 3: configuration spaces and sampling');
    const item = one(org, 'item');
    assert.equal(item.children[0].name, 'title', 'an item starts with its title');
    const resource = kids(one(m, 'resources'), 'resource').find((r) => r.attrs.identifier === item.attrs.identifierref);
    assert.ok(resource, 'the item\'s identifierref names a resource');
    assert.equal(resource.attrs.href, 'launch.html');
    assert.equal(resource.attrs.type, 'webcontent');
    assert.equal(resource.attrs[ns.scormtype], 'sco');
    if (version === '1.2') {
      assert.equal(one(item, 'adlcp:masteryscore').text, '60', 'pass 0.6 as 1.2\'s 0-100 mastery score');
    } else {
      const primary = one(one(one(item, 'imsss:sequencing'), 'imsss:objectives'), 'imsss:primaryObjective');
      assert.equal(primary.attrs.satisfiedByMeasure, 'true');
      assert.equal(one(primary, 'imsss:minNormalizedMeasure').text, '0.6');
    }

    const listed = kids(resource, 'file').map((f) => f.attrs.href);
    assert.deepEqual([...listed].sort(), names.filter((n) => n !== 'imsmanifest.xml').sort(), 'every file listed, every listed file present');
    assert.ok(listed.includes('launch.html') && listed.includes('assignment.json') && listed.includes('lab-assignment.js'));
    assert.ok(!names.includes('cspacelab-single.html'), 'the single-file page (the wasm again) is left out');
    assert.deepEqual(entries.find((e) => e.name === 'assignment.json').data, fs.readFileSync(EXAMPLE));

    // The launch page: the site's page, its lab in assignment mode for this version, same CSP.
    const launch = entries.find((e) => e.name === 'launch.html').data.toString('utf8');
    const index = fs.readFileSync(path.join(dist, 'index.html'), 'utf8');
    const csp = (html) => /http-equiv="Content-Security-Policy" content="([^"]*)"/.exec(html)[1];
    assert.equal(csp(launch), csp(index));
    assert.match(csp(launch), /connect-src 'self'/, 'it may fetch assignment.json');
    assert.match(launch, new RegExp(`<main class="lab" id="assignment" data-lab="assignment=assignment.json" data-lab-scorm="${version}">`));
    assert.match(launch, /<title>Week 3: configuration spaces and sampling - C-Space Lab<\/title>/);

    // Another zip reader agrees (Info-ZIP's, where the machine has it).
    if (fs.existsSync('/usr/bin/unzip')) {
      const t = spawnSync('/usr/bin/unzip', ['-t', path.join(out, `assignment-example-${ns.zip}.zip`)], { encoding: 'utf8' });
      assert.equal(t.status, 0, t.stdout + t.stderr);
      assert.match(t.stdout, /No errors detected/);
    }
  });
}

test('a title with $\' $& $1 (replacement patterns) is written as it is, in the page and the manifest', () => {
  const file = JSON.parse(fs.readFileSync(EXAMPLE, 'utf8'));
  file.title = "Costs in $'s & $& of $1 <ok>";
  const dir = tempDir();
  const assignment = path.join(dir, 'dollars.json');
  fs.writeFileSync(assignment, JSON.stringify(file));
  const r = pack(assignment, dist, dir, '--version', '2004');
  assert.equal(r.status, 0, r.stderr);
  const entries = readZip(fs.readFileSync(path.join(dir, 'dollars-scorm2004.zip')));
  const launch = entries.find((e) => e.name === 'launch.html').data.toString('utf8');
  const titles = launch.match(/<title>[\s\S]*?<\/title>/g);
  assert.deepEqual(titles, ["<title>Costs in $'s &amp; $&amp; of $1 &lt;ok&gt; - C-Space Lab</title>"]);
  assert.equal(launch.split('<main class="lab"').length, 2, 'one lab element');
  const manifest = parseXml(entries.find((e) => e.name === 'imsmanifest.xml').data.toString('utf8'));
  assert.ok(all(manifest).some((el) => el.name === 'title' && el.text === file.title), 'the manifest\'s title');
});

test('control characters in a title are left out of the manifest, which XML 1.0 would refuse', () => {
  const file = JSON.parse(fs.readFileSync(EXAMPLE, 'utf8'));
  file.title = 'Week\u0001 3\u001f: spaces';
  const dir = tempDir();
  const assignment = path.join(dir, 'controls.json');
  fs.writeFileSync(assignment, JSON.stringify(file));
  const r = pack(assignment, dist, dir, '--version', '1.2');
  assert.equal(r.status, 0, r.stderr);
  const text = readZip(fs.readFileSync(path.join(dir, 'controls-scorm12.zip')))
    .find((e) => e.name === 'imsmanifest.xml').data.toString('utf8');
  assert.doesNotMatch(text, /[\u0000-\u0008\u000B\u000C\u000E-\u001F]/);
  assert.ok(all(parseXml(text)).some((el) => el.name === 'title' && el.text === 'Week 3: spaces'), 'the title, without them');
});

test('an invalid assignment is refused with each item and field named, and nothing written', () => {
  const bad = JSON.parse(fs.readFileSync(EXAMPLE, 'utf8'));
  bad.items[1].points = -1;
  bad.items[4].check.all[1].pointer = 'params/samples';
  const dir = tempDir();
  const file = path.join(dir, 'broken.json');
  fs.writeFileSync(file, JSON.stringify(bad));
  const where = path.join(dir, 'out');
  const r = pack(file, dist, where);
  assert.equal(r.status, 2);
  assert.equal(r.stdout, '');
  assert.match(r.stderr, /^scorm-package: the assignment is not valid: .*broken\.json: 2 problems: items\[1\] \(P10\): points: a number in \[0, 1000\], got -1; items\[4\] \("Find a path with at most 50 samples"\): check\.all\[1\]: pointer: /);
  assert.equal(r.stderr.trimEnd().split('\n').length, 1, 'one line');
  assert.ok(!fs.existsSync(where), 'no package of an invalid assignment');
});

test('bad options and a missing site are one-line errors', () => {
  const r = pack(EXAMPLE, dist, tempDir(), '--version', '3');
  assert.equal(r.status, 2);
  assert.equal(r.stderr, "scorm-package: --version: 1.2, 2004 or both, not '3'\n");
  const empty = tempDir();
  const r2 = pack(EXAMPLE, empty, tempDir());
  assert.equal(r2.status, 2);
  assert.match(r2.stderr, /is not the built site \(no cspacelab\.wasm or index\.html\)/);
  const only = pack(EXAMPLE, dist, tempDir(), '--version', '2004');
  assert.equal(JSON.parse(only.stdout).packages.length, 1);
});

test('--help states the contract', () => {
  const r = spawnSync(process.execPath, [PACKAGER, '--help'], { encoding: 'utf8' });
  assert.equal(r.status, 0);
  for (const word of ['--dist', '--out', '--version', 'NAME-scorm12.zip', 'NAME-scorm2004.zip', 'CSPACELAB_CLI', '"packages"'])
    assert.ok(r.stdout.includes(word), word);
});
