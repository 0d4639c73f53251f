// A small static file server for the built site, used by scripts/serve.sh and the browser tests.
//   node scripts/static-server.mjs DIR [PORT] [HOST] [--cors ORIGIN|*]    (defaults: 8000, 127.0.0.1)
//
// --cors lets course pages of other origins embed the lab with the script tag (<div data-lab>
// + lab.js): lab.js then fetches cspacelab.wasm from this server with fetch(), which the browser
// lets a page of another origin read only when the answer carries Access-Control-Allow-Origin.
// `--cors '*'` sends `Access-Control-Allow-Origin: *` (what GitHub Pages sends); `--cors
// https://lms.example.edu` (or several, comma-separated) answers a request from one of those
// origins with its own origin and `Vary: Origin`, and others without the header. Scripts and
// the stylesheet load across origins without it; an iframe of embed.html needs none of this.
// Serves .wasm as application/wasm (needed for streaming compilation) and never caches, so a
// rebuilt app is what the next reload shows. Refuses paths that leave DIR. Takes request heads
// of up to MAX_HEADER_BYTES: a link may carry a 64 KB scene, and node's default (16 KB) answered
// such links with 431.
import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8', '.css': 'text/css; charset=utf-8',
  '.wasm': 'application/wasm', '.json': 'application/json', '.png': 'image/png',
  '.svg': 'image/svg+xml', '.ico': 'image/x-icon', '.txt': 'text/plain; charset=utf-8',
};

// The documented limits of a link (web/lab-url.js): a 64 KB encoded scene plus 63 other values
// of at most 256 characters, with room for the request's other headers.
export const MAX_HEADER_BYTES = 256 * 1024;

/**
 * The CORS header for --cors TEXT: a function from a request's Origin header to the headers to
 * add. Throws on text that is neither '*' nor a comma-separated list of origins (https://host[:port]).
 */
export function corsHeaders(text) {
  if (text === '*') return () => ({ 'Access-Control-Allow-Origin': '*' });
  const allowed = String(text).split(',').map((s) => s.trim()).filter(Boolean);
  if (!allowed.length) throw new Error('--cors needs * or an origin such as https://lms.example.edu');
  for (const o of allowed) {
    let origin = null;
    try {
      origin = new URL(o).origin;
    } catch {
      // below
    }
    if (origin !== o || !/^https?:/.test(o))
      throw new Error(`--cors: '${o}' is not an origin (scheme://host[:port], no path or trailing slash)`);
  }
  return (origin) => (allowed.includes(origin) ? { 'Access-Control-Allow-Origin': origin, Vary: 'Origin' } : { Vary: 'Origin' });
}

/**
 * Starts serving `root`; resolves to {server, url} once listening (port 0 = any free port).
 * options.cors: '*' or origins, as --cors.
 */
export function serve(root, port = 8000, host = '127.0.0.1', { cors = null } = {}) {
  const base = path.resolve(root);
  const corsFor = cors ? corsHeaders(cors) : () => ({});
  const server = http.createServer({ maxHeaderSize: MAX_HEADER_BYTES }, (req, res) => {
    let rel;
    try {
      rel = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    } catch {
      res.writeHead(400).end('bad request');
      return;
    }
    let file = path.join(base, rel);
    if (file !== base && !file.startsWith(base + path.sep)) {
      res.writeHead(403).end('forbidden');
      return;
    }
    if (fs.existsSync(file) && fs.statSync(file).isDirectory()) file = path.join(file, 'index.html');
    fs.readFile(file, (err, data) => {
      if (err) {
        res.writeHead(404, { 'Content-Type': 'text/plain' }).end('not found');
        return;
      }
      res.writeHead(200, {
        'Content-Type': TYPES[path.extname(file).toLowerCase()] || 'application/octet-stream',
        'Cache-Control': 'no-store',
        ...corsFor(req.headers.origin),
      });
      res.end(req.method === 'HEAD' ? undefined : data);
    });
  });
  return new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, host, () => {
      const addr = server.address();
      resolve({ server, url: `http://${host}:${addr.port}/` });
    });
  });
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const args = process.argv.slice(2);
  let cors = null;
  const at = args.indexOf('--cors');
  if (at >= 0) {
    cors = args[at + 1];
    args.splice(at, 2);
    try {
      corsHeaders(cors === undefined ? '' : cors);
    } catch (err) {
      console.error(`static-server: ${err.message}`);
      process.exit(2);
    }
  }
  const [dir, port = '8000', host = '127.0.0.1'] = args;
  if (!dir || !fs.existsSync(path.join(dir, 'index.html'))) {
    console.error(`static-server: no index.html in '${dir}' (build the wasm app first)`);
    process.exit(2);
  }
  serve(dir, Number(port), host, { cors }).then(({ url }) => {
    console.log(`C-Space Lab is served at ${url}${cors ? `, Access-Control-Allow-Origin for ${cors}` : ''}  (Ctrl+C stops)`);
  }, (err) => {
    console.error(`static-server: cannot listen on ${host}:${port}: ${err.message}`);
    process.exit(1);
  });
}
