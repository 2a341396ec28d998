/**
 * Initial states on an energy surface H = E: a point drawn in a box, with
 * one momentum then solved for so that H takes the value E exactly (to the
 * last bits). A point for which no value of that momentum in its range gives
 * E is rejected, and another is drawn.
 *
 * The roots are found by scanning the momentum's range for sign changes of
 * H − E and bisecting each to the last bit; when there are several (p and
 * −p for a kinetic energy p²/2), one is chosen at random, each equally
 * likely, so that the set is symmetric where H is.
 */
import type { HamiltonianFunction } from '../types.ts';
import type { Range } from './box.ts';

/** Sign changes are looked for between this many equal parts of the range. */
export const SCAN_PARTS = 64;

export interface EnergyTarget {
  value: number;
  /** index of the momentum solved for, in the state */
  component: number;
  /** where the root is sought */
  range: Range;
}

export interface Roots {
  roots: number[];
  /** the least and greatest finite H − E seen while scanning, for a message when there is no root */
  low: number;
  high: number;
}

/**
 * Every root of H(t, x with x[component] = p) = E for p in the range, as
 * the sign changes of a scan show them. `x` is changed in that component.
 */
export function momentumRoots(h: HamiltonianFunction, t: number, x: Float64Array, target: EnergyTarget): Roots {
  const { component, range, value } = target;
  const f = (p: number) => {
    x[component] = p;
    return h(t, x, 0) - value;
  };
  const roots: number[] = [];
  let low = Infinity;
  let high = -Infinity;
  let a = range.lo;
  let fa = f(a);
  const note = (v: number) => {
    if (v < low) low = v;
    if (v > high) high = v;
  };
  if (Number.isFinite(fa)) note(fa);
  if (fa === 0) roots.push(a);
  for (let i = 1; i <= SCAN_PARTS; i++) {
    const b = i === SCAN_PARTS ? range.hi : range.lo + ((range.hi - range.lo) * i) / SCAN_PARTS;
    const fb = f(b);
    if (Number.isFinite(fb)) note(fb);
    if (fb === 0) roots.push(b);
    else if (Number.isFinite(fa) && Number.isFinite(fb) && fa !== 0 && fa < 0 !== fb < 0) roots.push(bisect(f, a, b, fa));
    a = b;
    fa = fb;
  }
  return { roots, low, high };
}

/** The root of f in [a, b], where f changes sign, to the last bit: the end with the smaller |f| once no midpoint lies between. */
function bisect(f: (p: number) => number, a: number, b: number, fa: number): number {
  let fb = NaN;
  for (;;) {
    const mid = a + (b - a) / 2;
    if (mid === a || mid === b) break;
    const fm = f(mid);
    if (fm === 0) return mid;
    if (fm < 0 === fa < 0) {
      a = mid;
      fa = fm;
    } else {
      b = mid;
      fb = fm;
    }
  }
  if (Number.isNaN(fb)) fb = f(b);
  return Math.abs(fa) <= Math.abs(fb) ? a : b;
}
