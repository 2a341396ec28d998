/**
 * The frequency domain of a sampled series, as in the paper's §3.4 and §5.2:
 * the series minus its mean, weighted by the Hamming window of eq. 6, then
 * Fourier transformed.
 *
 * Why zero-padding to a power of two rather than Bluestein's algorithm for
 * arbitrary N: the zero-padded FFT samples the same windowed DTFT exactly,
 * only on a finer grid, so nothing is approximated; it keeps fft.js's
 * radix-4 speed, whereas Bluestein over fft.js measured 16× slower than
 * numpy; and the grid's only effect (where the bins fall) is removed by the
 * peak refinement in `peaks.ts`.
 */

import FFT from 'fft.js';
import { checkWindowName, windowedDeviation, type WindowName } from './window.ts';


export interface SpectrumOptions {
  /** Default 'hamming' (the paper's choice). */
  window?: WindowName;
  /** Extra zero-padding factor, a power of two; default 1. Larger gives a finer bin grid, not more resolution. */
  pad?: number;
}

export interface Spectrum {
  /** f_k = k/(M·Δ), cycles per time unit, k = 0..M/2. */
  frequency: Float64Array;
  /** One-sided: 2·|X_k| / Σ W_j (DC and Nyquist not doubled), so A·cos(2πft + φ) reads A. */
  amplitude: Float64Array;
  /** Re X_k with the amplitude's normalisation; phase is referred to the first sample. */
  re: Float64Array;
  /** Im X_k with the amplitude's normalisation (X_k = Σ y_j e^{−2πi jk/M}). */
  im: Float64Array;
  /** N */
  samples: number;
  /** M, the padded length: a power of two ≥ N, times `pad`. */
  padded: number;
  /** Δ, the time between samples. */
  interval: number;
  /** 1/(M·Δ) */
  binWidth: number;
  /** The window applied, so that peak refinement can apply the same one. */
  window: WindowName;
}

/** fft.js is untyped; this is the slice of it used here, with the buffer types it accepts. */
interface RealFFT {
  realTransform(out: Float64Array, data: Float64Array): void;
}

interface Plan {
  readonly fft: RealFFT;
  /** The padded real input, length M; its tail stays zero between uses. */
  readonly input: Float64Array;
  /** Interleaved complex output, length 2M; fft.js fills bins 0..M/2 only. */
  readonly output: Float64Array;
}

/**
 * FFT tables and work buffers per padded size: building them costs more than
 * a transform, and a live widget transforms the same size over and over.
 * Bounded because a size of 2^20 holds 24 MB of buffers.
 */
const plans = new Map<number, Plan>();
const PLAN_LIMIT = 6;

function plan(m: number): Plan {
  const cached = plans.get(m);
  if (cached) return cached;
  const made: Plan = {
    fft: new FFT(m) as RealFFT,
    input: new Float64Array(m),
    output: new Float64Array(2 * m),
  };
  if (plans.size >= PLAN_LIMIT) {
    const oldest = plans.keys().next();
    if (!oldest.done) plans.delete(oldest.value);
  }
  plans.set(m, made);
  return made;
}

/** Throws a one-line message a caller can show as is. */
function checkInput(samples: ArrayLike<number>, interval: number, pad: number): void {
  if (samples == null || typeof samples.length !== 'number' || samples.length < 2) {
    throw new Error('spectrum: need at least 2 samples');
  }
  if (typeof interval !== 'number' || !Number.isFinite(interval) || interval <= 0) {
    throw new Error(`spectrum: the sampling interval must be a finite positive number, got ${String(interval)}`);
  }
  if (!Number.isInteger(pad) || pad < 1 || (pad & (pad - 1)) !== 0 || pad > 1 << 20) {
    throw new Error(`spectrum: pad must be a power of two (1, 2, 4, …), got ${String(pad)}`);
  }
}

/** The smallest power of two ≥ n. */
function nextPowerOfTwo(n: number): number {
  let m = 2;
  while (m < n) m *= 2;
  return m;
}

/**
 * The one-sided spectrum of `samples` taken every `interval` time units.
 * Returns fresh arrays (the caller may keep them); only the work buffers are
 * shared between calls.
 */
export function spectrum(
  samples: ArrayLike<number>,
  interval: number,
  options: SpectrumOptions = {},
): Spectrum {
  const pad = options.pad ?? 1;
  checkInput(samples, interval, pad);
  const window = checkWindowName(options.window ?? 'hamming');
  const n = samples.length;
  const m = nextPowerOfTwo(n) * pad;
  const { fft, input, output } = plan(m);

  const weightSum = windowedDeviation(samples, window, input);
  input.fill(0, n); // a previous, longer series of the same padded size may have left data here
  fft.realTransform(output, input);

  const half = m / 2;
  const binWidth = 1 / (m * interval);
  const frequency = new Float64Array(half + 1);
  const amplitude = new Float64Array(half + 1);
  const re = new Float64Array(half + 1);
  const im = new Float64Array(half + 1);
  const twoSided = 2 / weightSum;
  for (let k = 0; k <= half; k++) {
    // DC and Nyquist have no mirror image in the discarded half, so they are not doubled.
    const scale = k === 0 || k === half ? twoSided / 2 : twoSided;
    const a = output[2 * k] * scale;
    const b = output[2 * k + 1] * scale;
    frequency[k] = k * binWidth;
    re[k] = a;
    im[k] = b;
    amplitude[k] = Math.sqrt(a * a + b * b); // not Math.hypot: several times slower in V8, and no overflow is possible here
  }
  return { frequency, amplitude, re, im, samples: n, padded: m, interval, binWidth, window };
}
