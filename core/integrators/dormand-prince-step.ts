/**
 * One step of Dormand & Prince's embedded pair 5(4) with its error control
 * and its dense output (Hairer, Nørsett & Wanner, *Solving ODEs I*, 2nd ed.,
 * §II.4–II.6, Table 5.2 and eq. (6.12); coefficients as in dopri5.f), cut
 * into its stages: the trial step, the local error estimate, the step-size
 * controller, the dense output's coefficients, and a sample from them.
 *
 * Every array a step touches is allocated once per stepper (`Stages`) or per
 * trajectory (`Continuation`), so a step allocates nothing.
 */
import { InputError } from '../errors.ts';
import type { VectorField } from '../types.ts';

// Nodes and weights (Hairer, Nørsett & Wanner, Table 5.2).
const C2 = 1 / 5, C3 = 3 / 10, C4 = 4 / 5, C5 = 8 / 9;
const A21 = 1 / 5;
const A31 = 3 / 40, A32 = 9 / 40;
const A41 = 44 / 45, A42 = -56 / 15, A43 = 32 / 9;
const A51 = 19372 / 6561, A52 = -25360 / 2187, A53 = 64448 / 6561, A54 = -212 / 729;
const A61 = 9017 / 3168, A62 = -355 / 33, A63 = 46732 / 5247, A64 = 49 / 176, A65 = -5103 / 18656;
const A71 = 35 / 384, A73 = 500 / 1113, A74 = 125 / 192, A75 = -2187 / 6784, A76 = 11 / 84;
// The 5th-order weights minus the embedded 4th-order ones: the local error estimate.
const E1 = 71 / 57600, E3 = -71 / 16695, E4 = 71 / 1920, E5 = -17253 / 339200, E6 = 22 / 525, E7 = -1 / 40;
// The continuous extension's last coefficient (dopri5.f, d1…d7).
const D1 = -12715105075 / 11282082432, D3 = 87487479700 / 32700410799, D4 = -10690763975 / 1880347072;
const D5 = 701980252875 / 199316789632, D6 = -1453857185 / 822651844, D7 = 69997945 / 29380423;

/** Step-size controller (HNW §II.4): safety factor, and the bounds of one change. */
const SAFETY = 0.9, SHRINK_MOST = 0.2, GROW_MOST = 10;

export interface Tolerances {
  rtol: number;
  atol: number;
}

/** Counts of the work done, for the bench and the tests. */
export interface AdaptiveStats {
  accepted: number;
  rejected: number;
  evaluations: number;
}

/** Where one trajectory's integration stands: its internal step, carried from one call of the stepper to the next. */
export interface Continuation {
  t0: number;
  dt: number;
  /** the sample number the next call starts from */
  k: number;
  /** the sample written to the caller's state, to recognise the same trajectory */
  sample: Float64Array;
  /** internal time, state, slope there, and next step size */
  t: number;
  y: Float64Array;
  f: Float64Array;
  h: number;
  /** the last step's interval and dense-output coefficients, 5 blocks of dim */
  tOld: number;
  hOld: number;
  dense: Float64Array;
}

/** A stepper's field, tolerances, counters, and the slopes and trial states of a step (k1 is the continuation's f). */
export interface Stages extends Tolerances {
  readonly field: VectorField;
  readonly dim: number;
  readonly stats: AdaptiveStats;
  readonly k2: Float64Array;
  readonly k3: Float64Array;
  readonly k4: Float64Array;
  readonly k5: Float64Array;
  readonly k6: Float64Array;
  readonly k7: Float64Array;
  /** a stage's state, and then the error estimate */
  readonly stage: Float64Array;
  /** the trial step's 5th-order solution */
  readonly next: Float64Array;
}

export function newStages(field: VectorField, dim: number, { rtol, atol }: Tolerances): Stages {
  const buffer = () => new Float64Array(dim);
  const stats: AdaptiveStats = { accepted: 0, rejected: 0, evaluations: 0 };
  return { field, dim, rtol, atol, stats, k2: buffer(), k3: buffer(), k4: buffer(), k5: buffer(), k6: buffer(), k7: buffer(), stage: buffer(), next: buffer() };
}

