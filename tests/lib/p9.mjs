// P9's visible area in the right half, computed apart from the lab: the square's right half
// clipped to the wedge between the lines from (x1, y1) through the opening's ends (1/2, 1/2 -+
// gap/2), its area by the shoelace formula. The CLI and browser tests check the lab against it.
export function p9RightArea(x1, y1, gap) {
  let poly = [[0.5, 0], [1, 0], [1, 1], [0.5, 1]];
  const clip = (through, sign) => {
    const side = ([x, y]) => sign * ((through[0] - x1) * (y - y1) - (through[1] - y1) * (x - x1));
    const out = [];
    poly.forEach((a, i) => {
      const b = poly[(i + 1) % poly.length], sa = side(a), sb = side(b);
      if (sa >= 0) out.push(a);
      if (sa * sb < 0) out.push([a[0] + sa / (sa - sb) * (b[0] - a[0]), a[1] + sa / (sa - sb) * (b[1] - a[1])]);
    });
    poly = out;
  };
  clip([0.5, 0.5 + gap / 2], -1);
  clip([0.5, 0.5 - gap / 2], 1);
  let twice = 0;
  poly.forEach((a, i) => { const b = poly[(i + 1) % poly.length]; twice += a[0] * b[1] - b[0] * a[1]; });
  return Math.abs(twice) / 2;
}
