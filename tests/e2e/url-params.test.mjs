// Links are parsed strictly: garbage values, a 10 MB scene, a zip bomb and script tags inside
// strings each give the in-app notice, fall back to the lesson's defaults, and leave no console
// error, no CSP violation, no new DOM and nothing executed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import zlib from 'node:zlib';
import { withBrowser, collectErrors, openLab, api, screenshot } from './lib/harness.mjs';

const b64url = (buf) => Buffer.from(buf).toString('base64').replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');

async function fresh(browser, { init } = {}) {
  const page = await browser.newPage({ viewport: { width: 1200, height: 760 } });
  const errors = collectErrors(page);
  const dialogs = [];
  page.on('dialog', (d) => { dialogs.push(d.message()); d.dismiss(); });
  await page.addInitScript(() => {
    window.__cspViolations = [];
    document.addEventListener('securitypolicyviolation', (e) => window.__cspViolations.push(e.violatedDirective));
  });
  if (init) await page.addInitScript(init);
  return { page, errors, dialogs };
}

// Every element of the page, as tag names: what the lab and its scripts put there.
// The page's elements by tag, once the parts loaded after the first frame are in and the scene's
// copy shows a box for start, goal and each obstacle (its shape follows the scene).
async function dom(page) {
  await page.waitForFunction(() => document.querySelector('.lab').cspacelabPrint &&
    document.querySelectorAll('.lab-access-scene fieldset').length === window.cspacelab.call('get_scene').obstacles.length + 2);
  return page.evaluate(() => Array.from(document.querySelectorAll('*'), (e) => e.tagName.toLowerCase()).join(' '));
}

