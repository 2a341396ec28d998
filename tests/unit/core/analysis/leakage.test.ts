/**
 * peakError (core/analysis/leakage.ts): the bound on how far the
 * other lines, and the mirror images at negative frequency, pull a refined
 * spectral peak. Checked on sums of cosines whose frequencies are known
 * exactly: the refined peak must lie within the bound of the true frequency,
 * for every phase, and the bound must not be vacuous.
 */
import { describe, expect, it } from 'vitest';
import { peakError } from '../../../../core/analysis/leakage.ts';
import { findPeaks, spectrum } from '../../../../core/index.ts';

/** Samples of Σ A cos(2πf t + φ) every `dt` over [0, T). */
function signal(lines: { A: number; f: number; phase: number }[], dt: number, T: number): Float64Array {
  const n = Math.round(T / dt);
  return Float64Array.from({ length: n }, (_, j) => lines.reduce((sum, { A, f, phase }) => sum + A * Math.cos(2 * Math.PI * f * j * dt + phase), 0));
}

/** The refined peak nearest f, and its error bound, for the samples y. */
function measure(y: Float64Array, dt: number, f: number) {
  const s = spectrum(y, dt);
  const lines = findPeaks(s, { top: 8, refine: y });
  const line = lines.reduce((a, b) => (Math.abs(b.frequency - f) < Math.abs(a.frequency - f) ? b : a));
  return { line, error: peakError(s, lines, line) };
}

describe('peakError(spectrum, lines, line)', () => {
  it('bounds the pull of a lone cosine’s own mirror image, whatever its phase, and is within a factor 3 of the worst', () => {
    let worst = 0;
    let bound = 0;
    for (let k = 0; k < 16; k++) {
      const y = signal([{ A: 1, f: 1.3, phase: (2 * Math.PI * k) / 16 }], 0.01, 40);
      const { line, error } = measure(y, 0.01, 1.3);
      expect(Math.abs(line.frequency - 1.3)).toBeLessThanOrEqual(error.bound);
      expect(error.resolved).toBe(true);
      worst = Math.max(worst, Math.abs(line.frequency - 1.3));
      bound = error.bound;
    }
    expect(worst).toBeGreaterThan(bound / 3);
  });

  it('bounds the pull of a stronger neighbour 16 bins away (the Introduction’s drive line beside the free line)', () => {
    for (let k = 0; k < 8; k++) {
      const y = signal(
        [
          { A: 0.5, f: 8 / (2 * Math.PI), phase: 0.2 },
          { A: 0.9, f: 1.658, phase: (2 * Math.PI * k) / 8 },
          { A: 0.5, f: 1.795, phase: 1 },
        ],
        0.01,
        40,
      );
      const { line, error } = measure(y, 0.01, 8 / (2 * Math.PI));
      expect(Math.abs(line.frequency - 8 / (2 * Math.PI))).toBeLessThanOrEqual(error.bound);
      expect(error.bins).toBeLessThan(0.1);
    }
  });

  it('grows as the line weakens against its neighbours', () => {
    const at = (A: number) => measure(signal([{ A, f: 1.2, phase: 0 }, { A: 1, f: 1.6, phase: 0 }], 0.01, 40), 0.01, 1.2).error.bound;
    expect(at(0.01)).toBeGreaterThan(20 * at(1));
  });

  it('says when a component lies inside the main lobe, where the first-order bound does not apply: a line near 0 and its mirror', () => {
    // 0.75 cycles over the record: the mirror image at −f is 1.5 bins away, inside Hamming's lobe of ±2 bins.
    const y = signal([{ A: 1, f: 0.75 / 40, phase: 0.3 }], 0.01, 40);
    const { error } = measure(y, 0.01, 0.75 / 40);
    expect(error.closest).toBeLessThan(2);
    expect(error.resolved).toBe(false);
  });

  it('counts the line’s own mirror even when the line is not in the list', () => {
    const y = signal([{ A: 1, f: 1.3, phase: 0 }], 0.01, 40);
    const s = spectrum(y, 0.01);
    const [line] = findPeaks(s, { top: 1, refine: y });
    expect(peakError(s, [], { ...line }).bound).toBeCloseTo(peakError(s, [line], line).bound, 15);
  });
});
