// Writes DIST/site-files.json: the built site's files that go into a SCORM package, sorted,
// for the page's Author view (web/lab-author.js), which packages the site it was served from
// and cannot list its folder. Run by the build after the app and the page's files are in DIST
// (src/app/CMakeLists.txt); the list names itself, since scripts/scorm-package.mjs, listing
// DIST on disk, finds it there too.
//   node scripts/site-files.mjs DIST
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { listFiles } from './list-files.mjs';

const P = createRequire(import.meta.url)('../web/lab-scorm-package.js');

const dist = process.argv[2];
if (!dist || !fs.existsSync(path.join(dist, 'index.html'))) {
  process.stderr.write('usage: node scripts/site-files.mjs DIST (the built site, with its index.html)\n');
  process.exit(2);
}
const files = [...new Set([...listFiles(dist), P.SITE_LIST])].filter(P.packaged).sort();
fs.writeFileSync(path.join(dist, P.SITE_LIST), JSON.stringify({ format: 'cspacelab-site-files', version: 1, files }, null, 1) + '\n');
