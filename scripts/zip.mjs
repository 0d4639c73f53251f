// A small zip writer and reader (PKWARE APPNOTE: local headers, central directory, end record;
// deflate or stored, CRC-32, no zip64, no encryption) for the SCORM packages
// (scripts/scorm-package.mjs) and their tests. node's zlib does the deflating: no dependency.
// The writer itself is web/lab-scorm-package.js's, shared with the page's Author view.
import zlib from 'node:zlib';
import { createRequire } from 'node:module';

const P = createRequire(import.meta.url)('../web/lab-scorm-package.js');

export const crc32 = P.crc32;

/**
 * A promise of the bytes (Buffer) of a zip of `entries` ([{name, data}]; names with '/' only, no
 * leading '/'), deflated by node's zlib at level 9: web/lab-scorm-package.js's writer, which the
 * page's Author view runs with the browser's deflater.
 */
export async function writeZip(entries) {
  return Buffer.from(await P.writeZip(entries, (data) => zlib.deflateRawSync(data, { level: 9 })));
}

/** The entries of a zip ([{name, data}]) from its central directory; checks each CRC-32. */
export function readZip(zip) {
  const endAt = zip.lastIndexOf(Buffer.from([0x50, 0x4b, 0x05, 0x06]));
  if (endAt < 0) throw new Error('zip: no end of central directory');
  const count = zip.readUInt16LE(endAt + 10);
  let at = zip.readUInt32LE(endAt + 16);
  const out = [];
  for (let i = 0; i < count; ++i) {
    if (zip.readUInt32LE(at) !== 0x02014b50) throw new Error('zip: bad central directory');
    const method = zip.readUInt16LE(at + 10);
    const crc = zip.readUInt32LE(at + 16);
    const size = zip.readUInt32LE(at + 20);
    const nameLength = zip.readUInt16LE(at + 28);
    const extra = zip.readUInt16LE(at + 30) + zip.readUInt16LE(at + 32);
    const local = zip.readUInt32LE(at + 42);
    const name = zip.toString('utf8', at + 46, at + 46 + nameLength);
    const bodyAt = local + 30 + zip.readUInt16LE(local + 26) + zip.readUInt16LE(local + 28);
    const body = zip.subarray(bodyAt, bodyAt + size);
    const data = method === 8 ? zlib.inflateRawSync(body) : method === 0 ? Buffer.from(body) : null;
    if (!data) throw new Error(`zip: ${name}: unknown method ${method}`);
    if (crc32(data) !== crc) throw new Error(`zip: ${name}: CRC mismatch`);
    out.push({ name, data });
    at += 46 + nameLength + extra;
  }
  return out;
}
