import type { Stepper, VectorField } from '../types.ts';

/**
 * The classical Runge–Kutta 3/8 rule (Kutta 1901; Hairer, Nørsett & Wanner,
 * *Solving ODEs I*, p. 138; the paper's Table 3):
 *
 *     k1 = f(t,        x)
 *     k2 = f(t + h/3,  x + h·k1/3)
 *     k3 = f(t + 2h/3, x + h·(−k1/3 + k2))
 *     k4 = f(t + h,    x + h·(k1 − k2 + k3))
 *     x ← x + h·(k1 + 3k2 + 3k3 + k4)/8
 *
 * This generic stepper calls a vector field through a function, for the
 * routes whose field is not known symbolically; expression models get a
 * fused stepper generated per model instead (see `fusedStepperSource`).
 */
export function rk38(field: VectorField, dim: number): Stepper {
  // Stage buffers are allocated once per stepper: nothing is allocated per step.
  const y = new Float64Array(dim);
  const stage = new Float64Array(dim);
  const k1 = new Float64Array(dim);
  const k2 = new Float64Array(dim);
  const k3 = new Float64Array(dim);
  const k4 = new Float64Array(dim);
  const third = 1 / 3;

  function advance(
    x: Float64Array,
    count: number,
    _params: Float64Array,
    t0: number,
    k0: number,
    dt: number,
    steps: number,
  ): number {
    for (let m = 0; m < count; m++) {
      const o = m * dim;
      for (let i = 0; i < dim; i++) y[i] = x[o + i];
      for (let k = 0; k < steps; k++) {
        const t = t0 + (k0 + k) * dt;
        field(t, y, k1);
        for (let i = 0; i < dim; i++) stage[i] = y[i] + dt * third * k1[i];
        field(t + dt * third, stage, k2);
        for (let i = 0; i < dim; i++) stage[i] = y[i] + dt * (k2[i] - third * k1[i]);
        field(t + 2 * dt * third, stage, k3);
        for (let i = 0; i < dim; i++) stage[i] = y[i] + dt * (k1[i] - k2[i] + k3[i]);
        field(t + dt, stage, k4);
        let sum = 0;
        for (let i = 0; i < dim; i++) {
          y[i] += dt * 0.125 * (k1[i] + 3 * (k2[i] + k3[i]) + k4[i]);
          sum += y[i];
        }
        // One subtraction tests every component: NaN or ±∞ anywhere makes sum − sum non-zero.
        if (sum - sum !== 0) {
          for (let i = 0; i < dim; i++) x[o + i] = y[i];
          return k;
        }
      }
      for (let i = 0; i < dim; i++) x[o + i] = y[i];
    }
    return steps;
  }

  return { dim, advance };
}
