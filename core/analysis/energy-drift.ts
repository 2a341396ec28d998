/**
 * The long-time law of an integrator's energy error, measured from the
 * relative error e_n = (H(x_n) − H₀)/|H₀| at every step of a run of an
 * autonomous H:
 *
 * - a method that is not symplectic (RK 3/8) gains a little energy error in
 *   every step with a non-zero mean along the orbit, so its error grows
 *   linearly in t, the "secular drift" (Hairer, Lubich & Wanner,
 *   *Geometric Numerical Integration*, 2nd ed., §IX.8 and Fig. I.2.3): the
 *   log–log slope of its envelope is 1;
 * - a symplectic method (Störmer–Verlet) conserves a modified Hamiltonian
 *   H̃ = H + O(h^p) up to exponentially small terms over exponentially long
 *   times (HLW Thm IX.8.1), so |H − H₀| stays below a bound O(h^p) and the
 *   largest error over the second half of a run equals that over the first.
 *
 * `energyDrift` measures; `driftCheck`, `boundedCheck` and
 * `modifiedEnergyCheck` are the theory checks, each with its error model.
 */
import { SMALL, two, UNIT_ROUNDOFF, type CheckCondition, type CheckInput } from './check-input.ts';
import { fitLine } from './line-fit.ts';
import { hamiltonianFlowCondition } from '../model/non-hamiltonian.ts';
import type { NonHamiltonianPart } from '../types.ts';

export interface EnergyDrift {
  /** steps in the run, and its time span */
  steps: number;
  T: number;
  /** the largest |e| over the first and over the second half of the run */
  first: number;
  second: number;
  /** the envelope's log–log slope over [from, T] */
  exponent: number;
  exponentError: number;
  from: number;
  /** the running maximum of |e| at `from` and at T */
  atFrom: number;
  atEnd: number;
  /** the part of e that does not grow: the deepest drop of |e| below its running maximum */
  bounded: number;
  /** the line's slope, per unit time */
  rate: number;
  /** the envelope at log-spaced times over [from, T], as fitted */
  envelope: { t: number[]; e: number[] };
  /** the largest |e| in each of `bins` equal stretches of time, for a figure: {t, e} */
  binned: { t: number[]; e: number[] };
  /** ∂exponent/∂log M at each envelope point (the fit's weights) */
  weights: number[];
}

/**
 * Measures the law of the relative energy error `e` (signed, one per step,
 * e[0] at t = dt) of a run of step `dt`: see {@link EnergyDrift}. The
 * exponent is fitted over the last two decades of time, [T/100, T].
 */
export function energyDrift(e: ArrayLike<number>, dt: number, options: { points?: number; bins?: number; decades?: number } = {}): EnergyDrift {
  const { points = 60, bins = 400, decades = 2 } = options;
  const n = e.length;
  const T = n * dt;
  let first = 0;
  let second = 0;
  for (let i = 0; i < n; i++) {
    const a = Math.abs(e[i]);
    if (2 * i < n) first = Math.max(first, a);
    else second = Math.max(second, a);
  }
  // The running maximum at log-spaced times: the envelope whose growth the law is about.
  const from = T / 10 ** decades;
  const et: number[] = [];
  const ee: number[] = [];
  let most = 0;
  let next = 0;
  for (let i = 0; i < n; i++) {
    most = Math.max(most, Math.abs(e[i]));
    const t = (i + 1) * dt;
    const target = from * (T / from) ** (next / (points - 1));
    if (t >= target - 1e-9 * dt) {
      if (most > 0) {
        et.push(t);
        ee.push(most);
      }
      while (from * (T / from) ** (next / (points - 1)) <= t + 1e-9 * dt && next < points) next++;
    }
  }
  const fit = fitLine(et.map(Math.log), ee.map(Math.log));
  // What does not grow: the deepest drop of |e| below its running maximum. A steady growth never drops;
  // an oscillation of amplitude B on top of it drops by up to 2B.
  const line = fitLine(Float64Array.from({ length: n }, (_, i) => (i + 1) * dt), e);
  let bounded = 0;
  for (let i = 0, top = 0; i < n; i++) {
    top = Math.max(top, Math.abs(e[i]));
    bounded = Math.max(bounded, top - Math.abs(e[i]));
  }
  const binned = { t: [] as number[], e: [] as number[] };
  const per = Math.max(1, Math.floor(n / bins));
  for (let start = 0; start < n; start += per) {
    let top = 0;
    let at = start;
    for (let i = start; i < Math.min(n, start + per); i++) {
      if (Math.abs(e[i]) >= top) {
        top = Math.abs(e[i]);
        at = i;
      }
    }
    binned.t.push((at + 1) * dt);
    binned.e.push(top);
  }
  return {
    steps: n,
    T,
    first,
    second,
    exponent: fit.slope,
    exponentError: fit.slopeError,
    from,
    atFrom: ee[0] ?? NaN,
    atEnd: most,
    bounded,
    rate: line.slope,
    envelope: { t: et, e: ee },
    binned,
    weights: fit.weights,
  };
}

