// Every file under a folder, as paths relative to it with '/', sorted: what the SCORM packages
// hold (scripts/scorm-package.mjs) and what the page's Author view is told the site has
// (scripts/site-files.mjs), listed by one function so that the two cannot differ.
import fs from 'node:fs';
import path from 'node:path';

export function listFiles(dir, prefix = '') {
  const out = [];
  for (const e of fs.readdirSync(path.join(dir, prefix), { withFileTypes: true })) {
    const rel = prefix ? prefix + '/' + e.name : e.name;
    if (e.isDirectory()) out.push(...listFiles(dir, rel));
    else if (e.isFile()) out.push(rel);
  }
  return out.sort();
}
