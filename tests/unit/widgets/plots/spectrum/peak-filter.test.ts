import { describe, expect, it } from 'vitest';
import { dropLeakage } from '../../../../../widgets/plots/spectrum/spectrum-analysis.ts';

describe('peak-filter', () => {
  it('dropLeakage(peaks, T, "hamming") drops peaks no stronger than the window’s sidelobes', () => {
    const peaks = [
      { frequency: 1.518, amplitude: 0.982 },
      { frequency: 3.036, amplitude: 0.0126 },
      { frequency: 1.441, amplitude: 0.0073 },
    ];
    expect(dropLeakage(peaks, 45, 'hamming')).toEqual(peaks.slice(0, 2));
  });

  it('dropLeakage(peaks, T, "none") drops what the rectangular window’s 1/(πm) sidelobes explain', () => {
    const main = { frequency: 1, amplitude: 1 };
    const near = { frequency: 1.1, amplitude: 0.15 };
    const far = { frequency: 3, amplitude: 0.15 };
    expect(dropLeakage([main, near, far], 20, 'none')).toEqual([main, far]);
  });

  it('dropLeakage(peaks, T, window) drops peaks within 1.5 resolution bins of zero frequency', () => {
    const trend = { frequency: 0.02, amplitude: 2 };
    const tone = { frequency: 0.34, amplitude: 1 };
    expect(dropLeakage([trend, tone], 10, 'hamming')).toEqual([tone]);
  });
});
