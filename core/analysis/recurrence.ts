/**
 * Poincaré recurrence, measured on a rotation of the circle: the section of
 * two uncoupled oscillators, taken once a period of the first, finds the
 * second's phase turned by α = ω₂/ω₁ (mod 1) each time, θ_n = θ₀ + nα. An
 * orbit of a flow that keeps a finite volume comes back as close to its
 * start as one likes (Poincaré 1890); how often is Kac's lemma (Kac 1947):
 * for an ergodic measure-preserving map, the mean time to return to a set
 * A is 1/μ(A). The rotation by an irrational α is ergodic, so returns to an
 * arc of ε turns come every 1/ε crossings on average.
 *
 * A finite run's error in that mean is bounded by the Denjoy–Koksma
 * inequality (Herman 1979; Kuipers & Niederreiter, *Uniform Distribution of
 * Sequences*, ch. 1 §3 and ch. 2 §5): over q_k steps, q_k a denominator of
 * α's convergents, the visits of a rotation to an arc differ from q_k·ε by
 * at most the variation of the arc's indicator, 2; any T is a sum of such
 * blocks by Ostrowski's expansion T = Σ b_k q_k, so over T steps the count
 * is off by at most 2 Σ b_k.
 */

/** The partial quotients [a₀; a₁, a₂, …] of x's continued fraction, up to `most` of them or until the remainder is rounding. */
export function continuedFraction(x: number, most = 40): number[] {
  const out: number[] = [];
  let r = x;
  for (let k = 0; k < most; k++) {
    // Each inversion amplifies the remainder's rounding: within 1e-9 of a whole number, the fraction has ended.
    const whole = Math.round(r);
    if (Math.abs(r - whole) < 1e-9) {
      out.push(whole);
      break;
    }
    const a = Math.floor(r);
    out.push(a);
    const rest = r - a;
    r = 1 / rest;
  }
  return out;
}

/** The denominators q_k of α's convergents (q₀ = 1, q₁ = a₁, q_k = a_k q_{k−1} + q_{k−2}), up to the first beyond `limit`. */
export function convergentDenominators(alpha: number, limit: number): number[] {
  const a = continuedFraction(alpha);
  const q = [1];
  let [previous, current] = [0, 1];
  for (let k = 1; k < a.length && current <= limit; k++) {
    [previous, current] = [current, a[k] * current + previous];
    q.push(current);
  }
  return q;
}

/** Σ b_k of Ostrowski's expansion T = Σ b_k q_k, taken greedily from the largest q_k ≤ T. */
export function ostrowskiDigitSum(T: number, denominators: readonly number[]): number {
  let rest = Math.floor(T);
  let sum = 0;
  for (let k = denominators.length - 1; k >= 0 && rest > 0; k--) {
    const b = Math.floor(rest / denominators[k]);
    sum += b;
    rest -= b * denominators[k];
  }
  return sum;
}

/** The Denjoy–Koksma bound on |visits − εT| for an arc of any width, over T steps of the rotation by α. */
export function arcVisitBound(alpha: number, T: number): number {
  return 2 * ostrowskiDigitSum(T, convergentDenominators(alpha - Math.floor(alpha), T));
}

/** The distance between two phases in turns, on the circle: 0 to 1/2. */
export function turnDistance(a: number, b: number): number {
  const d = Math.abs(a - b) % 1;
  return Math.min(d, 1 - d);
}

export interface ArcReturns {
  /** the crossings n at which the phase lay in the arc, the start (n = 0) first */
  visits: number[];
  /** the number of returns: visits after the start */
  returns: number;
  /** the mean time between successive visits, in crossings; NaN with no return */
  mean: number;
  /** the crossings from the start to the last return */
  span: number;
}

/** Visits of the phases θ_n (in turns) to the arc of `width` turns centred on θ₀. */
export function arcReturns(phases: ArrayLike<number>, width: number): ArcReturns {
  const visits: number[] = [];
  for (let n = 0; n < phases.length; n++) if (turnDistance(phases[n], phases[0]) < width / 2) visits.push(n);
  const returns = visits.length - 1;
  const span = returns > 0 ? visits[returns] - visits[0] : 0;
  return { visits, returns, mean: returns > 0 ? span / returns : NaN, span };
}

/** The crossings at which the phase came closer to θ₀ than ever before: Poincaré's returns, ever closer. */
export function recordReturns(phases: ArrayLike<number>): { n: number; distance: number }[] {
  const out: { n: number; distance: number }[] = [];
  let closest = Infinity;
  for (let n = 1; n < phases.length; n++) {
    const d = turnDistance(phases[n], phases[0]);
    if (d < closest) {
      closest = d;
      out.push({ n, distance: d });
    }
  }
  return out;
}

/** Whether the rotation by α is periodic within T steps: α a fraction whose denominator is at most T. */
export function periodicWithin(alpha: number, T: number): boolean {
  const a = continuedFraction(alpha - Math.floor(alpha));
  // The expansion ended before its 40 terms: a fraction, within rounding, with the last denominator its own.
  return a.length < 40 && convergentDenominators(alpha - Math.floor(alpha), Infinity).at(-1)! <= T;
}

export interface KacMeasurement extends ArcReturns {
  /** the Denjoy–Koksma bound on |returns − εT| over the span */
  visitBound: number;
  /** the largest difference of the phases from those of a run at half the step, times 16/15 (RK 3/8's Richardson) */
  phaseError: number;
  /** crossings whose phase lies within twice phaseError of the arc's ends, where the integration could move a visit in or out */
  ambiguous: number;
  /** the largest departure of a crossing's turn from α: 0 for a rotation of the circle */
  rotationSpread: number;
  /** α is a fraction with a denominator within the run */
  periodic: boolean;
}

/**
 * What Kac's check needs from a section's phases θ_n (turns), the same
 * phases from a run at half the step, the turn α a crossing should make
 * and the arc's width ε: the returns and their mean, the Denjoy–Koksma
 * bound on the count, the phases' integration error, and the two premises
 * (the motion is a rotation by α, and α is no fraction within the run).
 */
export function kacMeasurement(phases: ArrayLike<number>, halfStep: ArrayLike<number>, alpha: number, width: number): KacMeasurement {
  const r = arcReturns(phases, width);
  let phaseError = 0;
  for (let n = 0; n < Math.min(phases.length, halfStep.length); n++) phaseError = Math.max(phaseError, turnDistance(phases[n], halfStep[n]));
  phaseError *= 16 / 15;
  // The start's own error moves the arc's centre as much as the error moves a phase: twice the error from its ends.
  let ambiguous = 0;
  for (let n = 1; n < phases.length; n++) if (Math.abs(turnDistance(phases[n], phases[0]) - width / 2) <= 2 * phaseError) ambiguous++;
  let rotationSpread = 0;
  for (let n = 1; n < phases.length; n++) rotationSpread = Math.max(rotationSpread, turnDistance(phases[n] - phases[n - 1], alpha));
  return {
    ...r,
    visitBound: arcVisitBound(alpha, r.span),
    phaseError,
    ambiguous,
    rotationSpread,
    periodic: periodicWithin(alpha, Math.max(1, r.span)),
  };
}
