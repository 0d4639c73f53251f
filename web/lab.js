// Starts C-Space Lab in every [data-lab] element of the page, one independent instance each.
//
//   <div id="my-lab" data-lab="lesson=collision&amp;scene=p12" style="height:600px"></div>
//   <script src="https://your.site/cspacelab/lab.js" defer></script>
//
// data-lab holds the instance's configuration in a link's syntax (lab-url.js); with
// data-lab-config="url" the page's own address is read instead (index.html, embed.html).
// data-lab-ui="full|minimal" sets the default UI (a link's ui= wins); data-lab-home is where
// Share links point (default: the full lab next to this script). The element's id keeps its
// autosave apart from other labs on the page.
//
// data-lab-task="…" is the task text shown above the canvas (plain text; a task= in data-lab wins).
//
// assignment=URL (a relative URL of this site) puts the lab in assignment mode: lab-assignment.js,
// loaded only then, opens the file and reports to an LMS (SCORM) in a parent frame;
// data-lab-scorm="1.2|2004" says which LMS object to look for first (a package's launch page).
// element.cspacelabAssignment is then a promise of its CSpaceLabAssignment (.state null if the
// file was refused; null if the mode could not start at all).
//
// author=1 opens the instructor's Author view (lab-author.js, loaded only then).
//
// This script loads the rest (PARTS below; the accessible copies and print after the start) from
// its own folder unless the page has them; from a course page of another origin when the lab's
// server sends Access-Control-Allow-Origin (the wasm is fetched; docs/web.md, "Cross-origin
// embedding"). Each lab's API is element.cspacelab once it has started (the element then fires
// "cspacelab-ready"); window.cspacelab is the page's first lab's.
'use strict';

