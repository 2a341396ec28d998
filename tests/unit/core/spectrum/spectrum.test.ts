import { describe, it, expect } from 'vitest';
import { findPeaks, hamming, spectrum, type WindowName } from '../../../../core/index.ts';

// ---- Independent reference implementations (written from the definitions, not from the code) ----

/** The paper's eq. 6, typed in again here so that the module's own hamming() is not its own reference. */
const eq6 = (zeta: number): number => 25 / 46 - (21 / 46) * Math.cos(2 * Math.PI * zeta);
const rectangular = (): number => 1;
const windowFunction = (name: WindowName) => (name === 'hamming' ? eq6 : rectangular);

interface Tone {
  f: number;
  amp: number;
  phi: number;
}

/** x_j = offset + Σ A·cos(2πf·jΔ + φ). */
function tones(n: number, dt: number, parts: Tone[], offset = 0): Float64Array {
  const x = new Float64Array(n);
  for (let j = 0; j < n; j++) {
    let v = offset;
    for (const { f, amp, phi } of parts) v += amp * Math.cos(2 * Math.PI * f * j * dt + phi);
    x[j] = v;
  }
  return x;
}

/** y_j = W(j/N)·(x_j − x̄) and Σ W(j/N), straight from the definition. */
function windowed(x: ArrayLike<number>, name: WindowName): { y: number[]; sum: number } {
  const n = x.length;
  let mean = 0;
  for (let j = 0; j < n; j++) mean += x[j] / n;
  const w = windowFunction(name);
  const y: number[] = [];
  let sum = 0;
  for (let j = 0; j < n; j++) {
    y.push(w(j / n) * (x[j] - mean));
    sum += w(j / n);
  }
  return { y, sum };
}

/** O(N·M) DFT of the zero-padded windowed series, bins 0..M/2, one-sided normalisation 2/ΣW (DC, Nyquist ×1). */
function naiveSpectrum(x: ArrayLike<number>, m: number, name: WindowName) {
  const { y, sum } = windowed(x, name);
  const re: number[] = [];
  const im: number[] = [];
  for (let k = 0; k <= m / 2; k++) {
    let a = 0;
    let b = 0;
    for (let j = 0; j < y.length; j++) {
      const angle = (2 * Math.PI * ((j * k) % m)) / m;
      a += y[j] * Math.cos(angle);
      b -= y[j] * Math.sin(angle);
    }
    const scale = k === 0 || k === m / 2 ? 1 / sum : 2 / sum;
    re.push(a * scale);
    im.push(b * scale);
  }
  return { re, im };
}

/** One-sided amplitude of the windowed DTFT at frequency f, by direct summation. */
function naiveDtftAmplitude(x: ArrayLike<number>, dt: number, f: number, name: WindowName): number {
  const { y, sum } = windowed(x, name);
  let a = 0;
  let b = 0;
  for (let j = 0; j < y.length; j++) {
    a += y[j] * Math.cos(2 * Math.PI * f * j * dt);
    b -= y[j] * Math.sin(2 * Math.PI * f * j * dt);
  }
  return (2 * Math.hypot(a, b)) / sum;
}

/**
 * Hamming worst-case scalloping loss: 1.78 dB (Harris 1978, "On the use of
 * windows…", Proc. IEEE 66, Table 1), i.e. a peak bin reads ≥ 10^(−1.78/20)
 * ≈ 0.815 of the true amplitude; 0.81 leaves room for finite-N effects.
 * Zero-padding only makes the grid finer, so it can only reduce the loss.
 */
const SCALLOP_FLOOR = 0.81;

describe('hamming(zeta)', () => {
  it('hamming(zeta) matches eq. 6 at ζ = 0, 1/4, 1/2', () => {
    // Eq. 6: W(0) = 25/46 − 21/46 = 4/46; W(1/4) = 25/46 (cos = 0); W(1/2) = 25/46 + 21/46 = 1.
    expect(hamming(0)).toBeCloseTo(4 / 46, 15);
    expect(hamming(0.25)).toBeCloseTo(25 / 46, 15);
    expect(hamming(0.5)).toBeCloseTo(1, 15);
  });
});

