import { describe, expect, it } from 'vitest';
import { spacedTicks } from '../../../widgets/plots/axes.ts';
import { axisTicks, formatPower, scientificFormat } from '../../../widgets/plots/ticks.ts';
import { yScale } from '../../../widgets/plots/y-map.ts';

describe('plots/ticks', () => {
  it('axisTicks("linear", domain, n) gives d3’s round ticks and labels', () => {
    const { values, format } = axisTicks('linear', [0, 10], 5);
    expect(values).toEqual([0, 2, 4, 6, 8, 10]);
    expect(values.map(format)).toEqual(['0', '2', '4', '6', '8', '10']);
    expect(axisTicks('linear', [-1, 1], 4).format(-0.5)).toBe('−0.5');
  });

  it('axisTicks("symlog", domain, n) gives 0 and signed powers of ten, thinned to n', () => {
    expect(axisTicks('symlog', [-150, 2000], 10).values).toEqual([-100, -10, -1, 0, 1, 10, 100, 1000]);
    const thin = axisTicks('symlog', [-1e20, 1e20], 6).values;
    expect(thin.length).toBeLessThanOrEqual(6);
    expect(thin).toContain(0);
    for (const v of thin) if (v !== 0) expect(Math.log10(Math.abs(v)) % 1).toBe(0);
  });

  it('axisTicks("symlog", small domain) falls back to linear ticks', () => {
    expect(axisTicks('symlog', [-2, 2], 5).values).toEqual([-2, -1, 0, 1, 2]);
  });

  it('formatPower(v) writes 10ⁿ from 10⁴ on, with a true minus', () => {
    expect([0, 1, -10, 1000, 1e4, -1e20].map(formatPower)).toEqual(['0', '1', '−10', '1000', '10⁴', '−10²⁰']);
  });

  it('large linear ticks are labelled m×10ⁿ with the decimals the step needs', () => {
    const { values, format } = axisTicks('linear', [0, 6e9], 4);
    expect(values.map(format)).toEqual(['0', '2×10⁹', '4×10⁹', '6×10⁹']);
    expect(scientificFormat([1e-5, 1.5e-5, 2e-5])(1.5e-5)).toBe('1.5×10⁻⁵');
  });

  it('spacedTicks(values, position, gap) keeps 0 and drops labels crowding it', () => {
    const scale = yScale('symlog', [-1e6, 1e6], [400, 0]);
    const kept = spacedTicks([-1e6, -1e3, -10, -1, 0, 1, 10, 1e3, 1e6], scale, 13);
    expect(kept).toContain(0);
    expect(kept).not.toContain(1);
    expect(kept).not.toContain(-1);
    const at = kept.map((v) => scale(v)).sort((a, b) => a - b);
    for (let i = 1; i < at.length; i++) expect(at[i] - at[i - 1]).toBeGreaterThanOrEqual(13);
  });
});
