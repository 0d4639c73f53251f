// axe-core (Deque's accessibility checker) in a page of the lab. The page's CSP refuses an
// injected inline script, so pages checked with it are opened in a context made with
// newAxeContext() (bypassCSP); the lab's own scripts still load as they do for a student.
import fs from 'node:fs';
import { createRequire } from 'node:module';

const require = createRequire(import.meta.url);
const AXE_SOURCE = fs.readFileSync(require.resolve('axe-core/axe.min.js'), 'utf8');

/** What must not be found: WCAG 2.0 and 2.1, levels A and AA, and axe's best practices. */
const TAGS = ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'best-practice'];
const BLOCKING = new Set(['serious', 'critical']);

/** A browser context in which axe can be injected (the lab's options otherwise as given). */
export function newAxeContext(browser, options = {}) {
  return browser.newContext({ viewport: { width: 1280, height: 800 }, ...options, bypassCSP: true });
}

/**
 * Runs axe over the whole document of `target` (a page or a frame). Returns {blocking, other}:
 * the serious and critical violations, and the rest, each as one line "id (impact): help: targets".
 */
export async function runAxe(target) {
  if (!(await target.evaluate(() => typeof window.axe === 'object'))) await target.addScriptTag({ content: AXE_SOURCE });
  const violations = await target.evaluate(async (tags) => {
    const r = await window.axe.run(document, { runOnly: { type: 'tag', values: tags }, resultTypes: ['violations'] });
    return r.violations.map((v) => ({ id: v.id, impact: v.impact, help: v.help,
                                      targets: v.nodes.map((n) => n.target.join(' ')) }));
  }, TAGS);
  const line = (v) => `${v.id} (${v.impact}): ${v.help}: ${v.targets.join(', ')}`;
  return {
    blocking: violations.filter((v) => BLOCKING.has(v.impact)).map(line),
    other: violations.filter((v) => !BLOCKING.has(v.impact)).map(line),
  };
}
