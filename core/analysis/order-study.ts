/**
 * The order of a method, measured: its global error at a fixed time T for
 * several step sizes h, and the least-squares slope of log error against
 * log h. A method of order p has global error C·h^p·(1 + c·h^q + …) over a
 * fixed time (Hairer, Nørsett & Wanner, *Solving ODEs I*, 2nd ed.,
 * Thm II.3.6 and §II.8), with q = 2 for a symmetric method, whose error
 * expansion has only even powers of h (HNW Thm II.8.10; Hairer, Lubich &
 * Wanner, *Geometric Numerical Integration*, §II.3), and q = 1 otherwise.
 *
 * The check's error model, each term computed for the run at hand:
 *
 * - formula: the next term moves the local slope d log e/d log h by about
 *   q·c·h^q, so the fitted slope is off by up to q·|c|·h_max^q. The
 *   coefficient c is not known in advance (on the pendulum it is several
 *   times the motion's rate), so it is read off the data: the local slopes
 *   s between neighbouring steps change by q·c·(h₁^q − h_L^q) from the
 *   largest steps to the smallest, and the allowance is
 *   |s₁ − s_L|·h_max^q/(h_max^q − h_min^q). A wrong order shows as a slope
 *   that is off while the local slopes agree, and so is not excused.
 *   Premises: Ω·h_max ≤ 1/3 (Ω the motion's fastest rate), and local slopes
 *   that have settled, |s₁ − s_L| ≤ 1/3: outside that the series in h is
 *   not a small correction and no one-term estimate holds.
 * - integration: the reference's own error δ (0 against a closed form)
 *   moves log eᵢ by at most δ/eᵢ, and the slope by Σ|wᵢ|·δ/eᵢ with the
 *   fit's weights (line-fit.ts).
 * - measurement: rounding, 2⁻⁵³ of the state per step as a random walk
 *   over the Nᵢ steps of each run (Higham, *Accuracy and Stability of
 *   Numerical Algorithms*, §2.8), carried to the slope the same way. The
 *   premise is that every error stands 3× above this floor.
 */
import { SMALL, two, UNIT_ROUNDOFF, type CheckInput } from './check-input.ts';
import { fitLine } from './line-fit.ts';

/** The order of each fixed-step method, and whether it is symmetric (its error series in even powers of h). */
export const METHOD_ORDERS: Readonly<Record<string, { order: number; symmetric: boolean }>> = {
  rk38: { order: 4, symmetric: false },
  verlet: { order: 2, symmetric: true },
  yoshida4: { order: 4, symmetric: true },
  midpoint: { order: 2, symmetric: true },
};

export interface OrderStudyInput {
  /** the method's name, for the texts */
  method: string;
  /** the order the theory gives */
  order: number;
  /** a symmetric method (verlet, yoshida4, midpoint): its error expansion is in even powers of h */
  symmetric: boolean;
  /** the fixed time at which the errors are measured */
  T: number;
  /** the step sizes, each dividing T */
  steps: readonly number[];
  /** the global error at T for each step size (a norm of the state's difference from the truth) */
  errors: readonly number[];
  /** Ω, the fastest rate of the motion */
  rate: number;
  /** the size of the state (its largest component), which sets the rounding */
  size: number;
  /** the error of the reference the errors were measured against: 0 for a closed form */
  reference: number;
  /** what the reference is, e.g. "the closed form" or "Dormand–Prince at rtol 1e-13" */
  referenceName: string;
}

export interface OrderStudy {
  slope: number;
  /** log e ≈ intercept + slope·log h: the fitted line, for the figure */
  intercept: number;
  /** the rounding of each run, in the errors' units */
  rounding: number[];
}

/** The fitted slope of log error against log h. */
export function orderStudy(input: OrderStudyInput): OrderStudy {
  const usable = input.errors.map((e, i) => [input.steps[i], e] as const).filter(([h, e]) => h > 0 && e > 0 && Number.isFinite(e));
  const fit = fitLine(usable.map(([h]) => Math.log(h)), usable.map(([, e]) => Math.log(e)));
  const rounding = input.steps.map((h) => UNIT_ROUNDOFF * input.size * Math.sqrt(Math.round(input.T / h)));
  return { slope: fit.slope, intercept: fit.intercept, rounding };
}

/** The slopes between neighbouring steps, largest steps first. */
export function localSlopes(steps: readonly number[], errors: readonly number[]): number[] {
  const order = steps.map((h, i) => [h, errors[i]] as const).sort((a, b) => b[0] - a[0]);
  return order.slice(1).map(([h, e], i) => Math.log(order[i][1] / e) / Math.log(order[i][0] / h));
}

/** The theory check of the order: see the module comment for its error model. */
export function orderCheck(input: OrderStudyInput): CheckInput {
  const { method, order, symmetric, steps, errors, rate, reference, referenceName } = input;
  const study = orderStudy(input);
  const usable = errors.every((e) => e > 0 && Number.isFinite(e)) && errors.length >= 3;
  const weights = usable ? fitLine(steps.map(Math.log), errors.map(Math.log)).weights : [];
  const carried = (delta: (i: number) => number) => weights.reduce((sum, w, i) => sum + Math.abs(w) * (delta(i) / errors[i]), 0);
  const q = symmetric ? 2 : 1;
  const hMax = Math.max(...steps);
  const hMin = Math.min(...steps);
  const local = localSlopes(steps, errors);
  const spread = local.length >= 2 ? Math.abs(local[0] - local[local.length - 1]) : NaN;
  const nextTerm = (spread * hMax ** q) / (hMax ** q - hMin ** q);
  const floor = Math.max(...steps.map((_, i) => 3 * (study.rounding[i] + reference)));
  const smallest = Math.min(...errors);
  const term = (value: number, why: string) => ({ value: usable ? value : NaN, why });
  return {
    measured: usable ? study.slope : NaN,
    predicted: order,
    missing: `the ${method} runs gave ${errors.length} errors, not three or more positive ones: ${errors.map(two).join(', ')}`,
    validity: [
      {
        holds: rate * hMax <= SMALL,
        condition: `the steps must be small, Ω·h ≤ 1/3 with Ω = ${two(rate)} the fastest rate of the motion, but Ω·h_max = ${two(rate * hMax)}: the next terms of the error series are not small`,
      },
      {
        holds: !usable || smallest >= floor,
        condition: `every error must stand 3× above the rounding and reference floor, but at h = ${two(hMin)} it is ${two(smallest)} against ${two(floor)}: the error has reached rounding`,
      },
      {
        holds: !usable || !(spread > SMALL),
        condition: `the local slopes must have settled, changing by at most 1/3 from the largest steps to the smallest, but they run ${local.map((v) => v.toFixed(2)).join(', ')}: the next terms of the error series are not a small correction`,
      },
    ],
    errors: {
      formula: term(nextTerm, `the next term of the error series, c·h${q === 1 ? '¹' : '²'}${symmetric ? ' (a symmetric method: even powers only)' : ''}, read off the local slopes ${local.map((v) => v.toFixed(2)).join(', ')}`),
      integration: term(carried(() => reference), reference === 0 ? `none: measured against ${referenceName}` : `${referenceName} is itself wrong by about ${two(reference)}`),
      measurement: term(carried((i) => study.rounding[i]), `rounding, 2⁻⁵³ of the state per step as a random walk over ${Math.round(input.T / hMax)}–${Math.round(input.T / hMin)} steps`),
    },
    method: `least-squares slope of log error against log h, errors at T = ${two(input.T)} from ${two(Math.max(...errors))} to ${two(smallest)} against ${referenceName}`,
    formula: `order ${order}`,
  };
}
