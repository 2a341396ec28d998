/**
 * The integration methods a model can be run with, by name, and the checks
 * on a choice of one. RK 3/8 is the default, as in the paper.
 */
import { InputError } from '../errors.ts';

export const METHOD_NAMES = ['rk38', 'verlet', 'yoshida4', 'midpoint', 'adaptive'] as const;
export type MethodName = (typeof METHOD_NAMES)[number];

/** A method, with the tolerances of the adaptive one. */
export interface MethodChoice {
  readonly name: MethodName;
  /** relative tolerance of the adaptive method's local error */
  readonly rtol?: number;
  /** absolute tolerance of the adaptive method's local error */
  readonly atol?: number;
}

export const DEFAULT_METHOD: MethodChoice = { name: 'rk38' };
export const DEFAULT_RTOL = 1e-9;
export const DEFAULT_ATOL = 1e-12;
/**
 * Below this a relative tolerance asks for more than doubles hold: the
 * local error estimate is itself made of rounding there.
 */
export const LEAST_RTOL = 1e-14;

/**
 * The methods that need code generated from H's derivatives on the symbolic
 * routes: the splittings use ∂H/∂p and ∂H/∂q apart, the midpoint rule the
 * second derivatives. They are part of a compiled model's key.
 */
export const CODE_METHODS: ReadonlySet<MethodName> = new Set(['verlet', 'yoshida4', 'midpoint']);

/** The splitting methods, which need H = T(p) + V(q, t). */
export const SPLITTING_METHODS: ReadonlySet<MethodName> = new Set(['verlet', 'yoshida4']);

export function isMethodName(name: unknown): name is MethodName {
  return typeof name === 'string' && (METHOD_NAMES as readonly string[]).includes(name);
}

/**
 * A checked method choice from a name and, for the adaptive method only,
 * tolerances (defaults DEFAULT_RTOL and DEFAULT_ATOL). Throws an InputError
 * with a one-line message for anything else.
 */
export function methodChoice(name: unknown, rtol?: unknown, atol?: unknown): MethodChoice {
  if (!isMethodName(name)) {
    const shown = typeof name === 'string' ? `"${name}"` : String(name);
    throw new InputError(`the method must be one of ${METHOD_NAMES.join(', ')}, not ${shown}`);
  }
  if (name !== 'adaptive') {
    if (rtol !== undefined || atol !== undefined) throw new InputError(`rtol and atol are tolerances of the adaptive method, not of ${name}`);
    return { name };
  }
  const tolerance = (value: unknown, what: string, fallback: number) => {
    if (value === undefined) return fallback;
    if (typeof value !== 'number' || !Number.isFinite(value) || !(value >= 0)) {
      throw new InputError(`${what} must be a finite number ≥ 0, not ${String(value)}`);
    }
    return value;
  };
  const r = tolerance(rtol, 'rtol', DEFAULT_RTOL);
  const a = tolerance(atol, 'atol', DEFAULT_ATOL);
  if (r < LEAST_RTOL) throw new InputError(`rtol ${r} asks for more than double precision holds; give rtol ≥ ${LEAST_RTOL}`);
  return { name, rtol: r, atol: a };
}

/** One sentence on the error of each method, for a model's accuracy note. */
export const METHOD_ACCURACY: Record<MethodName, string> = {
  rk38: 'the RK 3/8 truncation error, O(dt⁴) over a fixed time, with an energy error that drifts',
  verlet: 'the Störmer–Verlet truncation error, O(dt²) over a fixed time; symplectic, so for an autonomous H the energy error stays bounded, O(dt²), instead of drifting',
  yoshida4: 'the Yoshida 4th-order composition error, O(dt⁴) over a fixed time; symplectic, so for an autonomous H the energy error stays bounded, O(dt⁴)',
  midpoint: 'the implicit midpoint rule’s truncation error, O(dt²) over a fixed time; symplectic for any H, energy error bounded for an autonomous H; Newton iterated to rounding',
  adaptive: 'the Dormand–Prince 5(4) local error held below atol + rtol·|x| per step, with 4th-order dense output at the sample times; errors add up over time and the energy drifts',
};
