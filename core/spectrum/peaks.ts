import type { Spectrum } from './spectrum.ts';
import { checkWindowName, dtftPower, windowedDeviation, type WindowName } from './window.ts';

export interface Peak {
  /** Cycles per time unit. */
  frequency: number;
  /** In the spectrum's normalisation: a unit sinusoid reads 1. */
  amplitude: number;
}

export interface PeakOptions {
  /** How many peaks, strongest first; default 5. */
  top?: number;
  /** The samples the spectrum was computed from; when given, each peak is refined on the DTFT. */
  refine?: ArrayLike<number>;
  /** Window for the refinement; default the spectrum's own, so that both see the same sequence. */
  window?: WindowName;
  /** Bins weaker than this are not peaks (e.g. to drop the window's sidelobes); default 0. */
  minAmplitude?: number;
  /** Cap on DTFT evaluations per refined peak; default 40 (each costs O(N)). */
  evaluations?: number;
}

/**
 * The strongest local maxima of the amplitude, strongest first. DC is never a
 * peak (after mean removal it holds only leakage), and neither is Nyquist,
 * whose missing right neighbour leaves nothing to interpolate against.
 */
function strongestMaxima(a: Float64Array, top: number, floor: number): number[] {
  const best: number[] = []; // bin indices, amplitude descending, at most `top`
  if (top === 0) return best;
  for (let k = 1; k < a.length - 1; k++) {
    const ak = a[k];
    // `>=` on the right so that a flat top of two equal bins still counts once.
    if (!(ak > a[k - 1] && ak >= a[k + 1]) || ak < floor) continue;
    if (best.length === top) {
      if (ak <= a[best[top - 1]]) continue;
      best.pop();
    }
    let i = best.length;
    best.push(k);
    while (i > 0 && a[best[i - 1]] < ak) {
      best[i] = best[i - 1];
      i--;
    }
    best[i] = k;
  }
  return best;
}

/**
 * Parabola through bins k−1, k, k+1. For the Hamming window it is fitted to
 * log amplitude, because a Gaussian lobe is then exactly a parabola and the
 * Hamming main lobe is close to Gaussian: the frequency error is a few
 * hundredths of a bin. The rectangular window's lobe is a sinc whose zeros
 * can fall on the neighbours, where log would throw the vertex anywhere, so
 * there the parabola is fitted to the amplitude itself, which stays within
 * the bin.
 */
function interpolate(s: Spectrum, k: number): Peak {
  const a = s.amplitude;
  const shape = s.window === 'hamming' ? Math.log : (v: number) => v;
  const left = shape(a[k - 1]);
  const mid = shape(a[k]);
  const right = shape(a[k + 1]);
  const curvature = left - 2 * mid + right;
  // A zero neighbour (log = −∞) or a flat top has no usable parabola: keep the bin.
  if (!(curvature < 0) || !Number.isFinite(curvature)) {
    return { frequency: s.frequency[k], amplitude: a[k] };
  }
  const delta = (0.5 * (left - right)) / curvature;
  const vertex = mid - 0.25 * (left - right) * delta;
  return {
    frequency: (k + delta) * s.binWidth,
    amplitude: s.window === 'hamming' ? Math.exp(vertex) : vertex,
  };
}

const GOLDEN = (3 - Math.sqrt(5)) / 2;

/**
 * Local maxima examined at most, per peak asked for, when looking past
 * sidelobes: a rejected one costs three DTFT sums, O(N) each.
 */
const CANDIDATES_PER_PEAK = 12;

/**
 * Brent's method (Brent 1973, ch. 5) for the maximum of a unimodal g on
 * [lo, hi]: parabolic steps through the best three points, falling back to a
 * golden-section step whenever a parabola misbehaves. Parabolic steps are
 * what make it pay: near a smooth maximum it needs ~10 evaluations where
 * golden section alone needs ~40, and each evaluation here is O(N).
 */
function maximise(g: (u: number) => number, lo: number, hi: number, tol: number, evaluations: number): { x: number; value: number } {
  let a = lo;
  let b = hi;
  let x = a + GOLDEN * (b - a);
  let w = x;
  let v = x;
  let gx = g(x);
  let gw = gx;
  let gv = gx;
  let step = 0; // the last step taken
  let before = 0; // the step before it, which a parabolic step must beat by half
  for (let used = 1; used < evaluations; used++) {
    const mid = 0.5 * (a + b);
    const tol1 = tol + 1e-10 * Math.abs(x);
    if (Math.abs(x - mid) <= 2 * tol1 - 0.5 * (b - a)) break;
    let parabolic = false;
    if (Math.abs(before) > tol1) {
      // Vertex of the parabola through (x, gx), (w, gw), (v, gv), as x + p/q.
      const r = (x - w) * (gx - gv);
      let q = (x - v) * (gx - gw);
      let p = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0) p = -p; // make q ≥ 0 while keeping the vertex offset p/q
      else q = -q;
      if (Math.abs(p) < Math.abs(0.5 * q * before) && p > q * (a - x) && p < q * (b - x)) {
        before = step;
        step = p / q;
        if (x + step - a < 2 * tol1 || b - (x + step) < 2 * tol1) step = x < mid ? tol1 : -tol1;
        parabolic = true;
      }
    }
    if (!parabolic) {
      before = (x < mid ? b : a) - x;
      step = GOLDEN * before;
    }
    const u = x + (Math.abs(step) >= tol1 ? step : Math.sign(step) * tol1);
    const gu = g(u);
    if (gu >= gx) {
      if (u < x) b = x;
      else a = x;
      v = w; gv = gw;
      w = x; gw = gx;
      x = u; gx = gu;
    } else {
      if (u < x) a = u;
      else b = u;
      if (gu >= gw || w === x) {
        v = w; gv = gw;
        w = u; gw = gu;
      } else if (gu >= gv || v === x || v === w) {
        v = u; gv = gu;
      }
    }
  }
  return { x, value: gx };
}

