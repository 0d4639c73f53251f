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