/** What the checks need to know of the run besides its energy error. */
export interface DriftContext {
  method: string;
  dt: number;
  /** Ω, the fastest rate of the motion */
  rate: number;
  /** does H depend on t? Then H is not conserved and no law applies. */
  autonomous: boolean;
  /** the model's non-Hamiltonian terms (Model.nonHamiltonian), if any: then H is not conserved either */
  nonHamiltonian?: NonHamiltonianPart;
  /** the largest |H|/|H₀| over the run, which sets the rounding of H relative to H₀ */
  scale?: number;
}

/** Rounding of the relative energy error after `steps` steps: 2⁻⁵³ per step as a random walk. */
const roundingAfter = (steps: number, scale = 1) => UNIT_ROUNDOFF * scale * Math.sqrt(steps);

const autonomy = (c: DriftContext): CheckCondition => ({
  holds: c.autonomous,
  condition: 'H depends on t, so the exact motion does not conserve it: there is no energy error to measure',
});

/** A non-Hamiltonian term changes H by design: that change is the physics, not the integrator's error. */
const conservative = (c: DriftContext): CheckCondition =>
  hamiltonianFlowCondition(c, 'the exact motion does not conserve H: its change is the physics, not an energy error of the integrator');

const small = (drift: EnergyDrift): CheckCondition => ({
  holds: drift.atEnd <= SMALL,
  condition: `the energy error must stay small, at most 1/3 of |H₀|, but it reaches ${two(drift.atEnd)}: the step is too large for the asymptotic laws`,
});

/**
 * The drift law of a method that is not symplectic: the envelope of |e|
 * grows like t¹. Premises: H autonomous, the error small, above rounding,
 * and growing: its bounded part at most 1/3 of it at the fit's start (else
 * no drift shows and there is no law to fit). Errors allowed: the bounded part b of e lowers the log-slope
 * at the fit's start by at most b/M(T/100), and the drift's own growth
 * (the next term, relative size M(T)) bends it; the fit's standard error,
 * twice; rounding, carried through the fit's weights.
 */
export function driftCheck(drift: EnergyDrift, context: DriftContext): CheckInput {
  const floor = roundingAfter(drift.steps, context.scale);
  const rounding = drift.weights.reduce((sum, w, i) => sum + Math.abs(w) * (roundingAfter(drift.envelope.t[i] / context.dt, context.scale) / drift.envelope.e[i]), 0);
  return {
    measured: drift.exponent,
    predicted: 1,
    missing: `the energy error of ${context.method} was exactly 0: nothing to fit`,
    validity: [
      autonomy(context),
      conservative(context),
      small(drift),
      {
        holds: drift.atFrom >= 3 * floor,
        condition: `the error at t = ${two(drift.from)}, ${two(drift.atFrom)}, must stand 3× above rounding, ${two(floor)}: take a larger dt or a longer run`,
      },
      {
        holds: drift.bounded <= SMALL * drift.atFrom,
        condition: `the growing part must dominate from the fit's start: the part that does not grow, ${two(drift.bounded)}, must be at most 1/3 of the error at t = ${two(drift.from)}, ${two(drift.atFrom)}; no drift shows over this run`,
      },
    ],
    errors: {
      formula: {
        value: drift.bounded / drift.atFrom + drift.atEnd,
        why: `the part of the error that does not grow, b = ${two(drift.bounded)}, lowers the slope by up to b/M(${two(drift.from)}); and the drift's own next term, of relative size M(T) = ${two(drift.atEnd)}`,
      },
      integration: { value: rounding, why: `rounding, 2⁻⁵³ per step as a random walk, carried through the fit` },
      measurement: { value: 2 * drift.exponentError, why: `twice the fit's standard error: the envelope grows in steps, once a period` },
    },
    method: `log–log slope of the largest |ΔH/H₀| so far, over t = ${two(drift.from)} … ${two(drift.T)} (${drift.steps} steps of ${context.method})`,
    formula: 'secular drift ∝ t¹ (HLW §IX.8)',
  };
}

