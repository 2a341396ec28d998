/**
 * The adaptive method: Dormand & Prince's embedded Runge–Kutta pair 5(4)
 * (Dormand & Prince 1980, "A family of embedded Runge–Kutta formulae",
 * J. Comput. Appl. Math. 6, 19–26) with step-size control and the
 * 4th-order continuous extension of Hairer's DOPRI5 (Hairer, Nørsett &
 * Wanner, *Solving ODEs I*, 2nd ed., §II.4–II.6, Table 5.2 and eq. (6.12);
 * coefficients as in dopri5.f).
 *
 * Written here rather than taken from a package: odex (Hairer's ODEX, which
 * Emmy uses) integrates in one call from start to end and cannot be
 * resumed, and a run here is cut into chunks — frames on the page, paced
 * stretches in the CLI — whose cuts must not change the numbers, or
 * `phasebook reproduce` could not match a file bit for bit. This stepper
 * carries its internal step (time, state, step size, last slope) from one
 * call to the next, and samples the times t0 + k·dt from the dense output,
 * so the samples are the same however the run is cut.
 *
 * In the Stepper interface `dt` is therefore the spacing of the samples,
 * not a step: the method picks its own steps.
 */
import { InputError } from '../errors.ts';
import type { Stepper, VectorField } from '../types.ts';

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