/** The field at (t, y) into `out`, counted. */
function evaluate(s: Stages, t: number, y: Float64Array, out: Float64Array): void {
  s.stats.evaluations++;
  // Called as a plain function, as before: a reader's vector field sees no `this`.
  const field = s.field;
  field(t, y, out);
}

/** The weighted RMS norm of `v` against the scale of y and z (HNW §II.4, eq. 4.11): 1 is the tolerance. */
function norm(s: Stages, v: Float64Array, y: Float64Array, z: Float64Array): number {
  const { dim, rtol, atol } = s;
  let sum = 0;
  for (let i = 0; i < dim; i++) {
    const scale = atol + rtol * Math.max(Math.abs(y[i]), Math.abs(z[i]));
    const r = v[i] / scale;
    sum += r * r;
  }
  return Math.sqrt(sum / dim);
}

/** A new trajectory's continuation at sample k0 of t0 + k·dt, from x[o…o+dim), with its slope and first step size. */
export function startContinuation(s: Stages, x: Float64Array, o: number, t0: number, dt: number, k0: number): Continuation {
  const { dim } = s;
  const t = t0 + k0 * dt;
  const y = Float64Array.from(x.subarray(o, o + dim));
  const f = new Float64Array(dim);
  evaluate(s, t, y, f);
  const c: Continuation = { t0, dt, k: k0, sample: new Float64Array(dim), t, y, f, h: 0, tOld: t, hOld: 0, dense: new Float64Array(5 * dim) };
  c.h = initialStep(s, c);
  return c;
}

/**
 * The first step size (Hairer's HINIT, HNW §II.4, p. 169), for a method of
 * order 5: a step whose Euler error would be 1 % of the state, then one
 * whose 5th-order term is the tolerance by a difference estimate of y''.
 */
function initialStep(s: Stages, c: Continuation): number {
  const { dim, stage, k2, k3 } = s;
  const { t, y, f } = c;
  const d0 = norm(s, y, y, y);
  const d1 = norm(s, f, y, y);
  const h0 = d0 < 1e-5 || d1 < 1e-5 ? 1e-6 : (0.01 * d0) / d1;
  for (let i = 0; i < dim; i++) stage[i] = y[i] + h0 * f[i];
  evaluate(s, t + h0, stage, k2);
  for (let i = 0; i < dim; i++) k3[i] = (k2[i] - f[i]) / h0;
  const d2 = norm(s, k3, y, y);
  const most = Math.max(d1, d2);
  const h1 = most <= 1e-15 ? Math.max(1e-6, h0 * 1e-3) : Math.pow(0.01 / most, 1 / 5);
  return Math.min(100 * h0, h1);
}

/**
 * One accepted step from c.t: trial steps, each smaller than the last,
 * until the local error is within tolerance; then the step is taken and the
 * next one sized from its error.
 */
export function acceptedStep(s: Stages, c: Continuation): void {
  let h = c.h;
  for (;;) {
    refuseVanishingStep(s, h, c.t);
    trialStep(s, c, h);
    const error = localError(s, c, h);
    if (error <= 1) return accept(s, c, h, error);
    s.stats.rejected++;
    h *= Math.min(1, shrinkFactor(error));
  }
}

/** A step lost in the rounding of t cannot make progress: the motion is singular there, or the tolerances ask too much. */
function refuseVanishingStep(s: Stages, h: number, t: number): void {
  if (!(h > 8 * Number.EPSILON * Math.max(1, Math.abs(t)))) {
    throw new InputError(`the adaptive method's step fell to ${h.toPrecision(3)} at t = ${t}: the motion is singular there, or rtol ${s.rtol} and atol ${s.atol} ask too much`);
  }
}

