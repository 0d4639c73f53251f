// A picture as a PNG of at most 256 colours (colour type 3), for the docs' screenshots: the lab's
// flat UI colours survive, anti-aliased edges take the nearest colour kept, and a 1280 x 800
// screenshot of 150 to 290 KB as Chromium writes it (RGB) takes well under 150 KB.
//
// The palette is the mean colour of the 256 most frequent 5-bit-per-channel boxes (the
// "popularity" method: the UI's large areas and every line colour are frequent; boxes of 4 bits
// merged the panel's grey with the white of its radio buttons), each pixel the nearest of them.
import zlib from 'node:zlib';

function chunk(type, data) {
  const head = Buffer.alloc(8);
  head.writeUInt32BE(data.length, 0);
  head.write(type, 4, 'ascii');
  const crc = Buffer.alloc(4);
  crc.writeUInt32BE(zlib.crc32(Buffer.concat([head.subarray(4), data])) >>> 0, 0);
  return Buffer.concat([head, data, crc]);
}

/** The PNG bytes of `rgba` (width * height * 4 bytes, alpha ignored) in at most 256 colours. */
export function palettePng(width, height, rgba) {
  const n = width * height;
  const box = (i) => ((rgba[i * 4] >> 3) << 10) | ((rgba[i * 4 + 1] >> 3) << 5) | (rgba[i * 4 + 2] >> 3);
  const count = new Uint32Array(32768), sum = new Float64Array(32768 * 3);
  for (let i = 0; i < n; ++i) {
    const b = box(i);
    ++count[b];
    for (let c = 0; c < 3; ++c) sum[b * 3 + c] += rgba[i * 4 + c];
  }
  const boxes = [...count.keys()].filter((b) => count[b] > 0).sort((a, b) => count[b] - count[a]).slice(0, 256);
  const palette = boxes.map((b) => [0, 1, 2].map((c) => Math.round(sum[b * 3 + c] / count[b])));
  // Each pixel its nearest palette colour (cached by its exact colour: a screenshot has few).
  const nearest = new Map();
  const indexOf = (r, g, b) => {
    const key = (r << 16) | (g << 8) | b;
    let k = nearest.get(key);
    if (k === undefined) {
      let best = Infinity;
      palette.forEach(([pr, pg, pb], j) => {
        const d = (pr - r) ** 2 + (pg - g) ** 2 + (pb - b) ** 2;
        if (d < best) [best, k] = [d, j];
      });
      nearest.set(key, k);
    }
    return k;
  };
  const raw = Buffer.alloc(height * (width + 1));
  for (let y = 0; y < height; ++y) {
    raw[y * (width + 1)] = 0;  // no filter: indices repeat along a row, which deflate finds
    for (let x = 0; x < width; ++x) {
      const i = y * width + x;
      raw[y * (width + 1) + 1 + x] = indexOf(rgba[i * 4], rgba[i * 4 + 1], rgba[i * 4 + 2]);
    }
  }
  const header = Buffer.alloc(13);
  header.writeUInt32BE(width, 0);
  header.writeUInt32BE(height, 4);
  header.set([8, 3, 0, 0, 0], 8);  // 8 bits, indexed colour, deflate, no filter method, no interlace
  return Buffer.concat([
    Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]),
    chunk('IHDR', header),
    chunk('PLTE', Buffer.from(palette.flat())),
    chunk('IDAT', zlib.deflateSync(raw, { level: 9 })),
    chunk('IEND', Buffer.alloc(0)),
  ]);
}
