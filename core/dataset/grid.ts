import type { Axis } from './box.ts';

/**
 * Initial states on a grid: the product of one axis per state component,
 * enumerated in C order (the first component varies slowest), as
 * numpy.meshgrid(…, indexing='ij') and itertools.product enumerate it.
 */

/** The number of grid points, Π n. */
export function gridSize(axes: readonly Axis[]): number {
  return axes.reduce((n, axis) => n * axis.n, 1);
}

/**
 * The i-th of n points from lo to hi, computed as numpy.linspace does
 * (i·step + lo, with the last point exactly hi), so that a grid read back in
 * Python compares equal to one made there.
 */
export function axisPoint(axis: Axis, i: number): number {
  if (axis.n === 1) return axis.lo;
  if (i === axis.n - 1) return axis.hi;
  return i * ((axis.hi - axis.lo) / (axis.n - 1)) + axis.lo;
}

/** Grid point `index` into out[offset …], one value per axis. */
export function gridPoint(axes: readonly Axis[], index: number, out: Float64Array, offset = 0): void {
  let rest = index;
  for (let c = axes.length - 1; c >= 0; c--) {
    const n = axes[c].n;
    const i = rest % n;
    rest = (rest - i) / n;
    out[offset + c] = axisPoint(axes[c], i);
  }
}
