/**
 * The implicit midpoint rule
 *
 *     x₁ = x₀ + h·f(t₀ + h/2, (x₀ + x₁)/2),
 *
 * symplectic for every Hamiltonian (Hairer, Lubich & Wanner, *Geometric
 * Numerical Integration*, 2nd ed., Thm VI.3.5 and §VI.4), of order 2. It is
 * solved for the midpoint Y = (x₀ + x₁)/2, the root of
 * G(Y) = Y − x₀ − (h/2)·f(t½, Y), by Newton's method with G' = I − (h/2)·J,
 * J = ∂f/∂x: exact second derivatives of H on the expression route
 * (expression/jacobian.ts), central differences of f otherwise.
 */
import { InputError } from '../errors.ts';
import type { Stepper, VectorField } from '../types.ts';
import { solveInPlace } from './linear-solve.ts';

/** Writes ∂f/∂x at (t, x), row-major dim×dim, into `out`; entries it never writes stay 0. */
export type JacobianFunction = (t: number, x: Float64Array, out: Float64Array) => void;

/** Newton iterations before a step is given up: quadratic convergence needs 3 or 4 from the explicit guess. */
const MOST_ITERATIONS = 30;
/**
 * Newton stops once a correction is below this, relative to the state: the
 * error left is then about the square of it (quadratic convergence), far
 * below rounding; with a finite-difference Jacobian the convergence is
 * linear with a ratio of about 1e-8·h‖J‖, and the same bound leaves ~1e-18.
 */
const CORRECTION = 1e-10;

/** ∂f/∂x by central differences of f, with steps ε^(1/3)·max(1, |x_j|): error O(1e-10) relative, enough for Newton. */
export function differenceJacobian(field: VectorField, dim: number): JacobianFunction {
  const y = new Float64Array(dim);
  const plus = new Float64Array(dim);
  const minus = new Float64Array(dim);
  const relative = Math.cbrt(Number.EPSILON);
  return (t, x, out) => {
    y.set(x);
    for (let j = 0; j < dim; j++) {
      const xj = x[j];
      const h = xj + relative * Math.max(1, Math.abs(xj)) - xj;
      y[j] = xj + h;
      field(t, y, plus);
      y[j] = xj - h;
      field(t, y, minus);
      y[j] = xj;
      for (let i = 0; i < dim; i++) out[i * dim + j] = (plus[i] - minus[i]) / (2 * h);
    }
  };
}

export interface MidpointStats {
  steps: number;
  iterations: number;
}

export function implicitMidpoint(field: VectorField, jacobian: JacobianFunction, dim: number): Stepper & { stats: MidpointStats } {
  const x0 = new Float64Array(dim);
  const mid = new Float64Array(dim);
  const f = new Float64Array(dim);
  const correction = new Float64Array(dim);
  const jac = new Float64Array(dim * dim);
  const matrix = new Float64Array(dim * dim);
  const stats: MidpointStats = { steps: 0, iterations: 0 };

  /** Newton for the midpoint of one step from x0; false when it fails to converge. */
  function solveMidpoint(tMid: number, half: number): boolean {
    // The explicit Euler half step is the first guess: its error is O(h²).
    field(tMid - half, x0, f);
    for (let i = 0; i < dim; i++) mid[i] = x0[i] + half * f[i];
    for (let iteration = 0; iteration < MOST_ITERATIONS; iteration++) {
      stats.iterations++;
      field(tMid, mid, f);
      jacobian(tMid, mid, jac);
      for (let i = 0; i < dim; i++) correction[i] = -(mid[i] - x0[i] - half * f[i]);
      for (let e = 0; e < dim * dim; e++) matrix[e] = -half * jac[e];
      for (let i = 0; i < dim; i++) matrix[i * dim + i] += 1;
      if (!solveInPlace(matrix, correction, dim)) return false;
      let size = 0;
      let scale = 1;
      for (let i = 0; i < dim; i++) {
        mid[i] += correction[i];
        size = Math.max(size, Math.abs(correction[i]));
        scale = Math.max(scale, Math.abs(mid[i]));
      }
      if (!Number.isFinite(size)) return false;
      if (size <= CORRECTION * scale) return true;
    }
    return false;
  }

  function advance(x: Float64Array, count: number, _params: Float64Array, t0: number, k0: number, dt: number, steps: number): number {
    const half = dt / 2;
    for (let m = 0; m < count; m++) {
      const o = m * dim;
      for (let i = 0; i < dim; i++) x0[i] = x[o + i];
      for (let k = 0; k < steps; k++) {
        const t = t0 + (k0 + k) * dt;
        if (!solveMidpoint(t + half, half)) {
          let finite = true;
          for (let i = 0; i < dim; i++) finite &&= Number.isFinite(mid[i]) && Number.isFinite(f[i]);
          if (!finite) {
            // The motion left the numbers: reported as a blow-up, like the explicit methods'.
            for (let i = 0; i < dim; i++) x[o + i] = NaN;
            return k;
          }
          throw new InputError(`the implicit midpoint rule's Newton iteration did not converge in the step from t = ${t}: take a smaller dt`);
        }
        for (let i = 0; i < dim; i++) x0[i] = 2 * mid[i] - x0[i];
        stats.steps++;
      }
      for (let i = 0; i < dim; i++) x[o + i] = x0[i];
    }
    return steps;
  }

  return { dim, advance, stats };
}
