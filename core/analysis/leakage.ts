/**
 * How far a refined spectral peak can sit from the true frequency of its
 * line: the measurement error of a frequency read off a windowed spectrum
 * (spectrum.ts, peaks.ts), for the chapters' theory checks.
 *
 * A record of length T = NΔ holds lines A_k cos(2πf_k t + φ_k). Each line is
 * two complex components, of size A_k/2 at ±f_k, and the windowed transform
 * near f is Σ (A_k/2) e^{iψ_k} W((f ∓ f_k)T), with W the window's transform
 * in bins, real and even up to a common phase. The maximum of |X|² near the
 * line at f is pulled by every other component through the slope of its
 * window response there. To first order in that pull,
 *
 *   δf = −Σ r_k cos ψ_k W'(Δν_k) / (W''(0) T),   r_k = A_k / A,
 *
 * and since the phases ψ_k are unknown, |cos ψ_k| ≤ 1 bounds it. The sum runs
 * over the other lines, the mirror images at −f_k of all of them, and the
 * line's own mirror at −f (Harris 1978 treats the same leakage). This needs
 * the other components to lie outside the main lobe, where W' is small; a
 * line closer than that is not resolved, and the bound says so.
 *
 * The refinement itself stops within 2·10⁻⁶ of a (padded) bin of the
 * maximum (Brent's tolerance in peaks.ts): the resolution term.
 */
import type { Peak } from '../spectrum/peaks.ts';
import type { Spectrum } from '../spectrum/spectrum.ts';

export interface PeakError {
  /** bound on the pull of the other lines and the mirrors, cycles per time unit */
  leakage: number;
  /** the refinement's stopping tolerance, cycles per time unit */
  resolution: number;
  /** leakage + resolution */
  bound: number;
  /** the bound in bins of 1/T, the record's resolution */
  bins: number;
  /** distance in bins to the nearest other component (line or mirror image) */
  closest: number;
  /**
   * Whether every other component found lies outside the main lobe, as the
   * first-order bound needs. (Two lines closer than the lobe merge into one
   * peak, and the second is then not in the list at all: a peak list cannot
   * show it.)
   */
  resolved: boolean;
}

/** sin(πx)/(πx) and its derivative, with their limits near 0. */
const sinc = (x: number) => (Math.abs(x) < 1e-6 ? 1 - (Math.PI * x) ** 2 / 6 : Math.sin(Math.PI * x) / (Math.PI * x));
const sincSlope = (x: number) =>
  Math.abs(x) < 1e-4 ? (-(Math.PI ** 2) * x) / 3 : (Math.PI * x * Math.cos(Math.PI * x) - Math.sin(Math.PI * x)) / (Math.PI * x * x);

/**
 * The window's transform in bins, as the continuous window w(x) on [0, 1]
 * gives it (close to the sampled window's for lines well below Nyquist):
 * for Hamming, w = a − b cos 2πx gives a·sinc(ν) + (b/2)(sinc(ν − 1) + sinc(ν + 1)).
 */
const WINDOWS = {
  hamming: { a: 25 / 46, b: 21 / 46, lobe: 2 },
  none: { a: 1, b: 0, lobe: 1 },
} as const;

function transform(window: Spectrum['window']) {
  const { a, b, lobe } = WINDOWS[window];
  const slope = (v: number) => (a * sincSlope(v) + (b / 2) * (sincSlope(v - 1) + sincSlope(v + 1))) / a;
  // W''(0)/W(0): sinc''(0) = −π²/3 and sinc''(±1) = 2.
  const curvature = Math.abs((a * (-(Math.PI ** 2) / 3) + (b / 2) * 4) / a);
  return { slope, curvature, lobe };
}

/**
 * The largest |W'| within half a bin of ν: the exact Δν is known only as well
 * as the peaks themselves, and a zero of W' there must not hide a pull.
 */
function slopeEnvelope(slope: (v: number) => number, v: number): number {
  let most = 0;
  for (let i = -10; i <= 10; i++) most = Math.max(most, Math.abs(slope(v + i / 20)));
  return most;
}

/** Bin-width fraction within which peaks.ts's refinement stops: 2 × its Brent tolerance of 1e-6 bins. */
const REFINE_TOLERANCE = 2e-6;

/**
 * The error of `line`'s refined frequency, given the other `lines` found in
 * the same spectrum `s` (findPeaks' output; `line` may be among them).
 */
export function peakError(s: Pick<Spectrum, 'samples' | 'interval' | 'binWidth' | 'window'>, lines: readonly Peak[], line: Peak): PeakError {
  const T = s.samples * s.interval;
  const { slope, curvature, lobe } = transform(s.window);
  let pull = 0;
  let closest = Infinity;
  const add = (ratio: number, bins: number) => {
    closest = Math.min(closest, Math.abs(bins));
    pull += ratio * slopeEnvelope(slope, Math.abs(bins));
  };
  for (const other of lines) {
    const ratio = other.amplitude / line.amplitude;
    if (other !== line && other.frequency !== line.frequency) add(ratio, (line.frequency - other.frequency) * T);
    add(ratio, (line.frequency + other.frequency) * T);
  }
  if (!lines.includes(line)) add(1, 2 * line.frequency * T);
  const leakage = pull / (curvature * T);
  const resolution = REFINE_TOLERANCE * s.binWidth;
  const bound = leakage + resolution;
  return { leakage, resolution, bound, bins: bound * T, closest, resolved: closest >= lobe };
}
