/**
 * A box in phase space: one closed range per state component, in the state's
 * order (q's then p's). A range with lo = hi holds the component fixed.
 */
export interface Range {
  lo: number;
  hi: number;
}

/** Grid axis: n points from lo to hi, both included (one point: lo). */
export interface Axis extends Range {
  n: number;
}

/** lo + (hi − lo)·u for u in [0, 1): a uniform draw from the range, exactly lo for a fixed component. */
export function pointIn(range: Range, u: number): number {
  return range.lo === range.hi ? range.lo : range.lo + (range.hi - range.lo) * u;
}
