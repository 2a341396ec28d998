/**
 * What an analysis hands a theory check (chapter/theory-check/theory-check.ts): the two
 * numbers, the errors allowed with their reasons, and the conditions of the
 * formula's regime, each computed for the current run. The same shape as
 * chapter/theory-check/check-verdict.ts's VerdictInput, declared here so that the core
 * imports nothing from the book.
 */
export interface CheckTerm {
  value: number | null;
  why: string;
}

export interface CheckCondition {
  holds: boolean;
  condition: string;
}

export interface CheckInput {
  measured: number;
  predicted: number;
  relative?: boolean;
  errors: { formula?: CheckTerm; integration?: CheckTerm; measurement?: CheckTerm };
  validity: CheckCondition[];
  missing?: string;
  /** how the measured value was obtained */
  method: string;
  /** the formula, in words */
  formula: string;
}

/** 2 significant digits, for the reasons' numbers. */
export const two = (x: number): string => (Number.isFinite(x) ? (Math.abs(x) < 1e-3 || Math.abs(x) >= 1e4 ? x.toExponential(1) : x.toPrecision(2)) : String(x));

/** "≪ 1" in the book's checks: at most a third (chapter/theory-check/check-verdict.ts, SMALL). */
export const SMALL = 1 / 3;

/** Rounding of one step, relative: half an ulp of 1 (2⁻⁵³). */
export const UNIT_ROUNDOFF = 2 ** -53;
