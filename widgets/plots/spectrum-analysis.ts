import { findPeaks, type Peak, spectrum, type Spectrum, type WindowName } from '../core/index.ts';
import { dropLeakage } from './peak-filter.ts';
import { padFor } from './spectrum-scale.ts';

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
/** DTFT evaluations per refined peak: Brent's method has converged well before (see core/peaks.ts). */
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