test('garbage values: an in-app notice, the defaults, nothing else', () => withBrowser(async ({ browser, url }) => {
  const { page: clean } = await fresh(browser);
  await openLab(clean, url);
  const cleanDom = await dom(clean);
  const defaults = await api(clean, 'snapshot');

  const { page, errors, dialogs } = await fresh(browser);
  await openLab(page, url + '?lesson=no-such-lesson&scene=%%%25&steps=12abc&ui=huge&id=a%20b&bogus=1&x%ZZ=1&BAD=2&&=&grid_n=3');
  const notice = (await api(page, 'status')).notice;
  await screenshot(page, 'url-garbage.png');
  for (const part of [/lesson "no-such-lesson" \(there is no such lesson\)/, /scene: /, /steps "12abc"/, /ui "huge"/,
                      /id "a b"/, /bogus \(not a parameter/, /"x%ZZ" is not a parameter/, /"BAD" is not a parameter/,
                      /grid_n \(not a parameter of /])
    assert.match(notice, part);
  assert.deepEqual(await api(page, 'snapshot'), defaults, 'the first lesson, exactly as it starts');
  assert.equal(await dom(page), cleanDom, 'no element added');
  // The accessible section shows the scene and the refused text as text, never as markup.
  assert.equal(await page.evaluate(() => document.querySelectorAll('.lab-access script, .lab-access img').length), 0);
  assert.deepEqual(errors, []);
  assert.deepEqual(dialogs, []);
  assert.deepEqual(await page.evaluate(() => window.__cspViolations), []);

  // Good lesson, bad values: each bad one is named and left at its default; good ones apply.
  const { page: p2, errors: e2 } = await fresh(browser);
  await openLab(p2, url + '?lesson=step-prm&samples=1e999&seed=-1&neighbors=k:0&checker=grid:1&steps=40&samples=5');
  const n2 = (await api(p2, 'status')).notice;
  assert.match(n2, /samples is given more than once/);
  assert.match(n2, /seed "-1" \(seed: an integer >= 0\)/);
  assert.match(n2, /neighbors "k:0"/);
  assert.match(n2, /checker "grid:1"/);
  const s2 = await api(p2, 'state');
  assert.deepEqual(s2.params, { checker: 'bisection', neighbors: 'k:10', samples: 200, seed: 1, sampler: 'uniform' },
                   'defaults stand in');
  assert.equal(s2.steps, 40, 'the good part of the link applies');
  const { page: p3 } = await fresh(browser);
  await openLab(p3, url + '?lesson=step-prm&samples=1e999');
  assert.match((await api(p3, 'status')).notice, /samples "1e999" \(out of range\)/);
  assert.deepEqual(e2, []);
}));

test('a 10 MB scene, a zip bomb, broken encodings and an invalid scene', () => withBrowser(async ({ browser, url }) => {
  // A 10 MB scene in the address (no server takes such a URL: the page's own history does).
  const big = 'z.' + 'A'.repeat(10 * 1024 * 1024);
  const { page, errors } = await fresh(browser, {
    init: `history.replaceState(null, '', '?lesson=step-prm&scene=${big}&seed=9');`,
  });
  const t0 = Date.now();
  await openLab(page, url);
  assert.equal(await page.evaluate(() => location.search.length > 10e6), true, 'the page saw the 10 MB link');
  assert.match((await api(page, 'status')).notice, /scene: 10\.0 MB is more than a link may carry \(64 KB\)/);
  assert.equal((await api(page, 'state')).params.seed, 9, 'the rest of the link still applies');
  assert.equal((await api(page, 'get_scene')).obstacles.length, 5, 'the lesson\'s default scene');
  assert.ok(Date.now() - t0 < 20000, 'refused without decoding');
  assert.deepEqual(errors, []);

  const cases = [
    // 8 MB of spaces deflate to a few KB: decompression stops at 1 MB.
    ['z.' + b64url(zlib.deflateRawSync(Buffer.alloc(8 << 20, 32))), /scene: is more than 1\.0 MB once decompressed/],
    ['z.' + b64url(Buffer.from('not deflate data at all')), /scene: is not valid compressed data/],
    ['z.@@@', /scene: is not base64url/],
    ['j.' + b64url('{"version": 1, '), /scene: is not JSON/],
    ['j.' + b64url('[1,2]'), /scene: is not a JSON object/],
    ['j.' + b64url(JSON.stringify({ version: 1, obstacles: [{ type: 'disk', center: [0, 0], radius: -1 }] })),
     /scene: obstacles\[0\]\.radius: must be >= 0/],
    ['j.' + b64url(JSON.stringify({ version: 1, robot: { type: 'arm2', base: [0.5, 0.5], lengths: [0.2, 0.2] } })),
     /scene: this lesson plans for a point robot/],
    ['no-such-scene', /scene "no-such-scene" \(no bundled scene has that name; there are .*p12/],
  ];
  for (const [scene, message] of cases) {
    const { page: p, errors: e } = await fresh(browser);
    await openLab(p, url + '?lesson=step-prm&scene=' + scene);
    assert.match((await api(p, 'status')).notice, message, scene.slice(0, 40));
    assert.equal((await api(p, 'get_scene')).obstacles.length, 5, 'the default scene');
    assert.deepEqual(e, [], 'no console errors for ' + scene.slice(0, 40));
    await p.close();
  }
}));

test('script tags in strings stay text', () => withBrowser(async ({ browser, url }) => {
  const evil = '<script>window.__pwned=1</script><img src=x onerror="window.__pwned=2">';
  const scene = { version: 1, name: evil, robot: { type: 'point' }, obstacles: [{ type: 'disk', center: [0.5, 0.5], radius: 0.1 }],
                  start: [0.1, 0.1], goal: [0.9, 0.9] };
  const { page: clean } = await fresh(browser);
  // The same lesson and obstacles: the page's accessible section holds the lesson's own controls
  // and a box per obstacle.
  await openLab(clean, url + '?lesson=step-prm&scene=j.' + b64url(JSON.stringify({ ...scene, name: 'clean' })));
  const cleanDom = await dom(clean);

  const link = url + '?lesson=step-prm&scene=j.' + b64url(JSON.stringify(scene)) + '&neighbors=' + encodeURIComponent(evil) +
               '&' + encodeURIComponent('<script>') + '=1&id=' + encodeURIComponent(evil);
  const { page, errors, dialogs } = await fresh(browser);
  await openLab(page, link);
  const notice = (await api(page, 'status')).notice;
  assert.match(notice, /neighbors "<script>window\.__pwned=1…"/, 'shown as text in the app');
  assert.match(notice, /"<script>" is not a parameter/);
  assert.equal((await api(page, 'get_scene')).name, evil, 'a scene name is data: kept as it is');
  assert.equal(await page.evaluate(() => window.__pwned), undefined, 'nothing ran');
  assert.equal(await dom(page), cleanDom, 'no element added');
  // The accessible section shows the scene and the refused text as text, never as markup.
  assert.equal(await page.evaluate(() => document.querySelectorAll('.lab-access script, .lab-access img').length), 0);

  // The share and embed dialogs carry the name and the link as field values, never markup.
  await page.evaluate(() => window.cspacelab.shell.action('embed'));
  await page.waitForSelector('.lab-dialog textarea');
  const fields = await page.$$eval('.lab-dialog textarea', (a) => a.map((t) => t.value));
  assert.ok(fields.every((f) => !f.includes('<script>window')), 'attribute values are escaped in the snippets');
  assert.equal(await page.evaluate(() => document.querySelectorAll('.lab-dialog script, .lab-dialog img, .lab-dialog iframe').length), 0);
  assert.equal(await page.evaluate(() => window.__pwned), undefined);
  assert.deepEqual(errors, []);
  assert.deepEqual(dialogs, []);
  assert.deepEqual(await page.evaluate(() => window.__cspViolations), []);
}));

test('the pages carry a Content-Security-Policy without inline script', () => withBrowser(async ({ browser, url }) => {
  for (const path of ['index.html', 'embed.html', 'examples/course-page.html']) {
    const { page } = await fresh(browser);
    await page.goto(url + path);
    const { csp, inline } = await page.evaluate(() => ({
      csp: document.querySelector('meta[http-equiv="Content-Security-Policy"]')?.content || '',
      inline: Array.from(document.scripts).filter((s) => !s.src).length,
    }));
    assert.match(csp, /script-src 'self' 'wasm-unsafe-eval'/, path);
    assert.doesNotMatch(csp, /'unsafe-inline'|'unsafe-eval'/, path);
    assert.equal(inline, 0, `${path} has no inline script`);
    // The policy is enforced: an injected inline script does not run.
    const ran = await page.evaluate(() => {
      const s = document.createElement('script');
      s.textContent = 'window.__inline = 1';
      document.body.appendChild(s);
      return window.__inline === 1;
    });
    assert.equal(ran, false, `${path} blocks inline script`);
    await page.close();
  }
}));
