import { padAndRound, type PaddingPolicy } from '../extent.ts';
import { transform, type Domain, type SignedKind } from '../scale.ts';

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
 * The time plots' policy. A single value gets a fixed margin in place of
 * padding: a tenth of its size each way (1 at 0) on a linear axis, half a
 * transformed unit on symlog. Linear ends go to d3's nice steps for about 20
 * ticks, round ends that still hug the data (the axis picks its own, fewer,
 * ticks); symlog ends to the 1-2-5 ladder.
 */
export const AUTOSCALE_POLICY: PaddingPolicy = {
  zeroSpan: { halfWidth: (u, kind) => (kind === 'symlog' ? 0.5 : u === 0 ? 1 : Math.abs(u) * 0.1), padded: false },
  linearNiceCount: 20,
  symlogRounding: 'ladder',
};

/**
 * A range containing [lo, hi] padded by `padding` of its span, rounded
 * outward to round numbers, under AUTOSCALE_POLICY (see padAndRound, which
 * also keeps 0 as the floor of data all ≥ 0 and the ceiling of data all
 * ≤ 0). Empty or non-finite data gives [−1, 1]; a single value v gives a
 * range around v.
 */
export function fit(lo: number, hi: number, kind: SignedKind, padding = FIT_PADDING): Domain {
  // before any data (or with a NaN in it) the plot still needs some range to draw its axes on
  if (!Number.isFinite(lo) || !Number.isFinite(hi) || lo > hi) return [-1, 1];
  // the time plots' symlog is the paper's ln(1 + |y|): constant c = 1
  return padAndRound(lo, hi, { ...AUTOSCALE_POLICY, padding, kind, c: 1 });
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

/**
 * A settled plot fits its data again once their fitted range is under this share of the range shown. Growth
 * leaves headroom on the side that grew, and how much depends on how the first frames cut the data (a busy
 * machine draws fewer, larger chunks): at 0.8, the nonlinear oscillator's q in [−0.96, 1] could stay on
 * [−1, 1.7], a quarter of it empty, where a quiet machine showed [−1.1, 1.1]. At 0.9 a settled plot leaves at
 * most a tenth empty beyond its fit's padding, and a fit that is already snug is still left alone.
 */
export const SETTLE_RATIO = 0.9;

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
