// A small static file server for the built site, used by scripts/serve.sh and the browser tests.
//   node scripts/static-server.mjs DIR [PORT] [HOST]     (defaults: 8000, 127.0.0.1)
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

/** Starts serving `root`; resolves to {server, url} once listening (port 0 = any free port). */
export function serve(root, port = 8000, host = '127.0.0.1') {
  const base = path.resolve(root);
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
  const [dir, port = '8000', host = '127.0.0.1'] = process.argv.slice(2);
  if (!dir || !fs.existsSync(path.join(dir, 'index.html'))) {
    console.error(`static-server: no index.html in '${dir}' (build the wasm app first)`);
    process.exit(2);
  }
  serve(dir, Number(port), host).then(({ url }) => {
    console.log(`C-Space Lab is served at ${url}  (Ctrl+C stops)`);
  }, (err) => {
    console.error(`static-server: cannot listen on ${host}:${port}: ${err.message}`);
    process.exit(1);
  });
}
