/**
 * Which sides of a tracked boundary polygon to split: those that have
 * stretched too long to follow the curve, and the two about a vertex where
 * the polygon turns too sharply. Length alone would miss the tips of the
 * filaments a shearing flow draws out, where short sides fold back on each
 * other; turning alone would miss a long straight run that later bends. Both
 * are measured in the units of `scale`, the plot's, so that "too long" and
 * "too sharp" mean what the eye sees.
 */

export interface SplitLimits {
  /** the longest side allowed, in units of scale */
  readonly maxSegment: number;
  /** the largest turn allowed at a vertex, radians, in (0, π) */
  readonly maxTurn: number;
  /** the lengths in q and in p of one unit */
  readonly scale: readonly [number, number];
}

/**
 * Sets split[i] to 1 for each side i (from vertex i to vertex i + 1, the
 * last to vertex 0) of the closed polygon (q_i, p_i), i < n, that is longer
 * than `maxSegment`, or that meets a vertex where the polygon turns through
 * more than `maxTurn`, and to 0 for the others; returns how many are set.
 * Allocates nothing: it runs every frame over thousands of vertices.
 */
export function markSplits(q: ArrayLike<number>, p: ArrayLike<number>, n: number, limits: SplitLimits, split: Uint8Array): number {
  const sq = 1 / limits.scale[0];
  const sp = 1 / limits.scale[1];
  const longest2 = limits.maxSegment * limits.maxSegment;
  // φ > m for φ, m in [0, π] ⟺ sin(φ − m) > 0 ⟺ |a × b| cos m − (a · b) sin m > 0: no square root, no arctangent.
  const cosTurn = Math.cos(limits.maxTurn);
  const sinTurn = Math.sin(limits.maxTurn);
  split.fill(0, 0, n);
  if (n < 2) return 0;
  // The side into vertex i is (aq, ap) in scaled units, the side out of it (bq, bp).
  let aq = (q[0] - q[n - 1]) * sq;
  let ap = (p[0] - p[n - 1]) * sp;
  for (let i = 0; i < n; i++) {
    const next = i + 1 === n ? 0 : i + 1;
    const bq = (q[next] - q[i]) * sq;
    const bp = (p[next] - p[i]) * sp;
    if (bq * bq + bp * bp > longest2) split[i] = 1;
    const cross = aq * bp - ap * bq;
    const dot = aq * bq + ap * bp;
    if (Math.abs(cross) * cosTurn - dot * sinTurn > 0) {
      split[i] = 1;
      split[i === 0 ? n - 1 : i - 1] = 1;
    }
    aq = bq;
    ap = bp;
  }
  let count = 0;
  for (let i = 0; i < n; i++) count += split[i];
  return count;
}
