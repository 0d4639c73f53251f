// SCORM packages of an assignment, the one builder of both packagers: scripts/scorm-package.mjs
// (node, from a built site on disk) and the page's Author view (web/lab-author.js, in the
// browser, from the site it was served from). Same entries in the same order, same manifest,
// same launch page, same zip headers: the two differ only where the deflater does (node's
// zlib at level 9; a browser's CompressionStream has its own level and zlib build, so its
// compressed bytes differ while every file's content is the same).
//
// A classic script (a global CSpaceLabScormPackage in the page, loaded only by the Author view)
// that node takes with require() (module.exports): no build step, no second copy.
//
// The package: imsmanifest.xml, launch.html (the site's index.html with its lab in assignment
// mode, data-lab="assignment=assignment.json"), assignment.json, then the site's files sorted,
// without cspacelab-single.html (it repeats the wasm). site-files.json, written at build time
// (scripts/site-files.mjs), is that list for a page, which cannot list its own folder.
'use strict';

(function (global) {
  const LAUNCH = 'launch.html';
  const ASSIGNMENT = 'assignment.json';
  const MANIFEST = 'imsmanifest.xml';
  const SITE_LIST = 'site-files.json';
  const LEFT_OUT = ['cspacelab-single.html'];

  /** Whether a file of the built site goes into a package (not the left-out ones, not our own names). */
  function packaged(file) {
    return !LEFT_OUT.includes(file) && file !== LAUNCH && file !== ASSIGNMENT && file !== MANIFEST;
  }

  // XML 1.0 has no control characters but tab and the line ends: a title pasted with one would
  // make the LMS refuse the whole manifest, so they are left out.
  const xml = (s) => String(s).replace(/[\u0000-\u0008\u000B\u000C\u000E-\u001F]/g, '')
    .replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');

  /** The package's identifier from the assignment file's name: an XML ID (a letter first). */
  function packageId(name) {
    return 'cspacelab-' + String(name).replace(/[^A-Za-z0-9_.-]/g, '-');
  }

  /** The launch page: the site's index.html with its lab in assignment mode for SCORM `version`. */
  function launchPage(indexHtml, title, version) {
    const main = /<main class="lab"[^>]*>/;
    if (!main.test(indexHtml)) throw new Error('the site\'s index.html has no <main class="lab"> to configure');
    return indexHtml
      // Replaced by functions: in a replacement string, $' $& $1 in a title would be patterns.
      .replace(main, () => `<main class="lab" id="assignment" data-lab="assignment=${ASSIGNMENT}" data-lab-scorm="${version}">`)
      .replace(/<title>[^<]*<\/title>/, () => `<title>${xml(title)} - C-Space Lab</title>`)
      .replace(/\n\s*<meta name="description"[^>]*>/, '');
  }

  function fileList(files) {
    return files.map((f) => `      <file href="${xml(f)}"/>`).join('\n');
  }

  // The 1.2 manifest sets adlcp:masteryscore (the assignment's pass as a percentage; the lab
  // reports 1.2's raw score as a percentage); 2004 (4th edition) a primary objective satisfied
  // by measure with minNormalizedMeasure = pass, which the LMS gives as cmi.scaled_passing_score.
  function manifest12(id, title, pass, files) {
    const mastery = typeof pass === 'number' ? `\n        <adlcp:masteryscore>${Math.round(pass * 10000) / 100}</adlcp:masteryscore>` : '';
    return `<?xml version="1.0" encoding="UTF-8"?>
<manifest identifier="${id}" version="1"
    xmlns="http://www.imsproject.org/xsd/imscp_rootv1p1p2"
    xmlns:adlcp="http://www.adlnet.org/xsd/adlcp_rootv1p2"
    xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
    xsi:schemaLocation="http://www.imsproject.org/xsd/imscp_rootv1p1p2 imscp_rootv1p1p2.xsd http://www.imsglobal.org/xsd/imsmd_rootv1p2p1 imsmd_rootv1p2p1.xsd http://www.adlnet.org/xsd/adlcp_rootv1p2 adlcp_rootv1p2.xsd">
  <metadata>
    <schema>ADL SCORM</schema>
    <schemaversion>1.2</schemaversion>
  </metadata>
  <organizations default="org">
    <organization identifier="org">
      <title>${xml(title)}</title>
      <item identifier="item" identifierref="sco" isvisible="true">
        <title>${xml(title)}</title>${mastery}
      </item>
    </organization>
  </organizations>
  <resources>
    <resource identifier="sco" type="webcontent" adlcp:scormtype="sco" href="${LAUNCH}">
${fileList(files)}
    </resource>
  </resources>
</manifest>
`;
  }

  function manifest2004(id, title, pass, files) {
    const sequencing = typeof pass === 'number' ? `
        <imsss:sequencing>
          <imsss:objectives>
            <imsss:primaryObjective objectiveID="pass" satisfiedByMeasure="true">
              <imsss:minNormalizedMeasure>${pass}</imsss:minNormalizedMeasure>
            </imsss:primaryObjective>
          </imsss:objectives>
        </imsss:sequencing>` : '';
    return `<?xml version="1.0" encoding="UTF-8"?>
<manifest identifier="${id}" version="1"
    xmlns="http://www.imsglobal.org/xsd/imscp_v1p1"
    xmlns:adlcp="http://www.adlnet.org/xsd/adlcp_v1p3"
    xmlns:adlseq="http://www.adlnet.org/xsd/adlseq_v1p3"
    xmlns:adlnav="http://www.adlnet.org/xsd/adlnav_v1p3"
    xmlns:imsss="http://www.imsglobal.org/xsd/imsss"
    xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
    xsi:schemaLocation="http://www.imsglobal.org/xsd/imscp_v1p1 imscp_v1p1.xsd http://www.adlnet.org/xsd/adlcp_v1p3 adlcp_v1p3.xsd http://www.adlnet.org/xsd/adlseq_v1p3 adlseq_v1p3.xsd http://www.adlnet.org/xsd/adlnav_v1p3 adlnav_v1p3.xsd http://www.imsglobal.org/xsd/imsss imsss_v1p0.xsd">
  <metadata>
    <schema>ADL SCORM</schema>
    <schemaversion>2004 4th Edition</schemaversion>
  </metadata>
  <organizations default="org">
    <organization identifier="org">
      <title>${xml(title)}</title>
      <item identifier="item" identifierref="sco" isvisible="true">
        <title>${xml(title)}</title>${sequencing}
      </item>
    </organization>
  </organizations>
  <resources>
    <resource identifier="sco" type="webcontent" adlcp:scormType="sco" href="${LAUNCH}">
${fileList(files)}
    </resource>
  </resources>
</manifest>
`;
  }

  const utf8 = (s) => new TextEncoder().encode(s);

  /**
   * A package's entries ([{name, data: Uint8Array}], in zip order) for SCORM `version` ('1.2' or
   * '2004'): `checked` is the validated assignment ({title, pass}), `name` the assignment file's
   * name without .json, `assignmentBytes` the file as it will be served, `indexHtml` the site's
   * index.html, `site` [{name, data}] the site's files (filtered and sorted here).
   */
  function packageEntries({ version, checked, name, assignmentBytes, indexHtml, site }) {
    const title = checked.title || 'C-Space Lab assignment';
    const pass = typeof checked.pass === 'number' ? checked.pass : undefined;
    const files = site.filter((f) => packaged(f.name)).sort((a, b) => (a.name < b.name ? -1 : a.name > b.name ? 1 : 0));
    const entries = [
      { name: LAUNCH, data: utf8(launchPage(indexHtml, title, version)) },
      { name: ASSIGNMENT, data: assignmentBytes },
      ...files,
    ];
    const names = entries.map((e) => e.name);
    const id = packageId(name);
    const text = version === '1.2' ? manifest12(id, title, pass, names) : manifest2004(id, title, pass, names);
    entries.unshift({ name: MANIFEST, data: utf8(text) });
    return entries;
  }

  /** A package's file name: NAME-scorm12.zip or NAME-scorm2004.zip. */
  function zipName(name, version) {
    return `${name}-scorm${version === '1.2' ? '12' : '2004'}.zip`;
  }

  // ---- the zip writer (PKWARE APPNOTE: local headers, central directory, end record; deflate
  // or stored, CRC-32, no zip64, no encryption). Every entry gets the same fixed time, so the
  // same files make the same bytes (with the same deflater).

  const CRC_TABLE = (() => {
    const t = new Uint32Array(256);
    for (let n = 0; n < 256; ++n) {
      let c = n;
      for (let k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
      t[n] = c >>> 0;
    }
    return t;
  })();

  function crc32(bytes) {
    let c = 0xffffffff;
    for (let i = 0; i < bytes.length; ++i) c = CRC_TABLE[(c ^ bytes[i]) & 0xff] ^ (c >>> 8);
    return (c ^ 0xffffffff) >>> 0;
  }

  const DOS_TIME = 0;                          // 00:00:00
  const DOS_DATE = (0 << 9) | (1 << 5) | 1;    // 1980-01-01, the format's first day
  const UTF8_FLAG = 0x0800;

  /**
   * The bytes (Uint8Array) of a zip of `entries` ([{name, data: Uint8Array}]; names with '/'
   * only, no leading '/'). `deflate(bytes)` gives the raw deflate of bytes (or a promise of it).
   */
  async function writeZip(entries, deflate) {
    const parts = [];
    const centrals = [];
    let offset = 0;
    for (const { name, data } of entries) {
      if (!name || name.startsWith('/') || name.includes('\\') || name.split('/').includes('..'))
        throw new Error(`zip: bad entry name '${name}'`);
      const nameBytes = utf8(name);
      const deflated = await deflate(data);
      const stored = deflated.length >= data.length;  // already compressed (or tiny): store it
      const body = stored ? data : deflated;
      const crc = crc32(data);
      const local = new DataView(new ArrayBuffer(30));
      local.setUint32(0, 0x04034b50, true);
      local.setUint16(4, 20, true);  // version needed: 2.0 (deflate)
      local.setUint16(6, UTF8_FLAG, true);
      local.setUint16(8, stored ? 0 : 8, true);
      local.setUint16(10, DOS_TIME, true);
      local.setUint16(12, DOS_DATE, true);
      local.setUint32(14, crc, true);
      local.setUint32(18, body.length, true);
      local.setUint32(22, data.length, true);
      local.setUint16(26, nameBytes.length, true);
      local.setUint16(28, 0, true);
      const central = new DataView(new ArrayBuffer(46));
      central.setUint32(0, 0x02014b50, true);
      central.setUint16(4, (3 << 8) | 20, true);  // made by: Unix, 2.0
      central.setUint16(6, 20, true);
      central.setUint16(8, UTF8_FLAG, true);
      central.setUint16(10, stored ? 0 : 8, true);
      central.setUint16(12, DOS_TIME, true);
      central.setUint16(14, DOS_DATE, true);
      central.setUint32(16, crc, true);
      central.setUint32(20, body.length, true);
      central.setUint32(24, data.length, true);
      central.setUint16(28, nameBytes.length, true);
      central.setUint32(38, (0o100644 << 16) >>> 0, true);  // a regular file, rw-r--r--
      central.setUint32(42, offset, true);
      parts.push(new Uint8Array(local.buffer), nameBytes, body);
      centrals.push(new Uint8Array(central.buffer), nameBytes);
      offset += 30 + nameBytes.length + body.length;
      if (offset > 0xffffffff) throw new Error('zip: more than 4 GB (no zip64)');
    }
    const dirLength = centrals.reduce((n, c) => n + c.length, 0);
    const end = new DataView(new ArrayBuffer(22));
    end.setUint32(0, 0x06054b50, true);
    end.setUint16(8, entries.length, true);
    end.setUint16(10, entries.length, true);
    end.setUint32(12, dirLength, true);
    end.setUint32(16, offset, true);
    const all = [...parts, ...centrals, new Uint8Array(end.buffer)];
    const out = new Uint8Array(all.reduce((n, p) => n + p.length, 0));
    let at = 0;
    for (const p of all) {
      out.set(p, at);
      at += p.length;
    }
    return out;
  }

  const api = { LAUNCH, ASSIGNMENT, MANIFEST, SITE_LIST, LEFT_OUT, packaged, packageId, launchPage,
                manifest12, manifest2004, packageEntries, zipName, crc32, writeZip };
  if (typeof module === 'object' && module.exports) module.exports = api;
  else global.CSpaceLabScormPackage = api;
})(typeof window !== 'undefined' ? window : globalThis);