(function () {
  const script = document.currentScript;
  const pageUrl = location.href.split(/[?#]/)[0];
  // The folder of this script; an inlined copy (single-file build) uses the page's.
  const base = script && script.src ? new URL('.', script.src).href : new URL('.', pageUrl).href;
  const PARTS = [['createCSpaceLab', 'cspacelab.js'], ['CSpaceLabApi', 'lab-api.js'],
                 ['CSpaceLabUrl', 'lab-url.js'], ['CSpaceLabShell', 'lab-shell.js'],
                 ['CSpaceLabAccess', 'lab-access.js'], ['CSpaceLabTask', 'lab-task.js']];
  const registry = window.CSpaceLab = window.CSpaceLab || { instances: [] };
  const shells = [];  // every lab's page shell, started or not (traps are routed to them)

  // A trap in a frame reaches the page as an uncaught error (Emscripten's main loop rethrows it):
  // it belongs to the lab whose frame was running. One outside any frame (an input handler) is
  // the only lab's when there is just one, if it is a WebAssembly.RuntimeError: a page script's
  // own RangeError or SyntaxError is not the lab's.
  window.addEventListener('error', (event) => {
    const live = shells.filter((s) => !s.dead);
    const inFrame = live.filter((s) => s.inFrame);
    if (inFrame.length) for (const s of inFrame) s.trap(event.error || new Error(event.message));
    else if (live.length === 1 && window.CSpaceLabShell && window.CSpaceLabShell.isTrap(event.error)) live[0].trap(event.error);
  });

  function load(file) {
    return new Promise((resolve, reject) => {
      const s = document.createElement('script');
      s.src = base + file;
      s.async = false;  // run in order, fetch in parallel
      s.onload = resolve;
      s.onerror = () => reject(new Error('could not load ' + file));
      document.head.appendChild(s);
    });
  }

  // The single-file build carries the wasm in the page: <script type="application/octet-stream"
  // id="cspacelab-wasm" data-encoding="gzip-base64">.
  let inlineWasm = null;
  function wasmFromPage() {
    const block = document.getElementById('cspacelab-wasm');
    if (!block) return Promise.resolve(null);
    if (!inlineWasm) {
      inlineWasm = (async () => {
        const binary = atob(block.textContent.trim());
        const bytes = new Uint8Array(binary.length);
        for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
        if (block.dataset.encoding !== 'gzip-base64') return bytes;
        if (typeof DecompressionStream !== 'function')
          throw new Error('this browser cannot unpack the single-file build (it needs DecompressionStream)');
        const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'));
        return new Uint8Array(await new Response(stream).arrayBuffer());
      })();
    }
    return inlineWasm;
  }

  /**
   * fetch() of a file of the lab. A page of another origin (a course page) may read it only if
   * the lab's server sends Access-Control-Allow-Origin; else the browser says "Failed to fetch".
   * So a failed fetch across origins is tried once more without reading it (mode no-cors): if
   * the server answers that, the header is missing, and the error says which one to add.
   */
  async function fetchFile(url) {
    try {
      return await fetch(url, { credentials: 'same-origin' });
    } catch (err) {
      const target = new URL(url, location.href);
      if (target.origin === location.origin) throw err;
      let answered = false;
      try {
        await fetch(target.href, { mode: 'no-cors', credentials: 'omit', cache: 'no-store' });
        answered = true;
      } catch {
        // not reachable at all (or this page's CSP refuses the origin): said below
      }
      const file = target.pathname.split('/').pop();
      const here = location.origin === 'null' ? 'this page' : `this page (${location.origin})`;
      if (answered) {
        throw new Error(`the lab's server (${target.origin}) does not let ${here} read ${file}: ` +
                        'it must send the header "Access-Control-Allow-Origin: *" (or name this page\'s origin) ' +
                        'with the lab\'s files. The lab\'s docs (web.md, "Cross-origin embedding") show it for common servers.');
      }
      throw new Error(`${target.href} could not be fetched (${err && err.message ? err.message : err}): the lab's server ` +
                      `did not answer, or this page's Content-Security-Policy does not allow ${target.origin} in connect-src.`);
    }
  }

  // The wasm, fetched and compiled once, as early as possible, for every lab on the page
  // (Module.instantiateWasm hands each instance the shared WebAssembly.Module).
  let compiled = null;
  function compileWasm() {
    if (!compiled) {
      compiled = (async () => {
        if (document.getElementById('cspacelab-wasm')) return WebAssembly.compile(await wasmFromPage());
        const url = base + 'cspacelab.wasm';
        const response = await fetchFile(url);
        if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
        // Streaming compilation needs the type application/wasm; other servers: from the bytes.
        if (typeof WebAssembly.compileStreaming === 'function' &&
            /^application\/wasm\b/i.test(response.headers.get('Content-Type') || ''))
          return WebAssembly.compileStreaming(response);
        return WebAssembly.compile(await response.arrayBuffer());
      })();
      compiled.catch(() => {});  // reported by each lab that waits for it
    }
    return compiled;
  }

  // Whether this browser runs WebAssembly's 128-bit SIMD, which the lab is built with: a
  // module of one function returning v128.const 0 is valid exactly where it does.
  function wasmSimd() {
    const module = new Uint8Array([0, 0x61, 0x73, 0x6d, 1, 0, 0, 0, 1, 5, 1, 0x60, 0, 1, 0x7b, 3, 2, 1, 0,
                                   0x0a, 0x16, 1, 0x14, 0, 0xfd, 0x0c, ...new Array(16).fill(0), 0x0b]);
    return typeof WebAssembly === 'object' && WebAssembly.validate(module);
  }

  function ensure(root, selector, make) {
    let node = root.querySelector(selector);
    if (!node) {
      node = make();
      root.appendChild(node);
    }
    return node;
  }

  // The lab's stylesheet, first in <head> so that the page's own rules win.
  function ensureStyles() {
    const links = Array.from(document.querySelectorAll('link[rel~="stylesheet"]'));
    if (links.some((l) => /(^|\/)lab\.css([?#]|$)/.test(l.getAttribute('href') || '')) || document.querySelector('style[data-lab-css]')) return;
    const link = document.createElement('link');
    link.rel = 'stylesheet';
    link.href = base + 'lab.css';
    document.head.insertBefore(link, document.head.firstChild);
  }

  async function start(root, index) {
    if (root.cspacelabStarted) return root.cspacelabStarted;
    root.classList.add('lab');
    const canvas = ensure(root, 'canvas', () => {
      const c = document.createElement('canvas');
      c.className = 'lab-canvas';
      c.tabIndex = 0;
      c.setAttribute('aria-label', 'C-Space Lab: interactive motion-planning canvas');
      return c;
    });
    const status = ensure(root, '.lab-status', () => {
      const s = document.createElement('div');
      s.className = 'lab-status';
      s.setAttribute('role', 'status');
      s.textContent = 'Loading C-Space Lab…';
      return s;
    });
    const showError = (message) => {
      status.hidden = false;
      status.classList.add('error');
      status.textContent = message;  // textContent: never parsed as HTML
    };

    const U = window.CSpaceLabUrl;
    const fromUrl = root.getAttribute('data-lab-config') === 'url';
    const config = fromUrl ? location.search : (root.getAttribute('data-lab') || '');
    const { values } = U.parseConfig(config);  // the shell reports this parse's problems
    const uiAttr = root.getAttribute('data-lab-ui');
    const ui = ['full', 'minimal'].includes(values.get('ui')) ? values.get('ui')
             : ['full', 'minimal'].includes(uiAttr) ? uiAttr : fromUrl ? 'full' : 'minimal';
    const single = !!document.getElementById('cspacelab-wasm');
    // The task, above the canvas from the start (the lab's height includes it).
    const task = window.CSpaceLabTask.normalise(values.has('task') ? values.get('task') : root.getAttribute('data-lab-task') || '');
    window.CSpaceLabTask.show(root, canvas, task);
    let storageId = [values.get('id'), root.getAttribute('data-lab-id'), root.id].find((x) => x && U.ID.test(x));
    if (!storageId) {
      if (!fromUrl) storageId = 'lab-' + index;
      else storageId = ui === 'minimal' && U.hasState(values) ? 'embed-' + U.stateKey(values).replace(':', '-') : 'main';
    }
    const options = {
      config,
      ui,
      storageId,
      scope: location.pathname.replace(/\/index\.html$/, '/'),
      home: root.getAttribute('data-lab-home') || (single || (fromUrl && ui === 'full') ? pageUrl : base + 'index.html'),
      base,
      single,
      task,
      // A lab with a page of its own has nothing to scroll: the wheel always zooms there.
      guardWheel: !fromUrl || window.top !== window,
    };
    root.classList.toggle('lab-minimal', ui === 'minimal');
    if (!fromUrl || window.top !== window) root.classList.add('lab-embedded');

    // (Cheap: creating a WebGL context only to test for it would cost a context and ~100 ms.)
    const noWebGl2 = 'C-Space Lab needs WebGL2, which this browser does not offer. Try a current Chrome, Firefox or Safari.';
    if (typeof WebGL2RenderingContext === 'undefined') {
      showError(noWebGl2);
      return null;
    }
    if (!wasmSimd()) {
      showError('C-Space Lab needs WebAssembly with SIMD, which this browser does not offer. ' +
                'Try Chrome or Edge 91+, Firefox 89+ or Safari 16.4+.');
      return null;
    }
    // The shell exists before the wasm: if the app fails at any point from here, it shows that
    // in the lab's place and offers the work saved in this browser (it needs only storage).
    const shell = new window.CSpaceLabShell(root, canvas, null, options);
    shells.push(shell);
    let module;
    try {
      module = await window.createCSpaceLab({
        canvas,
        print: (text) => console.log(text),
        printErr: (text) => {
          if (/Could not create an OpenGL\/WebGL2 context/.test(text)) showError(noWebGl2);
          else console.warn(text);
        },
        onAbort: (what) => shell.trap(new Error(String(what))),
        // A frame that throws is a trap (Emscripten stops the loop and rethrows it, past onAbort):
        // the page's error event finds the lab that was inside a frame. A stopped lab draws no more.
        preMainLoop: () => shell.framePre(),
        postMainLoop: () => shell.framePost(),
        instantiateWasm(imports, receive) {
          compileWasm()
            .then((m) => WebAssembly.instantiate(m, imports).then((instance) => receive(instance, m)))
            .catch((err) => showError('C-Space Lab could not start: ' + (err && err.message ? err.message : err)));
          return {};  // asynchronous
        },
      });
    } catch (err) {
      showError('C-Space Lab could not start: ' + (err && err.message ? err.message : err));
      return null;
    }
    const api = new window.CSpaceLabApi(module);
    shell.attach(api);
    api.shell = shell;
    root.cspacelabShell = shell;
    try {
      await shell.init();
    } catch (err) {
      if (!shell.dead) console.error('C-Space Lab: the page shell failed', err);
    }
    if (shell.dead) {
      // The crash panel is in the lab's place; the page can tell.
      status.hidden = true;
      root.dispatchEvent(new CustomEvent('cspacelab-stopped', { detail: shell, bubbles: true }));
      return null;
    }
    // The parallel DOM: what the canvas shows, as HTML a screen reader and the keyboard reach.
    root.cspacelabAccess = new window.CSpaceLabAccess(root, canvas, api, { ui });
    // Fetched after the first frame: the homework card's, top bar's, tables' and scene's copies,
    // and the worksheet the lab prints as (its picture, task and parameters, no controls).
    for (const n of ['Homework', 'Actions', 'Tables', 'Scene'])
      need(`CSpaceLab${n}Access`, `lab-${n.toLowerCase()}-access.js`)
        .then(() => window[`CSpaceLab${n}Access`](root.cspacelabAccess)).catch(console.warn);
    need('CSpaceLabPrint', 'lab-print.js')
      .then(() => { root.cspacelabPrint = new window.CSpaceLabPrint(root, canvas, api, shell); }).catch(console.warn);
    root.cspacelab = api;
    registry.instances.push(api);
    if (index === 0) window.cspacelab = api;  // the first lab in the page's order
    status.hidden = true;
    if (fromUrl && ui === 'full' && window.top === window) canvas.focus({ preventScroll: true });
    if (values.has('assignment')) root.cspacelabAssignment = startAssignment(root, api, values.get('assignment'), single);
    shell.openAuthor = () => openAuthor(root, api, single);
    if (values.has('author')) {
      if (values.get('author') === '1') root.cspacelabAuthor = openAuthor(root, api, single);
      else api.notify(`author: 1 opens the Author view, not ${U.excerpt(values.get('author'))}`);
    }
    root.dispatchEvent(new CustomEvent('cspacelab-ready', { detail: api, bubbles: true }));
    return api;
  }

  // A part's script, loaded once (unless the page has it).
  const loading = {};
  const need = (name, file) => window[name] ? Promise.resolve() : (loading[file] = loading[file] || load(file));

  /** Assignment mode: lab-assignment.js, loaded now (no other lab pays for it), opens the file. */
  async function startAssignment(root, api, raw, single) {
    try {
      if (single) throw new Error('the single-file lab cannot load files: use the lab\'s site or its SCORM package');
      await need('CSpaceLabAssignment', 'lab-assignment.js');
      if (root.cspacelabAccess) {  // the card in the accessible DOM, before the first event
        await need('CSpaceLabAssignmentAccess', 'lab-assignment-access.js');
        window.CSpaceLabAssignmentAccess(root.cspacelabAccess);
      }
      const A = window.CSpaceLabAssignment;
      const assignment = new A(root, api, A.assignmentUrl(raw, location.href));
      await assignment.start();
      return assignment;
    } catch (err) {
      return notifyFailure(api, 'No assignment: ', err);
    }
  }

  function notifyFailure(api, prefix, err) {
    try {
      api.notify(prefix + (err && err.message ? err.message : err));
    } catch {
      // the lab stopped: its crash panel says why
    }
    return null;
  }

  /** The Author view (author=1, File menu): its scripts load only now. Resolves to it or null. */
  async function openAuthor(root, api, single) {
    try {
      if (single) throw new Error('the single-file lab cannot package the site');
      for (const [name, file] of [['CSpaceLabAuthor', 'lab-author.js'], ['CSpaceLabScormPackage', 'lab-scorm-package.js']])
        await need(name, file);
      const view = root.cspacelabAuthorView = root.cspacelabAuthorView || new window.CSpaceLabAuthor(root, api, { base, load });
      view.open();
      return view;
    } catch (err) {
      return notifyFailure(api, 'No Author view: ', err);
    }
  }

  /** Starts every [data-lab] element not started yet; resolves to their APIs. */
  registry.startAll = function startAll() {
    ensureStyles();
    const roots = Array.from(document.querySelectorAll('[data-lab]'));
    return Promise.all(roots.map((root, i) => {
      if (!root.cspacelabStarted) root.cspacelabStarted = start(root, i);
      return root.cspacelabStarted;
    }));
  };

  if (wasmSimd()) compileWasm();  // where it could not compile, each lab says why instead
  const missing = PARTS.filter(([name]) => typeof window[name] === 'undefined').map(([, file]) => file);
  const loaded = Promise.all(missing.map(load));
  const domReady = document.readyState === 'loading'
    ? new Promise((resolve) => document.addEventListener('DOMContentLoaded', resolve, { once: true }))
    : Promise.resolve();
  registry.ready = Promise.all([loaded, domReady]).then(registry.startAll, (err) => {
    for (const root of document.querySelectorAll('[data-lab]')) {
      const status = root.querySelector('.lab-status') || root.appendChild(document.createElement('div'));
      status.className = 'lab-status error';
      status.textContent = 'C-Space Lab could not start: ' + err.message;
    }
  });
})();
