/**
 * The action J = (1/2π)∮p dq of a periodic one-degree-of-freedom orbit,
 * measured from its samples: the area its phase curve encloses, over 2π
 * (Goldstein, *Classical Mechanics*, §10.6; Landau & Lifshitz §49). It is
 * the momentum of the action–angle pair and the adiabatic invariant, and
 * measuring it from a simulation checks a closed form such as the
 * pendulum's (core/analysis/pendulum.ts) without trusting the formula's
 * own algebra.
 *
 * The area is the polygon's through the samples. Each chord cuts off the
 * segment of the curve between its ends, of area h³|ẋ × ẍ|/12 to leading
 * order for a time step h, so the polygon falls short by
 *
 *     ΔJ ≈ (h²/24π) ∮ (q̇ p̈ − ṗ q̈) dt,
 *
 * O(h²): for the harmonic oscillator sampled every θ = ωh of phase,
 * ΔJ/J = 1 − sin θ/θ ≈ θ²/6 exactly; for H = p²/2 + V the integrand is
 * p²V″(q) + V′(q)². The caller who needs the error runs at half the step:
 * the error at h is then 4/3 of the change (Richardson).
 */

/** A return counts only if its other coordinate lies within this fraction of that coordinate's range over the loop from the start. */
const RETURN_TOLERANCE = 0.1;

/**
 * The action J = (1/2π)∮p dq of a periodic 1-DOF orbit sampled at increasing
 * times t (uniform or not), its period, and the number of whole loops it was
 * measured over; null when the samples hold no whole loop (fewer than one
 * period, a rotation whose q grows without returning, a state that never
 * moves, or a sample that is not finite). q must be continuous, not wrapped
 * onto a circle.
 *
 * The loops are counted by the first sample's returns: the crossings of
 * q = q[0] in the direction q left it (the section the phase curve of
 * H = p²/2 + V crosses once each way per loop), placed by linear
 * interpolation between the samples on either side. When the orbit starts
 * at, or near, a turning point of q, where q hardly moves and that section
 * is tangent to the curve, the section is p = p[0] instead: the one of the
 * two coordinates that the first step moves the further, measured in units
 * of that coordinate's range over the samples. A crossing counts as a
 * return only if the other coordinate there lies within a tenth of its
 * range of its starting value; a crossing further away belongs to another
 * part of the curve, or to a rotation (q advanced by a whole turn).
 *
 * ∮p dq is summed on the polygon of samples, Σ(p_i + p_{i+1})/2·(q_{i+1} − q_i),
 * from the first sample to the last return, the last segment cut at the
 * interpolated crossing, and closed by the chord back to the first sample
 * (of zero dq on the q section), which makes the sum the polygon's area, the
 * same wherever the loop is cut. Its absolute value is taken, since the
 * phase curve of H = p²/2 + V runs clockwise (∮p dq > 0) but a time-reversed
 * one does not. It is divided by 2π and by the number of loops; the period
 * is the time from the first sample to the last return over that number.
 * The polygon's error is O(h²) (the module's note).
 */
export function loopAction(q: ArrayLike<number>, p: ArrayLike<number>, t: ArrayLike<number>): { action: number; period: number; loops: number } | null {
  const n = q.length;
  if (p.length !== n || t.length !== n) throw new RangeError(`q, p and t must have one length, not ${q.length}, ${p.length} and ${t.length}`);
  for (let i = 1; i < n; i++) if (!(t[i] > t[i - 1])) throw new RangeError(`the times must increase, but t[${i}] = ${t[i]} follows t[${i - 1}] = ${t[i - 1]}`);
  if (n < 3) return null;
  let [qMin, qMax, pMin, pMax] = [Infinity, -Infinity, Infinity, -Infinity];
  for (let i = 0; i < n; i++) {
    if (!Number.isFinite(q[i]) || !Number.isFinite(p[i]) || !Number.isFinite(t[i])) return null;
    [qMin, qMax, pMin, pMax] = [Math.min(qMin, q[i]), Math.max(qMax, q[i]), Math.min(pMin, p[i]), Math.max(pMax, p[i])];
  }
  if (!(qMax > qMin)) return null;
  // The first sample that has moved from the start.
  let first = 1;
  while (first < n && q[first] === q[0] && p[first] === p[0]) first++;
  if (first === n) return null;
  const qStep = (q[first] - q[0]) / (qMax - qMin);
  const pStep = pMax > pMin ? (p[first] - p[0]) / (pMax - pMin) : 0;
  const onQ = Math.abs(qStep) >= Math.abs(pStep);
  const [section, other] = onQ ? [q, p] : [p, q];
  const direction = Math.sign(onQ ? qStep : pStep);
  const [level, start] = [section[0], other[0]];

  let [otherMin, otherMax] = [start, start];
  let returns = 0;
  let last: { index: number; fraction: number } | null = null;
  for (let i = 1; i < n; i++) {
    [otherMin, otherMax] = [Math.min(otherMin, other[i]), Math.max(otherMax, other[i])];
    const a = direction * (section[i - 1] - level);
    const b = direction * (section[i] - level);
    if (!(a < 0 && b >= 0)) continue;
    const fraction = a / (a - b);
    const crossing = other[i - 1] + fraction * (other[i] - other[i - 1]);
    if (Math.abs(crossing - start) > RETURN_TOLERANCE * (otherMax - otherMin)) continue;
    returns++;
    last = { index: i, fraction };
  }
  if (last === null) return null;

  const { index: j, fraction: f } = last;
  let area = 0;
  for (let i = 0; i + 1 < j; i++) area += ((p[i] + p[i + 1]) / 2) * (q[i + 1] - q[i]);
  const qc = q[j - 1] + f * (q[j] - q[j - 1]);
  const pc = p[j - 1] + f * (p[j] - p[j - 1]);
  area += ((p[j - 1] + pc) / 2) * (qc - q[j - 1]);
  area += ((pc + p[0]) / 2) * (q[0] - qc);
  const tc = t[j - 1] + f * (t[j] - t[j - 1]);
  return { action: Math.abs(area) / (2 * Math.PI * returns), period: (tc - t[0]) / returns, loops: returns };
}
