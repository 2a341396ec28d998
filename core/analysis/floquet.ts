import type { Model } from '../types.ts';

/**
 * Floquet theory for a periodically driven linear system of one degree of
 * freedom (Landau & Lifshitz, Mechanics §27; Arnold, Mathematical Methods
 * §25): integrating the two fundamental solutions over one period T gives the
 * monodromy matrix M, with det M = 1 (Liouville). Its multipliers λ satisfy
 * λ² − (tr M)λ + 1 = 0, so the motion is stable when |tr M| < 2 and otherwise
 * grows like e^{st} with s = ln|λ_max|/T.
 */
export interface Floquet {
  trace: number;
  /** the larger |λ| */
  multiplier: number;
  /** growth rate s = ln|λ_max| / T (0 when stable) */
  growth: number;
  stable: boolean;
}

const basis = new Float64Array(4);

/** Floquet data of a linear 1-DOF model over one period, in `steps` RK 3/8 steps. */
export function floquet(model: Model, period: number, steps: number, t0 = 0): Floquet {
  if (model.dof !== 1) throw new Error('floquet: the model must have one degree of freedom');
  // Both fundamental solutions advance together as a batch of two: (q, p) = (1, 0) and (0, 1).
  basis[0] = 1;
  basis[1] = 0;
  basis[2] = 0;
  basis[3] = 1;
  model.stepper.advance(basis, 2, model.params, t0, 0, period / steps, steps);
  const trace = basis[0] + basis[3];
  const half = Math.abs(trace) / 2;
  const multiplier = half > 1 ? half + Math.sqrt(half * half - 1) : 1;
  return { trace, multiplier, growth: Math.log(multiplier) / period, stable: Math.abs(trace) < 2 };
}

export interface FloquetGridOptions {
  /** parameter along the horizontal axis, and its values */
  x: { param: string; values: ArrayLike<number> };
  /** parameter along the vertical axis, and its values */
  y: { param: string; values: ArrayLike<number> };
  /** the drive period for the current parameters, e.g. params => 2π/γ */
  period: (params: Float64Array, names: readonly string[]) => number;
  stepsPerPeriod?: number;
  /** called after each row, with the fraction done, so a worker can report progress */
  progress?: (fraction: number) => void;
}

/**
 * Growth rates over a grid of two parameters, row by row (y outer): the
 * stability chart of parametric resonance. Entry [j·nx + i] is for
 * x.values[i], y.values[j]; 0 means stable.
 */
export function floquetGrid(model: Model, options: FloquetGridOptions): Float64Array {
  const ix = model.paramNames.indexOf(options.x.param);
  const iy = model.paramNames.indexOf(options.y.param);
  if (ix < 0 || iy < 0) throw new Error(`floquetGrid: the model has no parameter ${ix < 0 ? options.x.param : options.y.param}`);
  const nx = options.x.values.length;
  const ny = options.y.values.length;
  const steps = options.stepsPerPeriod ?? 400;
  const saved = Float64Array.from(model.params);
  const out = new Float64Array(nx * ny);
  try {
    for (let j = 0; j < ny; j++) {
      model.params[iy] = options.y.values[j];
      for (let i = 0; i < nx; i++) {
        model.params[ix] = options.x.values[i];
        out[j * nx + i] = floquet(model, options.period(model.params, model.paramNames), steps).growth;
      }
      options.progress?.((j + 1) / ny);
    }
  } finally {
    model.params.set(saved);
  }
  return out;
}
