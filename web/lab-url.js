// C-Space Lab's links and configuration strings, parsed strictly in plain JS.
//
//   ?lesson=step-prm&scene=p12&samples=120&neighbors=k:8&checker=bisection&seed=7&steps=50&ui=minimal
//
// The same syntax configures an instance on a page: <div data-lab="lesson=collision&amp;scene=p12">.
// ?problem=P10[&seed=S] opens a homework problem instead.
// Keys (docs/web.md, Links, describes each):
//   lesson   a lesson's id                     scene   a bundled scene's name or an encoded scene
//   steps    the step to show                  ui      full | minimal
//   id       the autosave slot                 problem a homework problem, P1 … P13 (with seed)
//   task     the task text shown above the canvas (plain text, lines = paragraphs, at most 1000
//            characters; not part of the state: a new task keeps a student's saved work)
//   scheme   system | light | dark, and contrast system | normal | high: the look for this visit
//            (the student's own choice in File > Display is kept by the page)
//   camera   where the views look, each view name:numbers, views joined by "~":
//              camera=workspace:0.31,0.62,4~torus:1.2,0.4
//            a plane's centre x, y and zoom (1: Fit, 0.5 to 200), a 3-D view's yaw and pitch
//            (radians) and, for one that zooms (volume:0.8,0.5,1.44), its zoom (0.5 to 4; left
//            out when 1, and a link without it means 1); only views the user zoomed, panned or
//            turned are written; the app checks names and ranges. Part of the state, as a
//            snapshot holds it.
//   assignment  an assignment file to work through (docs/web.md, Assignments): a relative URL of
//            this site ("assignment.json", "week3/a.json"; another origin, a scheme or "//host"
//            is refused). lab.js then loads lab-assignment.js, which checks the URL, opens the
//            file and reports to an LMS (SCORM) in a parent frame. Not part of the state.
//   author   1: opens the instructor's Author view (docs/web.md, Authoring). Not state.
//   and the lesson's own parameters (whatever its params() reports: samples, neighbors,
//   checker, seed, sampler for Step PRM; grid_n, p, q for Collision checking; …).
//   lock     scene, params, lesson or a parameter's name: what the student cannot change
//   hide     answers (every lesson's), none, or answers by name (min_n, ...): not shown
//   reveal   never | after-answer: a hidden answer comes back once its homework exercise was
//            answered right (default never)
//            (lock, hide, reveal: comma-separated words the app reads, core/teaching/restrictions.hpp;
//            problem links take them too; Share and Embed write them again, so a link passed on
//            keeps its locks; `cspacelab link` writes them the same way)
// Values are never evaluated: numbers must match a number's syntax, lists are comma-separated
// numbers, strings go to the app, which checks them. A scene is a bundled scene's name or
//   z.<base64url of the deflate-raw of the scene's JSON>   (CompressionStream, all current browsers)
//   j.<base64url of the scene's JSON>                       (what a browser without it writes)
// Anything wrong is reported as a problem (text for the in-app notice) and that part is ignored.
'use strict';

