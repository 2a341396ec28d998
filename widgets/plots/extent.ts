import { scaleLinear, transform, untransform, type SignedKind } from './scale.ts';

/**
 * A rectangle of the data plane, [x0, x1] × [y0, y1]. Plots keep one per
 * panel and mutate it in place so that per-frame bookkeeping allocates
 * nothing; the functions that return a new extent run only when a plot
 * grows or is laid out.
 */
export interface Extent {
  x0: number;
  x1: number;
  y0: number;
  y1: number;
}

/** An extent that contains nothing: including any point makes it that point. */
export function emptyExtent(): Extent {
  return { x0: Infinity, x1: -Infinity, y0: Infinity, y1: -Infinity };
}

export function isEmpty(e: Extent): boolean {
  return !(e.x0 <= e.x1 && e.y0 <= e.y1);
}

/** Widens `e` in place to contain (x, y); non-finite points are ignored. */
export function includePoint(e: Extent, x: number, y: number): void {
  if (!Number.isFinite(x) || !Number.isFinite(y)) return;
  if (x < e.x0) e.x0 = x;
  if (x > e.x1) e.x1 = x;
  if (y < e.y0) e.y0 = y;
  if (y > e.y1) e.y1 = y;
}

/** Whether `inner` lies within `outer` (an empty `inner` always does). */
export function contains(outer: Extent, inner: Extent): boolean {
  if (isEmpty(inner)) return true;
  return inner.x0 >= outer.x0 && inner.x1 <= outer.x1 && inner.y0 >= outer.y0 && inner.y1 <= outer.y1;
}

/**
 * [lo, hi] widened by `headroom` of its span on each side, in the axis's
 * transformed space, and rounded outward to tick values for a linear axis.
 * A zero span (the first sample, or a coordinate that has not moved yet) is
 * given a width proportional to its size, so that the first frames do not
 * zoom onto a single point.
 */
export function padInterval(lo: number, hi: number, headroom: number, kind: SignedKind = 'linear', c = 1): [number, number] {
  let a = transform(kind, lo, c);
  let b = transform(kind, hi, c);
  if (!(b - a > 0)) {
    const half = Math.max(Math.abs(a) * 0.1, kind === 'symlog' ? 0.5 : 1e-6);
    a -= half;
    b += half;
  }
  const pad = (b - a) * headroom;
  // padding never crosses zero: a quantity that has not been negative keeps 0 as its floor
  a = untransform(kind, lo >= 0 && hi > 0 ? Math.max(0, a - pad) : a - pad, c);
  b = untransform(kind, hi <= 0 && lo < 0 ? Math.min(0, b + pad) : b + pad, c);
  if (kind === 'linear') [a, b] = scaleLinear().domain([a, b]).nice(16).domain() as [number, number];
  return [a, b];
}

/** The smallest extent holding both (either may be empty). */
export function union(a: Extent, b: Extent): Extent {
  return { x0: Math.min(a.x0, b.x0), x1: Math.max(a.x1, b.x1), y0: Math.min(a.y0, b.y0), y1: Math.max(a.y1, b.y1) };
}

/** The padded union of `current` (may be empty) and `data`. */
export function growExtent(
  current: Extent,
  data: Extent,
  headroom: number,
  xKind: SignedKind = 'linear',
  yKind: SignedKind = 'linear',
  c = 1,
): Extent {
  const [x0, x1] = padInterval(Math.min(current.x0, data.x0), Math.max(current.x1, data.x1), headroom, xKind, c);
  const [y0, y1] = padInterval(Math.min(current.y0, data.y0), Math.max(current.y1, data.y1), headroom, yKind, c);
  return { x0, x1, y0, y1 };
}

/**
 * `next` widened so that on each axis where it outgrew `previous` its span is
 * at least `factor` times the old one, extended on the side that grew: a
 * plot that keeps growing (particles flying off) is then redrawn a
 * logarithmic number of times, not once per small step outward.
 */
export function stretchGrowth(previous: Extent, next: Extent, factor: number, xKind: SignedKind = 'linear', yKind: SignedKind = 'linear', c = 1): Extent {
  if (isEmpty(previous)) return next;
  const [x0, x1] = stretch(previous.x0, previous.x1, next.x0, next.x1, factor, xKind, c);
  const [y0, y1] = stretch(previous.y0, previous.y1, next.y0, next.y1, factor, yKind, c);
  return { x0, x1, y0, y1 };
}

function stretch(oldLo: number, oldHi: number, lo: number, hi: number, factor: number, kind: SignedKind, c: number): [number, number] {
  const [a0, a1, b0, b1] = [oldLo, oldHi, lo, hi].map((v) => transform(kind, v, c));
  const grewLow = b0 < a0;
  const grewHigh = b1 > a1;
  const extra = factor * (a1 - a0) - (b1 - b0);
  if ((!grewLow && !grewHigh) || !(extra > 0)) return [lo, hi];
  let low = grewLow && grewHigh ? extra / 2 : grewLow ? extra : 0;
  // the stretch does not cross zero either; what it cannot add below, it adds above (and the reverse)
  if (b0 >= 0 && b0 - low < 0) low = b0;
  if (b1 <= 0 && b1 + (extra - low) > 0) low = extra - -b1;
  return [untransform(kind, b0 - low, c), untransform(kind, b1 + (extra - low), c)];
}

/**
 * `e` widened about its centre so that one data unit spans as many pixels
 * across as up in a width × height box: a circle stays round.
 */
export function fitEqualAspect(e: Extent, width: number, height: number): Extent {
  const perPixel = Math.max((e.x1 - e.x0) / width, (e.y1 - e.y0) / height);
  const cx = (e.x0 + e.x1) / 2;
  const cy = (e.y0 + e.y1) / 2;
  const hx = (perPixel * width) / 2;
  const hy = (perPixel * height) / 2;
  return { x0: cx - hx, x1: cx + hx, y0: cy - hy, y1: cy + hy };
}
