import { describe, expect, it } from 'vitest';
import { chooseMaxFrequency, niceCeil, padFor, steadyLimit } from '../../../../../widgets/plots/spectrum/spectrum-analysis.ts';

describe('spectrum-scale', () => {
  it('niceCeil(v) is the next round number at or above v', () => {
    expect(niceCeil(3.8)).toBe(4);
    expect(niceCeil(1.1)).toBe(1.2);
    expect(niceCeil(0.031)).toBeCloseTo(0.04, 15);
    expect(niceCeil(500)).toBe(500);
    expect(niceCeil(0)).toBe(1);
  });

  it('chooseMaxFrequency(peaks, nyquist) reaches past the significant peaks to ≥ 2.5× the strongest', () => {
    const peaks = [
      { frequency: 1.518, amplitude: 1 },
      { frequency: 3.036, amplitude: 0.0126 },
      { frequency: 9, amplitude: 0.001 },
    ];
    expect(chooseMaxFrequency(peaks, 1000, undefined, undefined)).toBe(4);
    expect(chooseMaxFrequency([peaks[0], { frequency: 4, amplitude: 0.5 }], 1000, undefined, undefined)).toBe(6);
  });

  it('chooseMaxFrequency(peaks, nyquist, theory) also shows the theoretical marker, and never passes Nyquist', () => {
    expect(chooseMaxFrequency([{ frequency: 1, amplitude: 1 }], 1000, 7, undefined)).toBe(10);
    expect(chooseMaxFrequency([{ frequency: 1, amplitude: 1 }], 2, undefined, undefined)).toBe(2);
    expect(chooseMaxFrequency([], 50, undefined, undefined)).toBe(50);
  });

  it('chooseMaxFrequency(peaks, nyquist, theory, current) keeps the current axis while it still fits', () => {
    const peaks = [{ frequency: 1.5, amplitude: 1 }];
    expect(chooseMaxFrequency(peaks, 1000, undefined, 6)).toBe(6);
    expect(chooseMaxFrequency(peaks, 1000, undefined, 3)).toBe(4);
    expect(chooseMaxFrequency(peaks, 1000, undefined, 100)).toBe(4);
  });

  it('steadyLimit(value, current) leaves 30% headroom, rises at once but falls only below half', () => {
    expect(steadyLimit(0.98, undefined)).toBe(1.5);
    expect(steadyLimit(0.7, 1.5)).toBe(1.5);
    expect(steadyLimit(1.3, 1.5)).toBe(2);
    expect(steadyLimit(0.3, 1.5)).toBe(0.4);
  });

  it('chooseMaxFrequency([], nyquist, theory, current, T) with no peak yet shows the marker or forty bins of 1/T', () => {
    expect(chooseMaxFrequency([], 1000, 1.518, undefined, 0.2)).toBe(4);
    expect(chooseMaxFrequency([], 1000, undefined, undefined, 2)).toBe(20);
    expect(chooseMaxFrequency([], 5, undefined, undefined, 2)).toBe(5);
  });

  it('padFor(s, maxFrequency) pads by powers of two until the visible axis holds enough bins', () => {
    expect(padFor({ binWidth: 0.25, padded: 256 }, 1)).toBe(128);
    expect(padFor({ binWidth: 0.25, padded: 8192 }, 1)).toBe(32);
    expect(padFor({ binWidth: 0.001, padded: 8192 }, 5)).toBe(1);
    expect(padFor({ binWidth: 1, padded: 1 << 17 }, 1)).toBe(2);
  });
});
