// Builds the single-file lab: one self-contained HTML page (for an LMS that takes one file, or
// to open from disk) from the built site.
//   node scripts/single-file.mjs DIST OUT.html
// Takes DIST/index.html and inlines its stylesheet and scripts (and LATE below, which lab.js
// would fetch); the wasm goes in as a gzip'd,
// base64'd data block (<script type="application/octet-stream" id="cspacelab-wasm">) that
// lab.js unpacks with DecompressionStream and hands to the module as wasmBinary: nothing is
// fetched, so the page works from file:// too. The page keeps a Content-Security-Policy with
// no 'unsafe-inline': each inline script and the style are allowed by their SHA-256 only.
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import crypto from 'node:crypto';

const [dist, out] = process.argv.slice(2);
if (!dist || !out) {
  console.error('usage: node scripts/single-file.mjs DIST OUT.html');
  process.exit(2);
}
const read = (f) => fs.readFileSync(path.join(dist, f), 'utf8');
const sha256 = (text) => `'sha256-${crypto.createHash('sha256').update(text, 'utf8').digest('base64')}'`;
// Inside <script>/<style>, "</script" or "</style" would end the element early.
const guard = (text, tag) => text.replace(new RegExp(`</(${tag})`, 'gi'), '<\\/$1');

let html = read('index.html');
html = html.replace(/\n\s*<link rel="preload"[^>]*>/g, '');  // nothing is fetched: the wasm is inline
const scriptHashes = [];
let styleHash = null;

html = html.replace(/<link rel="stylesheet" href="([^"]+)">/g, (_, href) => {
  const css = '\n' + guard(read(href), 'style') + '\n';
  styleHash = sha256(css);
  return `<style data-lab-css>${css}</style>`;
});
// lab.js loads the homework's, the top bar's, the tables' and the scene's accessible copies and
// the print worksheet once a lab has started; here they come inline first.
const LATE = ['lab-homework-access.js', 'lab-actions-access.js', 'lab-tables-access.js', 'lab-scene-access.js',
              'lab-print.js'];
const inline = (src) => {
  const js = '\n' + guard(read(src), 'script') + '\n';
  scriptHashes.push(sha256(js));
  return `<script>${js}</script>`;
};
html = html.replace(/<script src="([^"]+)"><\/script>/g, (_, src) =>
  (src === 'lab.js' ? LATE.map(inline).join('\n  ') + '\n  ' : '') +
  inline(src));
if (scriptHashes.length === 0 || styleHash === null) throw new Error('index.html has no scripts or stylesheet to inline');

const wasm = fs.readFileSync(path.join(dist, 'cspacelab.wasm'));
const packed = zlib.gzipSync(wasm, { level: 9 }).toString('base64');
const block = `<script type="application/octet-stream" id="cspacelab-wasm" data-encoding="gzip-base64">\n${packed}\n</script>\n  `;
// Before the first script: lab.js looks for it when it runs.
const first = html.indexOf('<script>');
html = html.slice(0, first) + block + html.slice(first);

const csp = [
  "default-src 'none'",
  `script-src ${scriptHashes.join(' ')} 'wasm-unsafe-eval'`,
  `style-src ${styleHash}`,
  'img-src data:',
  "object-src 'none'",
  "base-uri 'none'",
  "form-action 'none'",
].join('; ');
const before = html;
html = html.replace(/<meta http-equiv="Content-Security-Policy" content="[^"]*">/, `<meta http-equiv="Content-Security-Policy" content="${csp}">`);
if (html === before) throw new Error('index.html has no Content-Security-Policy meta tag to replace');
html = html.replace('<title>C-Space Lab</title>', '<title>C-Space Lab (single file)</title>');
html = html.replace(/<!-- No inline script[^>]*-->/, '<!-- The single-file build: inline scripts are allowed by their hashes only. -->');

fs.writeFileSync(out, html);
console.log(`${path.basename(out)}: ${(html.length / 1024).toFixed(0)} KB (wasm ${(wasm.length / 1024).toFixed(0)} KB, ` +
            `gzip+base64 ${(packed.length / 1024).toFixed(0)} KB)`);