/**
 * The bound of a symplectic method: the largest |e| over the second half of
 * the run over that of the first, 1 when nothing grows. Errors allowed: none
 * from the theory (H̃ is conserved for exponentially long times); sampling
 * the error's oscillation once a step misses its peak by up to (Ωh)²/2 of
 * it in either half (an oscillation at up to 2Ω, sampled every h); rounding
 * as a random walk.
 */
export function boundedCheck(drift: EnergyDrift, context: DriftContext & { symplectic: boolean; separable: boolean }): CheckInput {
  const floor = roundingAfter(drift.steps, context.scale);
  const sampling = (context.rate * context.dt) ** 2 / 2;
  return {
    measured: drift.second / drift.first,
    predicted: 1,
    missing: `the energy error of ${context.method} was exactly 0 over the first half: nothing to compare`,
    validity: [
      {
        holds: context.separable,
        condition: `H does not separate into T(p) + V(q), so ${context.method} cannot be applied (and a splitting is not symplectic for it)`,
      },
      {
        holds: context.symplectic,
        condition: `${context.method} is not symplectic: its energy error is not bounded by a modified Hamiltonian`,
      },
      autonomy(context),
      conservative(context),
      small(drift),
      {
        holds: context.rate * context.dt <= 1,
        condition: `backward error analysis needs a step that resolves the fastest oscillation, Ω·h ≤ 1, but Ω·h = ${two(context.rate * context.dt)}`,
      },
      {
        holds: drift.first >= 3 * floor,
        condition: `the error, ${two(drift.first)}, must stand 3× above rounding, ${two(floor)}: take a larger dt`,
      },
    ],
    errors: {
      formula: { value: 0, why: 'none: H̃ is conserved up to exponentially small terms for exponentially long times (HLW Thm IX.8.1)' },
      integration: { value: floor / drift.first, why: `rounding, 2⁻⁵³ per step as a random walk over ${drift.steps} steps` },
      // Beyond Ω·h = √2 the estimate means nothing (and the premise Ω·h ≤ 1 has failed already).
      measurement: { value: sampling < 1 ? sampling / (1 - sampling) : null, why: `sampling the error's oscillation once a step misses its peak by up to (Ω·h)²/2 = ${two(sampling)} of it` },
    },
    method: `largest |ΔH/H₀| over t > T/2 over that over t ≤ T/2: ${two(drift.second)} / ${two(drift.first)}, ${drift.steps} steps of ${context.method}`,
    formula: 'bounded: no growth (HLW Thm IX.8.1)',
  };
}

/**
 * The size of Störmer–Verlet's bounded error, from its modified
 * Hamiltonian (modified-hamiltonian.ts): H + h²H₂ is conserved up to h⁴,
 * so max|H(x_n) − H₀| = h²·max|H₂(x_n) − H₂(x₀)| up to a relative (Ωh)².
 * `predicted` is h²·max|ΔH₂|/|H₀| along the same run.
 */
export function modifiedEnergyCheck(drift: EnergyDrift, predicted: number, context: DriftContext & { separable: boolean }): CheckInput {
  const floor = roundingAfter(drift.steps, context.scale);
  const measured = Math.max(drift.first, drift.second);
  return {
    measured,
    predicted,
    relative: true,
    missing: `no modified Hamiltonian could be evaluated along the run`,
    validity: [
      { holds: context.separable, condition: `H does not separate into T(p) + V(q): ${context.method}'s modified Hamiltonian is not defined` },
      autonomy(context),
      conservative(context),
      small(drift),
      {
        holds: context.rate * context.dt <= SMALL,
        condition: `the h² term leads only while Ω·h ≤ 1/3, but Ω·h = ${two(context.rate * context.dt)}`,
      },
      { holds: measured >= 3 * floor, condition: `the error, ${two(measured)}, must stand 3× above rounding, ${two(floor)}` },
    ],
    errors: {
      formula: { value: (context.rate * context.dt) ** 2, why: `the h⁴ term of H̃, relative size (Ω·h)² = ${two((context.rate * context.dt) ** 2)}` },
      integration: { value: floor / predicted, why: 'rounding, 2⁻⁵³ per step as a random walk' },
    },
    method: `largest |ΔH/H₀| over ${drift.steps} steps of ${context.method}`,
    formula: 'h²·max|H₂(x) − H₂(x₀)|/|H₀|, H₂ = pᵀV″p/12 − |∇V|²/24',
  };
}