/** The stages k2…k7 of a step of size h from c: its 5th-order solution in s.next, and the slope there in k7. */
function trialStep(s: Stages, c: Continuation, h: number): void {
  const { dim, stage, next, k2, k3, k4, k5, k6, k7 } = s;
  const { t, y, f } = c;
  for (let i = 0; i < dim; i++) stage[i] = y[i] + h * A21 * f[i];
  evaluate(s, t + C2 * h, stage, k2);
  for (let i = 0; i < dim; i++) stage[i] = y[i] + h * (A31 * f[i] + A32 * k2[i]);
  evaluate(s, t + C3 * h, stage, k3);
  for (let i = 0; i < dim; i++) stage[i] = y[i] + h * (A41 * f[i] + A42 * k2[i] + A43 * k3[i]);
  evaluate(s, t + C4 * h, stage, k4);
  for (let i = 0; i < dim; i++) stage[i] = y[i] + h * (A51 * f[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i]);
  evaluate(s, t + C5 * h, stage, k5);
  for (let i = 0; i < dim; i++) stage[i] = y[i] + h * (A61 * f[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i]);
  const tNew = t + h;
  evaluate(s, tNew, stage, k6);
  for (let i = 0; i < dim; i++) next[i] = y[i] + h * (A71 * f[i] + A73 * k3[i] + A74 * k4[i] + A75 * k5[i] + A76 * k6[i]);
  // First same as last: k7 is the next step's first slope.
  evaluate(s, tNew, next, k7);
}

/** The trial step's local error: the difference of the 5th- and 4th-order solutions, in units of the tolerance. */
function localError(s: Stages, c: Continuation, h: number): number {
  const { dim, stage, next, k3, k4, k5, k6, k7 } = s;
  const f = c.f;
  for (let i = 0; i < dim; i++) stage[i] = h * (E1 * f[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
  return norm(s, stage, c.y, next);
}

/** Takes the trial step into c, its dense output kept for the samples inside it, and sizes the next from its error. */
function accept(s: Stages, c: Continuation, h: number, error: number): void {
  // Dense output coefficients before y and f are overwritten.
  keepDenseOutput(s, c, h);
  c.tOld = c.t;
  c.hOld = h;
  c.t = c.t + h;
  c.y.set(s.next);
  c.f.set(s.k7);
  c.h = h * growFactor(error);
  s.stats.accepted++;
}

/** The continuous extension's coefficients over the step just tried (dopri5.f, contd5), 5 blocks of dim in c.dense. */
function keepDenseOutput(s: Stages, c: Continuation, h: number): void {
  const { dim, next, k3, k4, k5, k6, k7 } = s;
  const { y, f, dense } = c;
  for (let i = 0; i < dim; i++) {
    const difference = next[i] - y[i];
    const b = h * f[i] - difference;
    dense[i] = y[i];
    dense[dim + i] = difference;
    dense[2 * dim + i] = b;
    dense[3 * dim + i] = difference - h * k7[i] - b;
    dense[4 * dim + i] = h * (D1 * f[i] + D3 * k3[i] + D4 * k4[i] + D5 * k5[i] + D6 * k6[i] + D7 * k7[i]);
  }
}

/** After an accepted step: the next step's size over this one's, from the error's 5th root, bounded both ways. */
function growFactor(error: number): number {
  return error === 0 ? GROW_MOST : Math.min(GROW_MOST, Math.max(SHRINK_MOST, SAFETY * Math.pow(error, -1 / 5)));
}

/** After a rejected step: the retry's size over this one's. A non-finite error (the trial state overflowed) shrinks it as much as allowed. */
function shrinkFactor(error: number): number {
  return Number.isFinite(error) ? Math.max(SHRINK_MOST, SAFETY * Math.pow(error, -1 / 5)) : SHRINK_MOST;
}

/** The state (dim components) at time T in the last accepted step's interval, from its dense output, into x at offset o. */
export function denseSample(c: Continuation, T: number, x: Float64Array, o: number, dim: number): void {
  if (T === c.t) {
    // The step's end is the state itself, not the interpolant's rounding of it.
    for (let i = 0; i < dim; i++) x[o + i] = c.y[i];
    return;
  }
  const s = (T - c.tOld) / c.hOld;
  const s1 = 1 - s;
  const d = c.dense;
  for (let i = 0; i < dim; i++) {
    x[o + i] = d[i] + s * (d[dim + i] + s1 * (d[2 * dim + i] + s * (d[3 * dim + i] + s1 * d[4 * dim + i])));
  }
}