(function (global) {
  const LIMITS = Object.freeze({
    sceneParam: 64 * 1024,   // characters of an encoded scene a link or page may carry
    sceneJson: 1024 * 1024,  // bytes of a scene's JSON once decoded (a zip bomb stops here)
    shareScene: 6000,        // characters of an encoded scene a Share link will hold (servers cap URLs near 8 KB)
    value: 256,              // characters of any other value
    task: 12 * 1024,         // characters of an escaped task= (1000 characters, each up to 12 escaped: %F0%9F%98%80)
    entries: 64,             // key=value pairs
    depth: 64,               // levels of JSON nesting (the app's kMaxJsonDepth, src/core/scene/scene.hpp)
  });
  const RESERVED = new Set(['lesson', 'scene', 'steps', 'ui', 'id', 'problem', 'task', 'scheme', 'contrast',
                            'camera', 'lock', 'hide', 'reveal', 'assignment', 'author']);
  // Keys that say how to show the lab, not what it shows: they are not part of its state. (lock,
  // hide and reveal are: a link that adds a lock applies again, so the lock holds the link's scene.)
  const PRESENTATION = new Set(['ui', 'id', 'task', 'scheme', 'contrast', 'assignment', 'author']);
  const RESTRICTION_KEYS = ['lock', 'hide', 'reveal'];
  const WORDS = /^[a-z0-9_,-]*$/;
  const KEY = /^[a-z][a-z0-9_]{0,31}$/;
  const NAME = /^[a-z0-9][a-z0-9-]{0,39}$/;
  const NUMBER = /^-?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d{1,3})?$/;
  const STEPS = /^\d{1,9}$/;
  const ID = /^[A-Za-z0-9_-]{1,40}$/;
  const B64URL = /^[A-Za-z0-9_-]+$/;
  const VIEW = /^[a-z][a-z0-9]{0,15}$/;
  const MAX_VIEWS = 8;

  /** A short, printable excerpt of untrusted text for a message: "abc…" (quotes included). */
  function excerpt(text, max = 24) {
    const s = String(text);
    let out = '';
    for (const ch of s.slice(0, max)) {
      const c = ch.codePointAt(0);
      out += c < 0x20 || (c >= 0x7f && c < 0xa0) || c > 0xffff ? '?' : ch;
    }
    return '"' + out + (s.length > max ? '…' : '') + '"';
  }

  function sizeText(n) {
    if (n >= 1024 * 1024) return (n / (1024 * 1024)).toFixed(1) + ' MB';
    if (n >= 1024) return Math.round(n / 1024) + ' KB';
    return n + ' characters';
  }

  function decodeComponent(text) {
    try {
      return decodeURIComponent(text.replace(/\+/g, ' '));
    } catch {
      return null;
    }
  }

  /**
   * Splits a query string ("?a=1&b=2", "a=1&b=2" or "") into raw values by key, checking the
   * syntax only. Returns {values: Map(key -> string), problems: [text]}. Keys given twice,
   * unknown-looking keys, oversized values and undecodable escapes are problems, and dropped.
   */
  function parseConfig(text) {
    const values = new Map();
    const problems = [];
    const seen = new Set();
    let query = typeof text === 'string' ? text : '';
    if (query.startsWith('?')) query = query.slice(1);
    if (query === '') return { values, problems };
    const pieces = query.split('&');
    if (pieces.length > LIMITS.entries) {
      problems.push(`the link has ${pieces.length} parts; at most ${LIMITS.entries} are read`);
      pieces.length = LIMITS.entries;
    }
    for (const piece of pieces) {
      if (piece === '') continue;
      const eq = piece.indexOf('=');
      const rawKey = eq < 0 ? piece : piece.slice(0, eq);
      const rawValue = eq < 0 ? '' : piece.slice(eq + 1);
      const key = rawKey.length <= 64 ? decodeComponent(rawKey) : null;
      if (key === null || !KEY.test(key)) {
        problems.push(`${excerpt(key === null ? rawKey : key)} is not a parameter`);
        continue;
      }
      if (seen.has(key)) {
        problems.push(`${key} is given more than once`);
        values.delete(key);
        continue;
      }
      seen.add(key);
      const limit = key === 'scene' ? LIMITS.sceneParam : key === 'task' ? LIMITS.task : LIMITS.value;
      if (rawValue.length > limit) {
        problems.push(`${key}: ${sizeText(rawValue.length)} is more than a link may carry (${sizeText(limit)})`);
        continue;
      }
      const value = decodeComponent(rawValue);
      if (value === null) {
        problems.push(`${key}: ${excerpt(rawValue)} is not properly escaped`);
        continue;
      }
      values.set(key, value);
    }
    return { values, problems };
  }

  /** Whether parsed values hold state (anything besides the PRESENTATION keys). */
  function hasState(values) {
    for (const key of values.keys()) if (!PRESENTATION.has(key)) return true;
    return false;
  }

  /** A short key for the state part of parsed values (not the PRESENTATION keys): "length:hash". */
  function stateKey(values) {
    const parts = [];
    for (const [k, v] of values) if (!PRESENTATION.has(k)) parts.push(k + '=' + v);
    const text = parts.join('&');
    return text.length + ':' + hash(text);
  }

  function parseNumber(raw) {
    if (raw.length > 40 || !NUMBER.test(raw)) throw new Error('not a number');
    const n = Number(raw);
    if (!Number.isFinite(n)) throw new Error('out of range');
    return n;
  }

  /**
   * A lesson parameter's value from its text, typed like the lesson's current value `template`:
   * a number, true/false, a string (the app checks it), or a list of numbers "a,b".
   */
  function parseValue(raw, template) {
    if (typeof template === 'number') return parseNumber(raw);
    if (typeof template === 'boolean') {
      if (raw === 'true' || raw === '1') return true;
      if (raw === 'false' || raw === '0') return false;
      throw new Error('not true or false');
    }
    if (typeof template === 'string') return raw;
    if (Array.isArray(template) && template.every((x) => typeof x === 'number')) {
      const parts = raw.split(',');
      if (parts.length !== template.length) throw new Error(`not ${template.length} comma-separated numbers`);
      return parts.map(parseNumber);
    }
    throw new Error('cannot be set from a link');
  }

  /**
   * The cameras of a link's camera value, as the app's snapshot holds them:
   * "workspace:0.31,0.62,4~torus:1.2,0.4" -> {workspace: [0.31, 0.62, 4], torus: [1.2, 0.4]}.
   * Throws an Error saying what is wrong (the syntax only: the app knows the lesson's views, which
   * are planes and which 3-D, and their ranges).
   */
  function parseCamera(raw) {
    const out = {};
    const parts = raw.split('~');
    if (parts.length > MAX_VIEWS) throw new Error(`more than ${MAX_VIEWS} views`);
    for (const part of parts) {
      const m = /^([^:]*):(.*)$/.exec(part);
      if (!m) throw new Error(`${excerpt(part)} is not view:numbers`);
      const [, name, list] = m;
      if (!VIEW.test(name)) throw new Error(`${excerpt(name)} is not a view's name`);
      if (Object.prototype.hasOwnProperty.call(out, name)) throw new Error(`${name} is given twice`);
      let numbers;
      try {
        numbers = list.split(',').map(parseNumber);
      } catch (e) {
        throw new Error(`${name}: ${excerpt(list)} is not comma-separated numbers`);
      }
      if (numbers.length !== 2 && numbers.length !== 3)
        throw new Error(`${name}: x,y,zoom (a plane) or yaw,pitch[,zoom] (a 3-D view), not ${numbers.length} numbers`);
      out[name] = numbers;
    }
    return out;
  }

  /** A snapshot's cameras as a link's camera value (parseCamera's inverse), or null if there are none. */
  function formatCamera(camera) {
    const parts = [];
    for (const [name, numbers] of Object.entries(camera || {}))
      if (VIEW.test(name) && Array.isArray(numbers) && numbers.every((x) => typeof x === 'number' && Number.isFinite(x)))
        parts.push(name + ':' + numbers.map(String).join(','));
    return parts.length ? parts.join('~') : null;
  }

  /** The text of a parameter's value in a link, or null if a link cannot hold it. */
  function formatValue(v) {
    if (typeof v === 'number') return Number.isFinite(v) ? String(v) : null;
    if (typeof v === 'boolean') return v ? 'true' : 'false';
    if (typeof v === 'string') return v;
    if (Array.isArray(v) && v.every((x) => typeof x === 'number' && Number.isFinite(x))) return v.map(String).join(',');
    return null;
  }

  /** Percent-encodes a value, leaving the readable ':' and ',' alone (both are fine in a query). */
  function encodeValue(text) {
    return encodeURIComponent(text).replace(/%3A/gi, ':').replace(/%2C/gi, ',');
  }

  function toBase64Url(bytes) {
    let binary = '';
    for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
    return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
  }

  function fromBase64Url(text) {
    if (!B64URL.test(text) || text.length % 4 === 1) throw new Error('is not base64url');
    const b64 = text.replace(/-/g, '+').replace(/_/g, '/') + '==='.slice((text.length + 3) % 4);
    let binary;
    try {
      binary = atob(b64);
    } catch {
      throw new Error('is not base64url');
    }
    const bytes = new Uint8Array(binary.length);
    for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
    return bytes;
  }

  /** Runs bytes through a (de)compression stream, stopping past `limit` output bytes. */
  async function transform(bytes, stream, limit) {
    const reader = new Blob([bytes]).stream().pipeThrough(stream).getReader();
    const chunks = [];
    let total = 0;
    for (;;) {
      let part;
      try {
        part = await reader.read();
      } catch {
        throw new Error('is not valid compressed data');
      }
      if (part.done) break;
      total += part.value.length;
      if (total > limit) {
        reader.cancel().catch(() => {});
        throw new Error(`is more than ${sizeText(limit)} once decompressed`);
      }
      chunks.push(part.value);
    }
    const out = new Uint8Array(total);
    let at = 0;
    for (const c of chunks) {
      out.set(c, at);
      at += c.length;
    }
    return out;
  }

  /** Whether JSON text nests past LIMITS.depth (checked before parsing: a recursive JSON.stringify fails from ~20000). */
  function tooDeep(text) {
    for (let i = 0, depth = 0, str = false; i < text.length; ++i) {
      const c = text[i];
      if (str) {
        if (c === '\\') ++i;
        else if (c === '"') str = false;
      } else if (c === '"') str = true;
      else if ((c === '[' || c === '{') && ++depth > LIMITS.depth) return true;
      else if (c === ']' || c === '}') --depth;
    }
    return false;
  }

  /** The compact text of a scene for a link: "z.…" (deflate-raw) or "j.…" (plain JSON). */
  async function encodeScene(scene) {
    const bytes = new TextEncoder().encode(JSON.stringify(scene));
    if (typeof CompressionStream === 'function') {
      try {
        return 'z.' + toBase64Url(await transform(bytes, new CompressionStream('deflate-raw'), Infinity));
      } catch {
        // fall through to the uncompressed form
      }
    }
    return 'j.' + toBase64Url(bytes);
  }

  /** The scene object of an encoded scene; throws an Error saying what is wrong with it. */
  async function decodeScene(text) {
    if (text.length > LIMITS.sceneParam) throw new Error(`${sizeText(text.length)} is more than a link may carry`);
    const m = /^([zj])\.(.*)$/s.exec(text);
    if (!m) throw new Error(`${excerpt(text)} is neither a bundled scene nor an encoded one (z.… or j.…)`);
    let bytes = fromBase64Url(m[2]);
    if (m[1] === 'z') {
      if (typeof DecompressionStream !== 'function') throw new Error('this browser cannot read compressed scenes');
      bytes = await transform(bytes, new DecompressionStream('deflate-raw'), LIMITS.sceneJson);
    } else if (bytes.length > LIMITS.sceneJson) {
      throw new Error(`is more than ${sizeText(LIMITS.sceneJson)}`);
    }
    let json;
    try {
      json = new TextDecoder('utf-8', { fatal: true }).decode(bytes);
    } catch {
      throw new Error('is not UTF-8 text');
    }
    if (tooDeep(json)) throw new Error(`is nested more than ${LIMITS.depth} levels deep`);
    let value;
    try {
      value = JSON.parse(json);
    } catch {
      throw new Error('is not JSON');
    }
    if (value === null || typeof value !== 'object' || Array.isArray(value)) throw new Error('is not a JSON object');
    return value;
  }

  function sameJson(a, b) {
    return JSON.stringify(a) === JSON.stringify(b);
  }

  /**
   * The query (without '?') that reproduces a snapshot {lesson, scene, params, steps, camera} exactly.
   * `bundled` maps names to the bundled scenes; a scene equal to one is written by name.
   * Returns {query, problems}: problems name what a link cannot hold (the link is then inexact).
   */
  async function buildQuery(snapshot, bundled = {}, extra = {}) {
    const parts = ['lesson=' + encodeValue(snapshot.lesson)];
    const problems = [];
    if (snapshot.scene) {
      const name = Object.keys(bundled).find((n) => sameJson(bundled[n], snapshot.scene));
      const text = name || (await encodeScene(snapshot.scene));
      if (!name && text.length > LIMITS.shareScene)
        problems.push(`the scene takes ${sizeText(text.length)} in a link, more than the ${sizeText(LIMITS.shareScene)} links may hold`);
      parts.push('scene=' + text);
    }
    for (const [key, value] of Object.entries(snapshot.params || {})) {
      const text = formatValue(value);
      if (text === null || !KEY.test(key) || RESERVED.has(key)) {
        problems.push(`the parameter ${key} cannot be written in a link`);
        continue;
      }
      const encoded = encodeValue(text);
      if (encoded.length > LIMITS.value) {  // parseConfig would refuse it
        problems.push(`the parameter ${key} takes ${sizeText(encoded.length)} in a link, ` +
                      `more than the ${sizeText(LIMITS.value)} a value may`);
        continue;
      }
      parts.push(key + '=' + encoded);
    }
    parts.push('steps=' + String(snapshot.steps || 0));
    const camera = formatCamera(snapshot.camera);
    if (camera !== null && encodeValue(camera).length > LIMITS.value)
      problems.push(`the views' zoom takes ${sizeText(encodeValue(camera).length)} in a link, more than the ${sizeText(LIMITS.value)} a value may`);
    else if (camera !== null) parts.push('camera=' + encodeValue(camera));
    for (const [key, value] of Object.entries(extra)) parts.push(key + '=' + encodeValue(String(value)));
    return { query: parts.join('&'), problems };
  }

  /**
   * A link's lock, hide and reveal, as text for the app's "restrict" (which names bad words):
   * {restrictions: {lock, hide, reveal}, problems}. A value that is not comma-separated words is
   * a problem here and left out.
   */
  function restrictionsOf(values) {
    const restrictions = {};
    const problems = [];
    for (const key of RESTRICTION_KEYS) {
      if (!values.has(key)) continue;
      const raw = values.get(key);
      if (WORDS.test(raw)) restrictions[key] = raw;
      else problems.push(`${key} ${excerpt(raw)} (comma-separated words: a-z, 0-9, _ and -)`);
    }
    return { restrictions, problems };
  }

  /** A short stable hash (FNV-1a, 32 bits, hex) of a string: storage ids of configured embeds. */
  function hash(text) {
    let h = 0x811c9dc5;
    for (let i = 0; i < text.length; ++i) {
      h ^= text.charCodeAt(i);
      h = Math.imul(h, 0x01000193) >>> 0;
    }
    return h.toString(16).padStart(8, '0');
  }

  const api = Object.freeze({
    LIMITS, RESERVED, PRESENTATION, RESTRICTION_KEYS, NAME, STEPS, ID,
    excerpt, sizeText, parseConfig, hasState, stateKey, parseValue, formatValue, encodeValue, restrictionsOf,
    parseCamera, formatCamera,
    encodeScene, decodeScene, tooDeep, buildQuery, hash, toBase64Url, fromBase64Url,
  });
  global.CSpaceLabUrl = api;
  if (typeof module !== 'undefined' && module.exports) module.exports = api;
})(typeof window !== 'undefined' ? window : globalThis);