/** Main-lobe half-width in bins of N: first zero of the window's transform. */
const LOBE: Record<WindowName, number> = { hamming: 2, none: 1 };

/**
 * Maximises |DTFT| near the interpolated frequency. The search stays within
 * the main lobe, where |DTFT| has a single maximum: ±1 bin, narrowed for
 * the rectangular window when the grid is no finer than N (its lobe is then
 * only ±1 bin wide, and the interpolated start may be up to half a bin off).
 */
function refine(y: Float64Array, weightSum: number, s: Spectrum, start: Peak, window: WindowName, evaluations: number): Peak {
  const lobe = (LOBE[window] * s.padded) / s.samples;
  const reach = Math.min(1, lobe - 0.5);
  const radiansPerBin = 2 * Math.PI * s.binWidth * s.interval;
  const theta0 = 2 * Math.PI * start.frequency * s.interval;
  const best = maximise((u) => dtftPower(y, theta0 + u * radiansPerBin), -reach, reach, 1e-6, evaluations);
  return {
    frequency: start.frequency + best.x * s.binWidth,
    amplitude: (2 * Math.sqrt(best.value)) / weightSum,
  };
}

/**
 * Whether a refined peak is a line rather than a sidelobe of the window. They
 * cannot be told apart by level (Hamming's sidelobes reach −43 dB, the
 * rectangular window's −13 dB), but they can by shape: half a bin from a
 * line the window's main lobe still holds 0.64 (rectangular) to 0.84
 * (Hamming) of the peak, while half a bin from a sidelobe's top lie its
 * nulls (Harris 1978). The bin here is 1/(N·Δ), the unpadded one.
 */
function isLine(y: Float64Array, s: Spectrum, peak: Peak): boolean {
  const theta = 2 * Math.PI * peak.frequency * s.interval;
  const half = Math.PI / s.samples;
  const top = dtftPower(y, theta);
  // Power ratio 0.09 is amplitude 0.3: far below any main lobe, far above a null.
  return dtftPower(y, theta - half) > 0.09 * top && dtftPower(y, theta + half) > 0.09 * top;
}

/**
 * The `top` strongest peaks of a spectrum, strongest first. Without `refine`
 * each peak is placed by interpolation between bins; with the original
 * samples, each is then moved to the maximum of the windowed DTFT itself,
 * which takes out the bin grid entirely (the scalloping loss in amplitude and
 * the interpolation bias in frequency), and the window's sidelobes are
 * recognised by their shape and skipped.
 */
export function findPeaks(s: Spectrum, options: PeakOptions = {}): Peak[] {
  const top = options.top ?? 5;
  if (!Number.isInteger(top) || top < 0) throw new Error(`findPeaks: top must be a whole number ≥ 0, got ${String(top)}`);
  const evaluations = options.evaluations ?? 40;
  if (!Number.isInteger(evaluations) || evaluations < 1) {
    throw new Error(`findPeaks: evaluations must be a whole number ≥ 1, got ${String(evaluations)}`);
  }
  const floor = options.minAmplitude ?? 0;
  const samples = options.refine;
  if (samples === undefined) return strongestMaxima(s.amplitude, top, floor).map((k) => interpolate(s, k));
  // With the samples at hand, sidelobes can be recognised and skipped, so look past them: a weak
  // harmonic may lie below dozens of the strong line's sidelobes (the README's 3ω at 0.4 % of ω).
  const peaks = strongestMaxima(s.amplitude, CANDIDATES_PER_PEAK * top + 12, floor).map((k) => interpolate(s, k));
  if (peaks.length === 0) return peaks;

  if (samples.length !== s.samples) {
    throw new Error(`findPeaks: refine has ${samples.length} samples but the spectrum was computed from ${s.samples}`);
  }
  const window = checkWindowName(options.window ?? s.window);
  const y = new Float64Array(samples.length);
  const weightSum = windowedDeviation(samples, window, y);
  const lines: Peak[] = [];
  for (const p of peaks) {
    // Strongest first: once `top` lines are found, no weaker candidate can displace one by more than refinement's shift.
    if (lines.length >= top + 2) break;
    // A sidelobe fails the shape test already at its interpolated place: three DTFT sums instead of a refinement's forty.
    if (!isLine(y, s, p)) continue;
    const r = refine(y, weightSum, s, p, window, evaluations);
    if (isLine(y, s, r) && !lines.some((l) => Math.abs(l.frequency - r.frequency) < 0.5 * s.binWidth)) lines.push(r);
  }
  return lines.sort((p, q) => q.amplitude - p.amplitude).slice(0, top);
}
