import { describe, expect, it } from 'vitest';
import { basisLine, compareWithTheory, describePeak, fixed, frequencyDecimals, peakLine, significant } from '../../../../../widgets/plots/spectrum/spectrum-readout.ts';

describe('peak-readout', () => {
  it('fixed(v, d) rounds to d places with a true minus sign and no −0', () => {
    expect(fixed(1.51818, 3)).toBe('1.518');
    expect(fixed(-2.5, 1)).toBe('−2.5');
    expect(fixed(-0.0001, 2)).toBe('0.00');
  });

  it('compareWithTheory(peak, theory, T) signs the difference as rounded: never “−0.00%”', () => {
    const theory = { frequency: 1.5, label: 'theory' };
    const at = (frequency: number) => compareWithTheory({ frequency, amplitude: 1 }, theory, 40);
    expect(at(1.5 * (1 - 1e-5))).toBe('strongest peak 1.500 vs theory: 0.00%');
    expect(at(1.5)).toBe('strongest peak 1.500 vs theory: 0.00%');
    expect(at(1.5 * (1 + 1e-5))).toBe('strongest peak 1.500 vs theory: 0.00%');
    expect(at(1.5 * 1.0123)).toBe('strongest peak 1.518 vs theory: +1.23%');
    expect(at(1.5 * 0.9877)).toBe('strongest peak 1.482 vs theory: −1.23%');
  });

  it('significant(v, d) keeps d significant digits, switching to ×10^n for extreme sizes', () => {
    expect(significant(0.98213, 3)).toBe('0.982');
    expect(significant(273.4, 3)).toBe('273');
    expect(significant(-0.0124, 3)).toBe('−0.0124');
    expect(significant(3.2e-7, 2)).toBe('3.2×10^-7');
    expect(significant(0)).toBe('0');
  });

  it('frequencyDecimals(T) grows with the time T the spectrum covers', () => {
    expect(frequencyDecimals(4)).toBe(2);
    expect(frequencyDecimals(40)).toBe(3);
    expect(frequencyDecimals(400)).toBe(4);
    expect(frequencyDecimals(1e9)).toBe(6);
    expect(frequencyDecimals(0)).toBe(3);
  });

  it('describePeak(peak, T) gives f, ω = 2πf and the amplitude', () => {
    const t = describePeak({ frequency: 1.518, amplitude: 0.9821 }, 40);
    expect(t).toEqual({ frequency: '1.518', omega: '9.54', amplitude: '0.982' });
  });

  it('peakLine(peak, T) reads as one line of text with its units', () => {
    expect(peakLine({ frequency: 1.5181, amplitude: 0.98 }, 45)).toBe(
      'f = 1.518 cycles per time unit · ω = 2πf = 9.54 rad per time unit · amplitude 0.98',
    );
  });

  it('basisLine(window, t0, T, N, stride) says what the spectrum was computed from', () => {
    expect(basisLine('hamming', 0, 45.8, 30533, 3)).toBe(
      'Hamming window · t = 0.0 … 45.8 · 30,533 samples (means of 3) · resolution 1/T = 0.022',
    );
    expect(basisLine('none', 12, 2, 4000, 1)).toMatch(/^no window · t = 12.00 … 14.00 · 4,000 samples · /);
  });
});