describe('spectrum(samples, interval, options)', () => {
  it('spectrum(samples, interval, { window, pad }) equals a naive O(N²) DFT at small N', () => {
    // Reference: the DFT definition X_k = Σ y_j e^{−2πi jk/M}, evaluated directly (naiveSpectrum above).
    let seed = 12345;
    const random = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648) * 2 - 1;
    // Longest first: 12 reuses the work buffers 16 left behind (same M), which must not leak into it.
    for (const n of [16, 12, 5, 2]) {
      const x = Array.from({ length: n }, random);
      for (const window of ['hamming', 'none'] as const) {
        for (const pad of [1, 4]) {
          const dt = 0.1;
          const s = spectrum(x, dt, { window, pad });
          let m = 2;
          while (m < n) m *= 2;
          m *= pad;
          expect(s.padded).toBe(m);
          expect(s.samples).toBe(n);
          expect(s.interval).toBe(dt);
          expect(s.binWidth).toBeCloseTo(1 / (m * dt), 14);
          const ref = naiveSpectrum(x, m, window);
          expect(s.re.length).toBe(m / 2 + 1);
          for (let k = 0; k <= m / 2; k++) {
            expect(s.frequency[k]).toBeCloseTo(k / (m * dt), 12); // f_k = k/(MΔ), the definition
            expect(s.re[k]).toBeCloseTo(ref.re[k], 12);
            expect(s.im[k]).toBeCloseTo(ref.im[k], 12);
            expect(s.amplitude[k]).toBeCloseTo(Math.hypot(ref.re[k], ref.im[k]), 12);
          }
        }
      }
    }
  });

  it('spectrum(samples, interval) reads exactly 1 for an on-bin unit sinusoid, with 21/50 beside it', () => {
    // Eq. 6 sampled at ζ = j/N has DFT N·25/46 at bin 0 and −N·21/92 at bins ±1, nothing else, and
    // Σ W = N·25/46. So a tone ½(e^{iθj+iφ} + c.c.) on bin k0 gives X_k0 = ½e^{iφ}·N·25/46, reading 1,
    // and |X_k0±1| = ½·N·21/92, reading (21/92)/(25/46) = 21/50; zero elsewhere; Re = cos φ, Im = sin φ.
    const n = 1024;
    const dt = 0.02;
    const k0 = 100;
    const phi = 0.7;
    const x = tones(n, dt, [{ f: k0 / (n * dt), amp: 1, phi }]);
    const s = spectrum(x, dt);
    expect(s.amplitude[k0]).toBeCloseTo(1, 12);
    expect(s.re[k0]).toBeCloseTo(Math.cos(phi), 12);
    expect(s.im[k0]).toBeCloseTo(Math.sin(phi), 12);
    expect(s.amplitude[k0 - 1]).toBeCloseTo(21 / 50, 12);
    expect(s.amplitude[k0 + 1]).toBeCloseTo(21 / 50, 12);
    for (let k = 0; k <= n / 2; k++) if (Math.abs(k - k0) > 1) expect(s.amplitude[k]).toBeLessThan(1e-12);

    // Rectangular window: the DFT basis is orthogonal, so the tone is in bin k0 alone.
    const r = spectrum(x, dt, { window: 'none' });
    expect(r.amplitude[k0]).toBeCloseTo(1, 12);
    for (let k = 0; k <= n / 2; k++) if (k !== k0) expect(r.amplitude[k]).toBeLessThan(1e-12);
  });

  it('spectrum(samples, interval) reads 1 for an off-bin unit sinusoid within the Hamming scalloping bound (N = 100000, 3000)', () => {
    const cases = [
      { n: 100000, dt: 0.01, f: [0.7312, 3.14159, 12.3456, 27.1828] },
      { n: 3000, dt: 0.05, f: [0.8123, 2.71828, 5.4321, 8.0101] },
    ];
    for (const { n, dt, f: freqs } of cases) {
      for (const f of freqs) {
        const s = spectrum(tones(n, dt, [{ f, amp: 1, phi: 1.1 }]), dt);
        const k = Math.round(f / s.binWidth);
        const peak = Math.max(s.amplitude[k - 1], s.amplitude[k], s.amplitude[k + 1]);
        expect(peak).toBeGreaterThan(SCALLOP_FLOOR); // Harris 1978, see SCALLOP_FLOOR
        expect(peak).toBeLessThan(1 + 1e-3); // the window's transform peaks at the tone, reading 1
        const [p] = findPeaks(s, { top: 1 });
        expect(Math.abs(p.amplitude - 1)).toBeLessThan(1 - SCALLOP_FLOOR);
        expect(Math.abs(p.frequency - f)).toBeLessThan(0.5 * s.binWidth);
      }
    }
  });

  it('spectrum(samples, interval) removes the mean: a constant offset makes no peak', () => {
    // A constant minus its mean is zero, so its spectrum is zero; by linearity an offset added to a
    // tone changes nothing but rounding.
    const flat = spectrum(new Float64Array(5000).fill(7.25), 0.1);
    expect(Math.max(...flat.amplitude)).toBeLessThan(1e-12);
    expect(findPeaks(flat)).toEqual([]);

    const dt = 0.01;
    const tone = [{ f: 0.37, amp: 1, phi: 0.2 }]; // low frequency, where DC leakage would hurt most
    const bare = spectrum(tones(20000, dt, tone), dt);
    const lifted = spectrum(tones(20000, dt, tone, 100), dt);
    for (let k = 0; k < bare.amplitude.length; k++) {
      expect(Math.abs(lifted.amplitude[k] - bare.amplitude[k])).toBeLessThan(1e-9);
    }
    const [p] = findPeaks(lifted, { top: 1 });
    expect(Math.abs(p.frequency - 0.37)).toBeLessThan(0.5 * lifted.binWidth);
  });

  it('spectrum(samples, interval) throws a one-line message on bad input', () => {
    expect(() => spectrum([], 1)).toThrow('spectrum: need at least 2 samples');
    expect(() => spectrum([3], 1)).toThrow('spectrum: need at least 2 samples');
    expect(() => spectrum([1, Number.NaN, 2], 1)).toThrow('spectrum: sample 1 is NaN; every sample must be a finite number');
    expect(() => spectrum([1, 2, Number.POSITIVE_INFINITY], 1)).toThrow('sample 2 is Infinity');
    expect(() => spectrum([1e308, 1e308], 1)).toThrow('spectrum: the samples are too large to sum');
    for (const interval of [0, -1, Number.NaN, Number.POSITIVE_INFINITY]) {
      expect(() => spectrum([1, 2], interval)).toThrow('spectrum: the sampling interval must be a finite positive number');
    }
    for (const pad of [0, 3, 1.5]) expect(() => spectrum([1, 2], 1, { pad })).toThrow('spectrum: pad must be a power of two');
    expect(() => spectrum([1, 2], 1, { window: 'hann' as WindowName })).toThrow(`spectrum: unknown window "hann"`);
  });
});

