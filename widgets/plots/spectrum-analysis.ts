import { findPeaks, spectrum, type Peak, type Spectrum, type WindowName } from '../core/spectrum.ts';
import { dropLeakage } from './peak-filter.ts';

/** A spectrum and its strongest peaks. */
export interface Analysis {
  spectrum: Spectrum;
  /** strongest first, each refined on the windowed DTFT, leakage and trends dropped */
  peaks: Peak[];
}

/** Bins weaker than this fraction of the strongest are not looked at as peaks (−54 dB, below Hamming's sidelobes). */
const PEAK_FLOOR = 2e-3;
/** Extra candidates asked of findPeaks, so that some may be dropped as leakage. */
const SPARE = 4;

/**
 * The spectrum of `samples` taken every `interval` and its `wanted`
 * strongest peaks, which is what the spectrum view reads out.
 */
export function analyse(samples: Float64Array, interval: number, window: WindowName, wanted: number): Analysis {
  const s = spectrum(samples, interval, { window });
  let strongest = 0;
  for (let k = 1; k < s.amplitude.length; k++) if (s.amplitude[k] > strongest) strongest = s.amplitude[k];
  if (!(strongest > 0) || wanted <= 0) return { spectrum: s, peaks: [] };
  const found = findPeaks(s, { top: wanted + SPARE, refine: samples, minAmplitude: PEAK_FLOOR * strongest });
  return { spectrum: s, peaks: dropLeakage(found, samples.length * interval, window).slice(0, wanted) };
}

/** A theoretical frequency as the view's option gives it, with a label; undefined for none or a bad value. */
export function theoryOf(option: number | { frequency: number; label?: string } | undefined, format: (f: number) => string): { frequency: number; label: string } | undefined {
  if (option === undefined) return undefined;
  const frequency = typeof option === 'number' ? option : option.frequency;
  if (!(frequency > 0) || !Number.isFinite(frequency)) return undefined;
  const label = typeof option === 'number' || option.label === undefined ? `theory ${format(frequency)}` : option.label;
  return { frequency, label };
}
