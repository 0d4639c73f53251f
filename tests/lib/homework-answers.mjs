// Answers to the homework's exercises computed apart from the lab, by brute force from their
// definitions: the CLI, homework, assignment and SCORM tests check the lab's grading against them.

/** P10: the distance on S^1, the least |q2 - q1 + 2 pi k| over the turns k. */
export function s1(q1, q2) {
  let best = Infinity;
  for (let k = -4; k <= 4; ++k) best = Math.min(best, Math.abs(q2 - q1 + 2 * Math.PI * k));
  return best;
}

/**
 * P12: the smallest N whose points t = i/(N-1) on the edge (0,0)-(1,0) land in the closed disk
 * of `center` and `radius` (null when none up to 100000 does).
 */
export function minGrid(center, radius) {
  for (let n = 2; n < 100000; ++n)
    for (let i = 0; i < n; ++i) if (Math.hypot(i / (n - 1) - center[0], center[1]) <= radius) return n;
  return null;
}

/**
 * P9: the share of the unit square in sight from (x1, y1), x1 < 1/2, past a wall at x = 1/2
 * open for a height d in the middle: all of the left half, and of the right half what lies
 * between the rays through the opening's ends, integrated here column by column (midpoints).
 */
export function visibility(x1, y1, d, columns = 200000) {
  const lo = 0.5 - d / 2, hi = 0.5 + d / 2, run = 0.5 - x1;
  const sLo = (lo - y1) / run, sHi = (hi - y1) / run;
  let right = 0;
  for (let i = 0; i < columns; ++i) {
    const x = 0.5 + (i + 0.5) * 0.5 / columns;
    const top = Math.min(1, hi + sHi * (x - 0.5)), bottom = Math.max(0, lo + sLo * (x - 0.5));
    right += Math.max(0, top - bottom) * 0.5 / columns;
  }
  return 0.5 + right;
}
