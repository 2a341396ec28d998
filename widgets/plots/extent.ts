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
 * What an interval of zero span (the first sample, or a coordinate that has
 * not moved yet) is widened to: it has no span to pad by.
 */
export interface ZeroSpanRule {
  /** Half the width it is given, in transformed units, at transformed position u. */
  halfWidth: (u: number, kind: SignedKind) => number;
  /** Whether the padding is then added to that width too; if not, the width is the whole margin. */
  padded: boolean;
}

/** How a family of plots pads its intervals, whatever the amount: single values and rounding. */
export interface PaddingPolicy {
  zeroSpan: ZeroSpanRule;
  /** The tick count for d3's nice() that rounds a linear axis's ends: the more ticks, the smaller the step and the closer the ends hug the data. */
  linearNiceCount: number;
  /** A symlog axis's ends: rounded outward on the 1-2-5 ladder (see roundOutward), or left as padded. */
  symlogRounding: 'ladder' | 'none';
}

/** One interval's padding: the policy, on which axis, and how much. */
export interface PadOptions extends PaddingPolicy {
  /** Fraction of the span added on each side, in transformed units. */
  padding: number;
  kind: SignedKind;
  /** The symlog constant c of the axis (a linear axis ignores it). */
  c: number;
}

/**
 * [lo, hi] widened by `padding` of its span on each side, in the axis's
 * transformed space (so that symlog padding is even in decades), then rounded
 * outward as the policy says. A zero span is first widened by the policy's
 * zero-span rule. Padding never crosses zero: data that are all ≥ 0 (a
 * distance, an energy, a count) keep 0 as the floor, and data all ≤ 0 keep
 * it as the ceiling.
 */
export function padAndRound(lo: number, hi: number, options: PadOptions): [number, number] {
  const { kind, c, padding, zeroSpan } = options;
  let a = transform(kind, lo, c);
  let b = transform(kind, hi, c);
  let pad: number;
  if (b - a > 0) pad = (b - a) * padding;
  else {
    const half = zeroSpan.halfWidth(a, kind);
    a -= half;
    b += half;
    pad = zeroSpan.padded ? (b - a) * padding : 0;
  }
  const low = lo >= 0 && hi > 0 ? Math.max(0, a - pad) : a - pad;
  const high = hi <= 0 && lo < 0 ? Math.min(0, b + pad) : b + pad;
  return roundEnds(untransform(kind, low, c), untransform(kind, high, c), options);
}

/** Padded ends rounded outward, to d3's nice steps on a linear axis and as the policy says on a symlog one. */
function roundEnds(lo: number, hi: number, options: PadOptions): [number, number] {
  if (options.kind === 'linear') return scaleLinear().domain([lo, hi]).nice(options.linearNiceCount).domain();
  return options.symlogRounding === 'ladder' ? [roundOutward(lo, -1), roundOutward(hi, 1)] : [lo, hi];
}

/**
 * v moved away from zero (direction 1 rounds up, −1 down) to the next value
 * of the 1-2-5 ladder (…, 0.5, 1, 2, 5, 10, …); 0 stays 0.
 */
export function roundOutward(v: number, direction: 1 | -1): number {
  if (v === 0 || !Number.isFinite(v)) return v;
  const away = Math.sign(v) === direction;
  const magnitude = Math.abs(v);
  const decade = 10 ** Math.floor(Math.log10(magnitude));
  const ladder = [1, 2, 5, 10];
  let rounded: number;
  if (away) rounded = decade * ladder.find((f) => f * decade >= magnitude * (1 - 1e-12))!;
  else rounded = decade * [...ladder].reverse().find((f) => f * decade <= magnitude * (1 + 1e-12))!;
  return Math.sign(v) * rounded;
}

/**
 * The plane's policy. A single value gets a width of a tenth of its
 * transformed size each way (at least half a unit on symlog, a hair on
 * linear), so that the first frames do not zoom onto a single point, and is
 * then padded like any span; linear ends go to d3's nice steps for about 16
 * ticks, symlog ends stay as padded.
 */
export const PLANE_POLICY: PaddingPolicy = {
  zeroSpan: { halfWidth: (u, kind) => Math.max(Math.abs(u) * 0.1, kind === 'symlog' ? 0.5 : 1e-6), padded: true },
  linearNiceCount: 16,
  symlogRounding: 'none',
};

/** [lo, hi] padded by `headroom` of its span on each side under the plane's policy (see padAndRound). */
export function padInterval(lo: number, hi: number, headroom: number, kind: SignedKind = 'linear', c = 1): [number, number] {
  return padAndRound(lo, hi, { ...PLANE_POLICY, padding: headroom, kind, c });
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
