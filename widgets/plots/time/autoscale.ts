import { scaleLinear, transform, untransform, type Domain, type SignedKind } from '../scale.ts';

/**
 * The y range of a plot that fits its data. A running plot only grows its
 * range (grow), with headroom so that a steadily growing amplitude, like the
 * exponential one of parametric resonance, triggers a redraw only every so
 * often rather than every frame; the Refit button shrinks it again (fit).
 */

/** Headroom added on growth, as a fraction of the span (in transformed units for symlog). */
export const GROWTH_HEADROOM = 0.25;
/** Padding of a fitted range. */
export const FIT_PADDING = 0.05;

/**
 * A range containing [lo, hi] padded by `padding` of its span, rounded
 * outward to round numbers. Empty or non-finite data gives [−1, 1]; a single
 * value v gives a range around v. Padding never crosses zero: data that are
 * all ≥ 0 (a distance, an energy, a count) keep 0 as the floor, and data
 * all ≤ 0 keep it as the ceiling.
 */
export function fit(lo: number, hi: number, kind: SignedKind, padding = FIT_PADDING): Domain {
  if (!Number.isFinite(lo) || !Number.isFinite(hi) || lo > hi) return [-1, 1];
  const floor = (padded: number) => (lo >= 0 && hi > 0 ? Math.max(0, padded) : padded);
  const ceiling = (padded: number) => (hi <= 0 && lo < 0 ? Math.min(0, padded) : padded);
  if (kind === 'symlog') {
    let u0 = transform('symlog', lo);
    let u1 = transform('symlog', hi);
    const pad = u1 > u0 ? (u1 - u0) * padding : 0.5;
    u0 -= pad;
    u1 += pad;
    return [roundOutward(floor(untransform('symlog', u0)), -1), roundOutward(ceiling(untransform('symlog', u1)), 1)];
  }
  if (lo === hi) {
    const half = lo === 0 ? 1 : Math.abs(lo) * 0.1;
    return niceLinear(lo - half, hi + half);
  }
  const pad = (hi - lo) * padding;
  return niceLinear(floor(lo - pad), ceiling(hi + pad));
}

/**
 * The range grown to contain [lo, hi] with headroom, or null when `domain`
 * already contains it (the common case, so the caller redraws nothing).
 */
export function grow(domain: Domain, lo: number, hi: number, kind: SignedKind): Domain | null {
  if (!(lo < domain[0]) && !(hi > domain[1])) return null;
  if (!Number.isFinite(lo) || !Number.isFinite(hi)) return null;
  return fit(Math.min(lo, domain[0]), Math.max(hi, domain[1]), kind, GROWTH_HEADROOM);
}

/** Rounded outward on d3's nice steps for about 20 ticks: round ends that still hug the data (the axis picks its own, fewer, ticks). */
function niceLinear(lo: number, hi: number): Domain {
  const [a, b] = scaleLinear().domain([lo, hi]).nice(20).domain();
  return [a, b];
}

/** How much of a range the data may leave empty before a settled plot fits it again. */
export const SETTLE_RATIO = 0.8;

/**
 * The fitted range of data [lo, hi] when it is much tighter than `domain`
 * (its span, in the axis's own units, under SETTLE_RATIO of the domain's),
 * else null: growth leaves headroom, and once the data have stopped
 * growing the plot hugs them again.
 */
export function settle(domain: Domain, lo: number, hi: number, kind: SignedKind): Domain | null {
  if (!(lo <= hi) || !Number.isFinite(lo) || !Number.isFinite(hi)) return null;
  const tight = fit(lo, hi, kind);
  const t = (v: number) => transform(kind, v);
  return t(tight[1]) - t(tight[0]) < SETTLE_RATIO * (t(domain[1]) - t(domain[0])) ? tight : null;
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

/** Smallest and largest finite value of a list, as [lo, hi]; [Infinity, −Infinity] when there is none. */
export function extent(values: ArrayLike<number>): [number, number] {
  let lo = Infinity;
  let hi = -Infinity;
  for (let i = 0; i < values.length; i++) {
    const v = values[i];
    if (v - v !== 0) continue; // NaN or ±Infinity
    if (v < lo) lo = v;
    if (v > hi) hi = v;
  }
  return [lo, hi];
}
