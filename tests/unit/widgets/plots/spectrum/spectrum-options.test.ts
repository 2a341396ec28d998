import { describe, expect, it } from 'vitest';
import { checkSpectrumOptions } from '../../../../../widgets/plots/spectrum/spectrum-rows.ts';

describe('spectrum-options', () => {
  it('checkSpectrumOptions(o) accepts the documented options', () => {
    expect(() => checkSpectrumOptions({})).not.toThrow();
    expect(() => checkSpectrumOptions({ window: 'none', show: 'reim', span: 20, maxFrequency: 5, peaks: 0, refresh: 100, maxSamples: 4096 })).not.toThrow();
    expect(() => checkSpectrumOptions({ span: [2, 8] })).not.toThrow();
  });

  it('checkSpectrumOptions(o) names the first bad option and its value', () => {
    expect(() => checkSpectrumOptions({ window: 'hann' })).toThrow(`spectrumView: window must be 'hamming' or 'none', not "hann"`);
    expect(() => checkSpectrumOptions({ show: 'Re' })).toThrow(/show must be/);
    expect(() => checkSpectrumOptions({ span: -1 })).toThrow(/span must be/);
    expect(() => checkSpectrumOptions({ span: [5, 1] })).toThrow(/span must be/);
    expect(() => checkSpectrumOptions({ peaks: 2.5 })).toThrow(/peaks must be/);
    expect(() => checkSpectrumOptions({ maxFrequency: 0 })).toThrow(/maxFrequency/);
  });
});
