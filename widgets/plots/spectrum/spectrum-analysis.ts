import { findPeaks, type Peak, type Spectrum, spectrum, type WindowName } from '../../../core/index.ts';

/** A spectrum and its strongest peaks. */
export interface Analysis {
  spectrum: Spectrum;
  /** strongest first, each refined on the windowed DTFT, leakage and trends dropped */
  peaks: Peak[];
}

/** Bins weaker than this fraction of the strongest are not looked at as peaks (−54 dB, below Hamming's sidelobes). */
const PEAK_FLOOR = 2e-3;
/**
 * Zero-padding of the spectrum searched for peaks. On the plain grid a weak
 * peak on the flank of a strong one, two or three bins away, need not be a
 * local maximum of the bins (Kepler's 2f over the first orbits is missed);
 * four points per resolution bin find it, and refinement does the rest.
 */
const SEARCH_PAD = 4;
/** DTFT evaluations per refined peak: Brent's method has converged well before (see core/spectrum/peaks.ts). */
const EVALUATIONS = 24;
/** Extra candidates asked of findPeaks, so that some may be dropped as leakage. */
const SPARE = 4;

/**
 * The spectrum of `samples` taken every `interval` and its `wanted`
 * strongest peaks, which is what the spectrum view reads out.
 */
export function analyse(samples: Float64Array, interval: number, window: WindowName, wanted: number): Analysis {
  const s = spectrum(samples, interval, { window, pad: SEARCH_PAD });
  let strongest = 0;
  for (let k = 1; k < s.amplitude.length; k++) if (s.amplitude[k] > strongest) strongest = s.amplitude[k];
  if (!(strongest > 0) || wanted <= 0) return { spectrum: s, peaks: [] };
  const duration = samples.length * interval;
  const floor = PEAK_FLOOR * strongest;
  // Refining costs O(N) per evaluation, so only as many candidates as the leakage test keeps are refined.
  const rough = findPeaks(s, { top: wanted + SPARE, minAmplitude: floor });
  const kept = dropLeakage(rough, duration, window).slice(0, wanted);
  if (kept.length === 0) return { spectrum: s, peaks: [] };
  const top = rough.indexOf(kept[kept.length - 1]) + 1;
  const refined = findPeaks(s, { top, refine: samples, minAmplitude: floor, evaluations: EVALUATIONS });
  return { spectrum: s, peaks: dropLeakage(refined, duration, window).slice(0, wanted) };
}

/** A theoretical frequency as the view's option gives it, with a label; undefined for none or a bad value. */
export function theoryOf(option: number | { frequency: number; label?: string } | undefined, format: (f: number) => string): { frequency: number; label: string } | undefined {
  if (option === undefined) return undefined;
  const frequency = typeof option === 'number' ? option : option.frequency;
  if (!(frequency > 0) || !Number.isFinite(frequency)) return undefined;
  const label = typeof option === 'number' || option.label === undefined ? `theory ${format(frequency)}` : option.label;
  return { frequency, label };
}

/** The display keeps at least this many times maxFrequency below its Nyquist frequency. */
const DISPLAY_HEADROOM = 16;

/**
 * The spectrum as drawn up to `maxFrequency`: the same windowed transform,
 * but of block means of D samples, where D leaves the Nyquist frequency at
 * least 16× above the axis's end, then zero-padded so the visible part has a
 * few hundred bins. Drawing only needs the low end, and transforming the
 * full series padded that finely costs ten times as much (a 2^18-point FFT
 * where 2^14 does). A block mean is a slight low-pass (−0.2% at the axis's
 * end) and stands for the middle of its block, so Re and Im are turned back
 * by that half-block delay to stay referred to the first sample (up to
 * maxFrequency: bins past the axis keep the block-referred phase).
 */
export function displaySpectrum(samples: Float64Array, interval: number, window: WindowName, maxFrequency: number): Spectrum {
  const n = samples.length;
  const d = Math.max(1, Math.min(Math.floor(n / 64), Math.floor(0.5 / interval / (DISPLAY_HEADROOM * maxFrequency))));
  let y = samples;
  let delay = 0;
  if (d > 1) {
    const m = Math.floor(n / d);
    const start = n - m * d;
    y = new Float64Array(m);
    for (let k = 0; k < m; k++) {
      let sum = 0;
      for (let j = start + k * d, end = j + d; j < end; j++) sum += samples[j];
      y[k] = sum / d;
    }
    delay = (start + (d - 1) / 2) * interval;
  }
  const coarse = spectrum(y, interval * d, { window });
  const pad = padFor(coarse, maxFrequency);
  const s = pad > 1 ? spectrum(y, interval * d, { window, pad }) : coarse;
  if (delay > 0) {
    const end = Math.min(s.frequency.length, Math.ceil(maxFrequency / s.binWidth) + 2);
    for (let k = 0; k < end; k++) {
      // X(f) referred to the first sample is e^{−2πifτ} times X referred to the first block's middle
      const phi = 2 * Math.PI * s.frequency[k] * delay;
      const c = Math.cos(phi);
      const sn = Math.sin(phi);
      const re = s.re[k];
      s.re[k] = re * c + s.im[k] * sn;
      s.im[k] = s.im[k] * c - re * sn;
    }
  }
  return s;
}

/**
 * Highest sidelobe of each window relative to its main lobe: the exact
 * Hamming window's sidelobes stay below −42.5 dB (0.0075) everywhere; the
 * rectangular window's fall off as 1/(π·m) at m resolution bins away.
 */
function sidelobe(window: WindowName, bins: number): number {
  if (window === 'hamming') return 0.0085;
  return Math.min(0.25, 1.25 / (Math.PI * Math.max(1, bins)));
}

const TREND_BINS = 1.5;

/**
 * Drops peaks that are no more than a sidelobe of a stronger peak: local
 * maxima of leakage rather than motion. `peaks` must be strongest first, as
 * findPeaks returns them; `duration` is the time the spectrum covers, so
 * that 1/duration is one resolution bin. Peaks within TREND_BINS of zero
 * frequency go too.
 */
export function dropLeakage(peaks: readonly Peak[], duration: number, window: WindowName): Peak[] {
  const kept: Peak[] = [];
  for (const p of peaks) {
    // Below one and a half resolution bins a "peak" is a trend over the window, not an oscillation.
    if (p.frequency * duration < TREND_BINS) continue;
    const leak = kept.some((s) => p.amplitude < s.amplitude * sidelobe(window, Math.abs(p.frequency - s.frequency) * duration));
    if (!leak) kept.push(p);
  }
  return kept;
}

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