describe('findPeaks(spectrum, options)', () => {
  it('findPeaks(s, { refine: samples }) reads a unit sinusoid as 1 ± 1e-3 at its true frequency', () => {
    // Truth: the tone's own amplitude (1) and frequency. Tolerance in frequency, in bins of M: 1e-4 for
    // N = 100000. For N = 3000 the maximum of |DTFT| itself sits up to a few 1e-4 bins from the tone,
    // pulled by the Hamming sidelobes of the tone's negative-frequency image (the next test shows the
    // refinement does land on that maximum), so 5e-4 there.
    const cases = [
      { n: 100000, dt: 0.01, f: [0.7312, 3.14159, 12.3456, 27.1828], tol: 1e-4 },
      { n: 3000, dt: 0.05, f: [2.71828, 4.2576, 5.4321, 7.3854], tol: 5e-4 },
    ];
    for (const { n, dt, f: freqs, tol } of cases) {
      for (const [i, f] of freqs.entries()) {
        const x = tones(n, dt, [{ f, amp: 1, phi: 0.3 + i }]);
        const s = spectrum(x, dt);
        const [p] = findPeaks(s, { top: 1, refine: x });
        expect(Math.abs(p.amplitude - 1)).toBeLessThan(1e-3);
        expect(Math.abs(p.frequency - f) / s.binWidth).toBeLessThan(tol);
      }
    }
  });

  it('findPeaks(s, { refine: samples }) lands on the maximum of a naively summed windowed DTFT', () => {
    // Reference: golden-section search on naiveDtftAmplitude, bracketed ±0.05 bin around the tone.
    // A low tone (30 bins above DC, N = 3000) where the DTFT maximum is visibly off the tone.
    const n = 3000;
    const dt = 0.05;
    const f0 = 0.2;
    const x = tones(n, dt, [{ f: f0, amp: 1, phi: 0 }]);
    const s = spectrum(x, dt);
    let lo = f0 - 0.05 * s.binWidth;
    let hi = f0 + 0.05 * s.binWidth;
    const g = 0.5 * (Math.sqrt(5) - 1);
    for (let i = 0; i < 50; i++) {
      const c = hi - g * (hi - lo);
      const d = lo + g * (hi - lo);
      if (naiveDtftAmplitude(x, dt, c, 'hamming') > naiveDtftAmplitude(x, dt, d, 'hamming')) hi = d;
      else lo = c;
    }
    const fMax = 0.5 * (lo + hi);
    const [p] = findPeaks(s, { top: 1, refine: x });
    expect(Math.abs(p.frequency - fMax) / s.binWidth).toBeLessThan(1e-5);
    expect(p.amplitude).toBeCloseTo(naiveDtftAmplitude(x, dt, fMax, 'hamming'), 9);
  });

  it('findPeaks(s, { top: 2, refine }) finds amplitudes 1 and 0.3, strongest first, at their frequencies', () => {
    // Truth: the two tones the series is built from.
    const dt = 0.01;
    const parts = [
      { f: 11.7, amp: 0.3, phi: -1.1 },
      { f: 4.321, amp: 1, phi: 0.4 },
    ];
    const x = tones(20000, dt, parts);
    const s = spectrum(x, dt);
    for (const refine of [undefined, x]) {
      const peaks = findPeaks(s, { top: 2, refine });
      expect(peaks).toHaveLength(2);
      const [strong, weak] = peaks;
      const tolF = refine ? 1e-3 * s.binWidth : 0.5 * s.binWidth;
      const tolA = refine ? 1e-3 : 1 - SCALLOP_FLOOR;
      expect(Math.abs(strong.frequency - 4.321)).toBeLessThan(tolF);
      expect(Math.abs(strong.amplitude - 1)).toBeLessThan(tolA);
      expect(Math.abs(weak.frequency - 11.7)).toBeLessThan(tolF);
      expect(Math.abs(weak.amplitude - 0.3)).toBeLessThan(tolA * 0.3);
    }
  });

  it("findPeaks(spectrum(samples, interval, { window: 'none' }), { refine }) also reads 1", () => {
    // The rectangular window leaks more (sidelobes −13 dB, Harris 1978), so the DTFT maximum is
    // pulled further by the negative-frequency image: tolerances 1e-3 in amplitude and in bins.
    const n = 100000;
    const dt = 0.01;
    for (const f of [3.14159, 12.3456]) {
      const x = tones(n, dt, [{ f, amp: 1, phi: 2 }]);
      const s = spectrum(x, dt, { window: 'none' });
      const [p] = findPeaks(s, { top: 1, refine: x });
      expect(Math.abs(p.amplitude - 1)).toBeLessThan(1e-3);
      expect(Math.abs(p.frequency - f) / s.binWidth).toBeLessThan(1e-3);
    }
  });

  it('findPeaks(s, { minAmplitude }) drops the window sidelobes and never reports DC', () => {
    // Hamming's highest sidelobe is −43 dB ≈ 0.007 (Harris 1978, Table 1), far below 0.05.
    const dt = 0.01;
    const x = tones(30000, dt, [{ f: 5.55, amp: 1, phi: 0 }], 3);
    const s = spectrum(x, dt);
    expect(findPeaks(s, { top: 5 })).toHaveLength(5); // the sidelobes are local maxima too
    const peaks = findPeaks(s, { top: 5, minAmplitude: 0.05 });
    expect(peaks).toHaveLength(1);
    expect(Math.abs(peaks[0].frequency - 5.55)).toBeLessThan(0.5 * s.binWidth);
    for (const p of findPeaks(s, { top: 50 })) expect(p.frequency).toBeGreaterThan(0);
  });

  it('findPeaks(s, options) throws a one-line message on bad options', () => {
    const x = tones(100, 0.1, [{ f: 1, amp: 1, phi: 0 }]);
    const s = spectrum(x, 0.1);
    expect(() => findPeaks(s, { refine: x.subarray(1) })).toThrow(
      'findPeaks: refine has 99 samples but the spectrum was computed from 100',
    );
    expect(() => findPeaks(s, { top: -1 })).toThrow('findPeaks: top must be a whole number');
  });
});

describe('findPeaks(s) and the window’s sidelobes', () => {
  it('findPeaks(spectrum(tone)) reports the tone and not its Hamming sidelobes', () => {
    // A single off-bin cosine has one line; anything else found near it is leakage (Harris 1978).
    const n = 20001;
    const dt = 0.005;
    const tone = Float64Array.from({ length: n }, (_, j) => Math.cos(2 * Math.PI * 1.5182 * j * dt));
    const peaks = findPeaks(spectrum(tone, dt), { top: 5, refine: tone });
    expect(peaks[0].frequency).toBeCloseTo(1.5182, 2);
    for (const p of peaks.slice(1)) expect(Math.abs(p.frequency - 1.5182)).toBeGreaterThan(6 / (n * dt));
  });
});
