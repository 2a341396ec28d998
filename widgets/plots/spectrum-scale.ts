import type { Peak, Spectrum } from '../core/index.ts';

/** The smallest of 1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8 × 10^k that is ≥ v. */
export function niceCeil(v: number): number {
  if (!(v > 0) || !Number.isFinite(v)) return 1;
  const decade = 10 ** Math.floor(Math.log10(v));
  for (const m of [1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10]) if (m * decade >= v * (1 - 1e-12)) return m * decade;
  return 10 * decade;
}

/**
 * The upper end of the frequency axis when the chapter does not fix it. As
 * the paper's §5.2 says, the interesting part of a spectrum is usually the
 * low frequencies, so the axis reaches a little past the significant peaks
 * (those of at least 2% of the strongest) and the theoretical marker, to at
 * least 2.5× the strongest peak, on a round number, and never past Nyquist.
 * With no peaks it shows the marker, or forty resolution bins 1/duration.
 * It keeps `current` while that still shows everything without wasting more
 * than 60% of the width, so the axis does not twitch at each recompute.
 */
export function chooseMaxFrequency(peaks: readonly Peak[], nyquist: number, theory: number | undefined, current: number | undefined, duration?: number): number {
  // With no peak yet, about forty resolution bins: where the first peak will appear once the window holds a period or two.
  let target = duration !== undefined && duration > 0 ? Math.min(nyquist, 40 / duration) : nyquist;
  if (peaks.length > 0) {
    const strongest = peaks[0];
    let highest = strongest.frequency;
    for (const p of peaks) if (p.amplitude >= 0.02 * strongest.amplitude && p.frequency > highest) highest = p.frequency;
    target = Math.max(2.5 * strongest.frequency, 1.4 * highest);
  }
  if (theory !== undefined && theory > 0) target = peaks.length ? Math.max(target, 1.3 * theory) : 2.5 * theory;
  target = Math.min(nyquist, niceCeil(target));
  if (current !== undefined && current >= target && current <= 2.5 * target && current <= nyquist) return current;
  return target;
}

/** Room above the tallest line for the peak marks and the marker's label. */
const HEADROOM = 1.3;

/**
 * An axis limit that follows `value` up at once but comes down only when
 * `value` falls below half of it, so the plot does not rescale at every
 * recompute of a slowly varying spectrum.
 */
export function steadyLimit(value: number, current: number | undefined): number {
  const wanted = value > 0 && Number.isFinite(value) ? value * HEADROOM : 1;
  if (current === undefined || wanted > current || wanted < 0.5 * current) return niceCeil(wanted);
  return current;
}

/** Bins wanted on the visible frequency axis, and the largest padded FFT made to get them. */
const SMOOTH_BINS = 320;
const MAX_PADDED = 1 << 18;

/** The zero-padding factor (a power of two) that puts about SMOOTH_BINS bins below maxFrequency. */
export function padFor(s: Pick<Spectrum, 'binWidth' | 'padded'>, maxFrequency: number): number {
  let pad = 1;
  while (maxFrequency / (s.binWidth / pad) < SMOOTH_BINS && s.padded * pad * 2 <= MAX_PADDED) pad *= 2;
  return pad;
}

/** The largest value drawn in bins 1 … end: |X|, and |Re X|, |Im X| too when they are shown (DC is left out: the mean was removed). */
export function largestShown(s: Pick<Spectrum, 'amplitude' | 're' | 'im'>, reim: boolean, end: number): number {
  let m = 0;
  const last = Math.min(end, s.amplitude.length - 1);
  for (let k = 1; k <= last; k++) {
    if (s.amplitude[k] > m) m = s.amplitude[k];
    if (reim) m = Math.max(m, Math.abs(s.re[k]), Math.abs(s.im[k]));
  }
  return m;
}