/** Where one trajectory's integration stands between two calls. */
interface Continuation {
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

/** Continuations kept, at least; enough for a worker's batch. */
const KEPT = 1024;

export function dormandPrince(field: VectorField, dim: number, tolerances: Tolerances): Stepper & { stats: AdaptiveStats } {
  const { rtol, atol } = tolerances;
  const k2 = new Float64Array(dim), k3 = new Float64Array(dim), k4 = new Float64Array(dim);
  const k5 = new Float64Array(dim), k6 = new Float64Array(dim), k7 = new Float64Array(dim);
  const stage = new Float64Array(dim), next = new Float64Array(dim);
  const stats: AdaptiveStats = { accepted: 0, rejected: 0, evaluations: 0 };
  const kept = new Map<string, Continuation[]>();
  let keptCount = 0;

  const keyOf = (t0: number, dt: number, k: number, x: Float64Array, o: number) => `${t0}|${dt}|${k}|${x[o]}|${x[o + dim - 1]}`;

  function evaluate(t: number, y: Float64Array, out: Float64Array): void {
    stats.evaluations++;
    field(t, y, out);
  }

  /** The weighted RMS norm of `v` against the scale of y and y'. */
  function norm(v: Float64Array, y: Float64Array, z: Float64Array): number {
    let sum = 0;
    for (let i = 0; i < dim; i++) {
      const scale = atol + rtol * Math.max(Math.abs(y[i]), Math.abs(z[i]));
      const r = v[i] / scale;
      sum += r * r;
    }
    return Math.sqrt(sum / dim);
  }

  /** The first step size (Hairer's HINIT, HNW §II.4, p. 169), for a method of order 5. */
  function initialStep(c: Continuation): number {
    const { t, y, f } = c;
    const d0 = norm(y, y, y);
    const d1 = norm(f, y, y);
    const h0 = d0 < 1e-5 || d1 < 1e-5 ? 1e-6 : (0.01 * d0) / d1;
    for (let i = 0; i < dim; i++) stage[i] = y[i] + h0 * f[i];
    evaluate(t + h0, stage, k2);
    for (let i = 0; i < dim; i++) k3[i] = (k2[i] - f[i]) / h0;
    const d2 = norm(k3, y, y);
    const most = Math.max(d1, d2);
    const h1 = most <= 1e-15 ? Math.max(1e-6, h0 * 1e-3) : Math.pow(0.01 / most, 1 / 5);
    return Math.min(100 * h0, h1);
  }

  /** One accepted step from c.t, retrying smaller steps until the error is within tolerance. */
  function step(c: Continuation): void {
    const { y, f, dense } = c;
    let h = c.h;
    for (;;) {
      const t = c.t;
      if (!(h > 8 * Number.EPSILON * Math.max(1, Math.abs(t)))) {
        throw new InputError(`the adaptive method's step fell to ${h.toPrecision(3)} at t = ${t}: the motion is singular there, or rtol ${rtol} and atol ${atol} ask too much`);
      }
      for (let i = 0; i < dim; i++) stage[i] = y[i] + h * A21 * f[i];
      evaluate(t + C2 * h, stage, k2);
      for (let i = 0; i < dim; i++) stage[i] = y[i] + h * (A31 * f[i] + A32 * k2[i]);
      evaluate(t + C3 * h, stage, k3);
      for (let i = 0; i < dim; i++) stage[i] = y[i] + h * (A41 * f[i] + A42 * k2[i] + A43 * k3[i]);
      evaluate(t + C4 * h, stage, k4);
      for (let i = 0; i < dim; i++) stage[i] = y[i] + h * (A51 * f[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i]);
      evaluate(t + C5 * h, stage, k5);
      for (let i = 0; i < dim; i++) stage[i] = y[i] + h * (A61 * f[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i]);
      const tNew = t + h;
      evaluate(tNew, stage, k6);
      for (let i = 0; i < dim; i++) next[i] = y[i] + h * (A71 * f[i] + A73 * k3[i] + A74 * k4[i] + A75 * k5[i] + A76 * k6[i]);
      // First same as last: k7 is the next step's first slope.
      evaluate(tNew, next, k7);
      for (let i = 0; i < dim; i++) stage[i] = h * (E1 * f[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
      const error = norm(stage, y, next);
      if (error <= 1) {
        // Dense output coefficients before y and f are overwritten (dopri5.f, contd5).
        for (let i = 0; i < dim; i++) {
          const difference = next[i] - y[i];
          const b = h * f[i] - difference;
          dense[i] = y[i];
          dense[dim + i] = difference;
          dense[2 * dim + i] = b;
          dense[3 * dim + i] = difference - h * k7[i] - b;
          dense[4 * dim + i] = h * (D1 * f[i] + D3 * k3[i] + D4 * k4[i] + D5 * k5[i] + D6 * k6[i] + D7 * k7[i]);
        }
        c.tOld = t;
        c.hOld = h;
        c.t = tNew;
        y.set(next);
        f.set(k7);
        const grow = error === 0 ? GROW_MOST : Math.min(GROW_MOST, Math.max(SHRINK_MOST, SAFETY * Math.pow(error, -1 / 5)));
        c.h = h * grow;
        stats.accepted++;
        return;
      }
      stats.rejected++;
      // A non-finite error (the trial state overflowed) shrinks the step as much as allowed.
      const shrink = Number.isFinite(error) ? Math.max(SHRINK_MOST, SAFETY * Math.pow(error, -1 / 5)) : SHRINK_MOST;
      h *= Math.min(1, shrink);
    }
  }

  /** The state at time T in the last step's interval, into x at offset o. */
  function sampleAt(c: Continuation, T: number, x: Float64Array, o: number): void {
    if (T === c.t) {
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

  function resume(x: Float64Array, o: number, t0: number, dt: number, k0: number): Continuation | undefined {
    const key = keyOf(t0, dt, k0, x, o);
    const list = kept.get(key);
    if (!list) return undefined;
    const at = list.findIndex((c) => c.sample.every((v, i) => v === x[o + i]));
    if (at < 0) return undefined;
    const [c] = list.splice(at, 1);
    if (list.length === 0) kept.delete(key);
    keptCount--;
    return c;
  }

  function keep(c: Continuation, x: Float64Array, o: number): void {
    c.sample.set(x.subarray(o, o + dim));
    const key = keyOf(c.t0, c.dt, c.k, x, o);
    const list = kept.get(key);
    if (list) list.push(c);
    else kept.set(key, [c]);
    keptCount++;
    // The oldest go first: a trajectory not continued for this long has been restarted or dropped.
    while (keptCount > KEPT) {
      const [oldest, entries] = kept.entries().next().value as [string, Continuation[]];
      entries.shift();
      if (entries.length === 0) kept.delete(oldest);
      keptCount--;
    }
  }

  function start(x: Float64Array, o: number, t0: number, dt: number, k0: number): Continuation {
    const t = t0 + k0 * dt;
    const y = Float64Array.from(x.subarray(o, o + dim));
    const f = new Float64Array(dim);
    evaluate(t, y, f);
    const c: Continuation = { t0, dt, k: k0, sample: new Float64Array(dim), t, y, f, h: 0, tOld: t, hOld: 0, dense: new Float64Array(5 * dim) };
    c.h = initialStep(c);
    return c;
  }

  function advance(x: Float64Array, count: number, _params: Float64Array, t0: number, k0: number, dt: number, steps: number): number {
    for (let m = 0; m < count; m++) {
      const o = m * dim;
      const c = resume(x, o, t0, dt, k0) ?? start(x, o, t0, dt, k0);
      for (let k = 0; k < steps; k++) {
        const T = t0 + (k0 + k + 1) * dt;
        while (c.t < T) step(c);
        sampleAt(c, T, x, o);
        let sum = 0;
        for (let i = 0; i < dim; i++) sum += x[o + i];
        // NaN or ±∞ anywhere makes the sum minus itself non-zero.
        if (sum - sum !== 0) return k;
      }
      c.k = k0 + steps;
      keep(c, x, o);
    }
    return steps;
  }

  return { dim, advance, stats };
}
