/**
 * The verdict of a theory check, apart from how it is shown: a pure function
 * of the numbers a chapter passes, so that its logic is unit-tested
 * (tests/unit/check-verdict.test.ts) and the widget (theory-check.ts) only
 * draws it.
 *
 * A check compares a measured value with a formula's. It names the errors it
 * allows, each computed by the chapter from the current parameters:
 *
 * - `formula`: what the formula leaves out (its first neglected order);
 * - `integration`: the integrator's truncation and rounding error;
 * - `measurement`: the measurement's own error (a spectral peak's leakage and
 *   resolution, a fit's residual, a sampled maximum, …).
 *
 * It agrees exactly when |measured − predicted| (divided by |predicted| for a
 * relative check) is at most their sum. Before that, it asks whether the
 * formula applies at all: a chapter states the conditions of the formula's
 * regime (a slow ramp, a small amplitude, a bound orbit), and when one fails
 * the verdict is "outside the formula's validity", neither agreement nor
 * disagreement. When a number cannot be had (a period of a pendulum that goes
 * over the top), the verdict says so and why, rather than comparing NaN.
 */

export const ERROR_SOURCES = ['formula', 'integration', 'measurement'] as const;
export type ErrorSource = (typeof ERROR_SOURCES)[number];

/**
 * One source of error: its size, in the check's units (a fraction for a
 * relative check), and why it is that size. A size that cannot be estimated
 * for these parameters is null (or NaN), and the check then gives no verdict.
 */
export interface ErrorTerm {
  value: number | null;
  /** one line, e.g. "the b³ and b⁴ terms the formula leaves out" */
  why: string;
}

/** A condition of the formula's regime, evaluated by the chapter for the current parameters. */
export interface Condition {
  holds: boolean;
  /** what the condition is and how it stands, e.g. "the ramp is slow: (2π + 2)|ε|/ω² = 0.03 ≤ 1/3" */
  condition: string;
}

export interface VerdictInput {
  measured: number;
  predicted: number;
  relative?: boolean;
  /** the errors allowed, by source; a bare number has no stated reason */
  errors?: Partial<Record<ErrorSource, ErrorTerm | number | null>>;
  /**
   * A single allowance without an error model, as checks were first written;
   * kept so that a reader's saved edit of an old cell still runs. Not with `errors`.
   */
  tolerance?: number;
  /** the formula's regime: the check is judged only when every condition holds */
  validity?: Condition | readonly Condition[];
  /** why measured or predicted is not a number, when it is not */
  missing?: string;
}

export type Verdict = 'agrees' | 'disagrees' | 'outside' | 'undefined';

export interface AllowedTerm {
  source: ErrorSource | 'allowance';
  value: number;
  why: string;
}

export interface Judgement {
  verdict: Verdict;
  /** |measured − predicted|, NaN when either is missing */
  difference: number;
  /** the difference as compared: divided by |predicted| for a relative check */
  error: number;
  /** the sum of the terms */
  allowed: number;
  terms: AllowedTerm[];
  /** for 'outside' the failed condition, for 'undefined' what is missing and why */
  reason: string;
}

/** "≪ 1" in the book's checks: a small quantity is at most a third of what it is compared with. */
export const SMALL = 1 / 3;

function checkTerm(source: string, value: unknown): void {
  if (value === null) return;
  if (typeof value !== 'number') throw new TypeError(`theoryCheck: the ${source} error must be a number, not ${String(value)}`);
  if (value < 0) throw new RangeError(`theoryCheck: the ${source} error is a size and cannot be negative (got ${value})`);
}

/** The terms a check allows, in the order formula, integration, measurement. */
export function allowedTerms(input: Pick<VerdictInput, 'errors' | 'tolerance'>): AllowedTerm[] {
  const { errors, tolerance } = input;
  if (errors !== undefined && tolerance !== undefined) {
    throw new Error('theoryCheck: give either `errors` (the error model) or `tolerance`, not both');
  }
  if (errors === undefined) {
    if (tolerance === undefined) throw new Error('theoryCheck: state the errors allowed, as `errors: {formula, integration, measurement}`');
    checkTerm('allowed', tolerance);
    return [{ source: 'allowance', value: tolerance, why: 'an allowance without a stated error model' }];
  }
  for (const key of Object.keys(errors)) {
    if (!(ERROR_SOURCES as readonly string[]).includes(key)) {
      throw new Error(`theoryCheck: unknown source of error "${key}"; use ${ERROR_SOURCES.join(', ')}`);
    }
  }
  const terms: AllowedTerm[] = [];
  for (const source of ERROR_SOURCES) {
    const term = errors[source];
    if (term === undefined) continue;
    const { value, why } = term === null || typeof term === 'number' ? { value: term, why: '' } : term;
    checkTerm(source, value);
    terms.push({ source, value: value ?? NaN, why });
  }
  if (terms.length === 0) throw new Error('theoryCheck: `errors` names no source of error');
  return terms;
}

const conditions = (validity: VerdictInput['validity']): readonly Condition[] =>
  validity === undefined ? [] : Array.isArray(validity) ? validity : [validity as Condition];

/** Judges a check: see the module's comment for the rules, which apply in the order written there. */
export function judge(input: VerdictInput): Judgement {
  const { measured, predicted, relative = false } = input;
  const terms = allowedTerms(input);
  const allowed = terms.reduce((sum, term) => sum + term.value, 0);
  const difference = Math.abs(measured - predicted);
  const error = relative ? difference / Math.abs(predicted) : difference;
  const result = (verdict: Verdict, reason = ''): Judgement => ({ verdict, difference, error, allowed, terms, reason });

  const failed = conditions(input.validity).find((c) => !c.holds);
  if (failed) return result('outside', failed.condition);

  if (!Number.isFinite(measured) || !Number.isFinite(predicted)) {
    const which = !Number.isFinite(measured) ? 'the measurement' : 'the formula';
    return result('undefined', input.missing ?? `${which} gave no number`);
  }
  if (relative && predicted === 0) return result('undefined', 'the formula predicts 0, so a relative difference means nothing');
  const unknown = terms.find((term) => !Number.isFinite(term.value));
  if (unknown) return result('undefined', `the ${unknown.source} error could not be estimated${unknown.why ? `: ${unknown.why}` : ''}`);
  return result(error <= allowed ? 'agrees' : 'disagrees');
}
