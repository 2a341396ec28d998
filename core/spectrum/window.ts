/**
 * Spectral windows, and the windowed, mean-removed series that both the FFT
 * (`spectrum.ts`) and the peak refinement (`peaks.ts`) transform, with its
 * DTFT at any frequency. Keeping the preparation in one place guarantees that
 * the refinement maximises the DTFT of exactly the sequence whose FFT it
 * started from.
 */

export type WindowName = 'hamming' | 'none';

/**
 * Hamming's exact coefficients 25/46 and 21/46 (the paper's eq. 6), not the
 * rounded 0.54/0.46: the exact pair cancels the first sidelobe, so far
 * leakage onto weak peaks is lower.
 */
const HAMMING_A = 25 / 46;
const HAMMING_B = 21 / 46;

/** The Hamming window of the paper's eq. 6, W(ζ) = 25/46 − 21/46·cos 2πζ, on ζ ∈ [0, 1). */
export function hamming(zeta: number): number {
  return HAMMING_A - HAMMING_B * Math.cos(2 * Math.PI * zeta);
}

/** Throws unless `name` is a window this module knows; callers may pass unchecked strings. */
export function checkWindowName(name: unknown): WindowName {
  if (name === 'hamming' || name === 'none') return name;
  throw new Error(`spectrum: unknown window ${JSON.stringify(name)}; use 'hamming' or 'none'`);
}

interface Weights {
  readonly values: Float64Array;
  readonly sum: number;
}

/**
 * Weights are cached because a widget recomputes the spectrum of a series of
 * the same length many times; a handful of lengths is enough, and the bound
 * keeps a long session from holding every length it ever saw.
 */
const weightCache = new Map<string, Weights>();
const WEIGHT_CACHE_LIMIT = 8;

/**
 * W_j = W(j/N) for j = 0..N−1: the periodic sampling of eq. 6, whose DFT has
 * just three non-zero bins, so an on-bin tone reads exactly 1 with its
 * neighbours at 21/50.
 */
function weights(name: WindowName, n: number): Weights {
  const key = `${name}:${n}`;
  const cached = weightCache.get(key);
  if (cached) return cached;
  const values = new Float64Array(n);
  let sum = 0;
  if (name === 'none') {
    values.fill(1);
    sum = n;
  } else {
    for (let j = 0; j < n; j++) {
      const w = hamming(j / n);
      values[j] = w;
      sum += w;
    }
  }
  const made = { values, sum };
  if (weightCache.size >= WEIGHT_CACHE_LIMIT) {
    const oldest = weightCache.keys().next();
    if (!oldest.done) weightCache.delete(oldest.value);
  }
  weightCache.set(key, made);
  return made;
}

/** Names the first bad sample; all finite means the sum itself overflowed. */
function nonFiniteMessage(samples: ArrayLike<number>): string {
  for (let j = 0; j < samples.length; j++) {
    const x = samples[j];
    if (!Number.isFinite(x)) return `spectrum: sample ${j} is ${String(x)}; every sample must be a finite number`;
  }
  return 'spectrum: the samples are too large to sum (beyond ±1.8e308)';
}

/**
 * Writes y_j = W_j·(x_j − x̄) into `out[0..N)` and returns Σ W_j, the
 * normalisation that makes a unit sinusoid read 1. The mean goes first so
 * that an offset, which can dwarf the oscillation, does not leak from the DC
 * bin across the window's sidelobes onto low-frequency peaks. Throws on the
 * first non-finite sample, naming it, because one NaN would silently blank
 * the whole spectrum.
 */
export function windowedDeviation(
  samples: ArrayLike<number>,
  name: WindowName,
  out: Float64Array,
): number {
  const n = samples.length;
  let total = 0;
  for (let j = 0; j < n; j++) total += samples[j];
  // Any NaN or ±∞ makes the sum non-finite, so the per-sample search runs only
  // on bad input: a check inside the loop above doubled the cost of this function.
  if (!Number.isFinite(total)) throw new Error(nonFiniteMessage(samples));
  const mean = total / n;
  const { values, sum } = weights(name, n);
  for (let j = 0; j < n; j++) out[j] = values[j] * (samples[j] - mean);
  return sum;
}

const BLOCK = 512;

/**
 * |Σ y_j e^{−iθj}|², the windowed DTFT's power at θ radians per sample. The
 * rotor e^{−iθj} advances by complex multiplication (no trig in the loop)
 * and is reset from cos/sin every BLOCK samples, which bounds the drift of
 * the recurrence to BLOCK roundings whatever N is.
 */
export function dtftPower(y: Float64Array, theta: number): number {
  const n = y.length;
  const c = Math.cos(theta);
  const s = Math.sin(theta);
  let re = 0;
  let im = 0;
  for (let start = 0; start < n; start += BLOCK) {
    let zr = Math.cos(theta * start);
    let zi = -Math.sin(theta * start);
    const end = Math.min(start + BLOCK, n);
    for (let j = start; j < end; j++) {
      re += y[j] * zr;
      im += y[j] * zi;
      const next = zr * c + zi * s; // z ← z·e^{−iθ}
      zi = zi * c - zr * s;
      zr = next;
    }
  }
  return re * re + im * im;
}
