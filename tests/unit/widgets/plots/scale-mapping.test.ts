import { describe, expect, it } from 'vitest';
import { scaleLog as d3Log } from 'd3-scale';
import { makeMapping, scaleLog, toPixel } from '../../../../widgets/plots/scale.ts';
import { formatTick, symlogTicks, ticksFor } from '../../../../widgets/plots/ticks.ts';

describe('plots/scale: mappings', () => {
  it('toPixel(makeMapping("log", domain, range, 1, scaleLog(label)), v) agrees with d3 scaleLog, and a log axis must bring its scale', () => {
    const scale = scaleLog(String).domain([1e-3, 1e3]).range([300, 0]);
    const reference = d3Log().domain([1e-3, 1e3]).range([300, 0]);
    const m = makeMapping('log', [1e-3, 1e3], [300, 0], 1, scale);
    for (const v of [1e-3, 0.02, 1, 7, 1e3]) {
      expect(toPixel(m, v)).toBeCloseTo(reference(v), 9);
      expect(scale(v)).toBeCloseTo(reference(v), 9);
      expect(scale.invert(reference(v))).toBeCloseTo(v, 9);
    }
    // Six decades over 300 px: 50 px a decade.
    expect(toPixel(m, 1) - toPixel(m, 10)).toBeCloseTo(50, 9);
    expect(() => makeMapping('log', [1, 10], [0, 1])).toThrow(/scaleLog/);
  });

  // The reference is d3-scale's own scaleLog, whose ticks and label thinning the charts keep without its interpolators.
  it('scaleLog(label): ticks, labels shown, and nice as d3 scaleLog, across one to thirty decades, either way round', () => {
    const label = (v: number) => `<${v}>`;
    const domains: [number, number][] = [[1, 10], [2, 7], [0.013, 0.4], [1e-3, 1e3], [3e-12, 2e-2], [1e-30, 1], [1e5, 1e-2], [0.5, 0.9]];
    for (const domain of domains) {
      const ours = scaleLog(label).domain(domain).range([0, 500]);
      const reference = d3Log().domain(domain).range([0, 500]);
      for (const count of [2, 5, 10, 25]) {
        const ticks = ours.ticks(count);
        expect(ticks).toEqual(reference.ticks(count));
        const format = ours.tickFormat(count);
        const referenceFormat = reference.tickFormat(count, label as unknown as string);
        expect(ticks.map(format)).toEqual(ticks.map(referenceFormat));
      }
      expect(scaleLog(label).domain(domain).nice().domain()).toEqual(d3Log().domain(domain).nice().domain());
    }
  });

  it('toPixel(makeMapping("linear", domain, range), v) agrees with the d3 scale', () => {
    const m = makeMapping('linear', [-3, 7], [400, 20]);
    for (const v of [-3, -1.5, 0, 2, 7, 12]) expect(toPixel(m, v)).toBeCloseTo(m.scale(v), 10);
    expect(toPixel(m, -3)).toBeCloseTo(400, 12);
    expect(toPixel(m, 7)).toBeCloseTo(20, 12);
  });

  it('toPixel(makeMapping("symlog", domain, range, c), v) agrees with d3 scaleSymlog', () => {
    const m = makeMapping('symlog', [-2000, 1500], [0, 640], 2);
    for (const v of [-2000, -30, -1, 0, 0.5, 40, 1500]) expect(toPixel(m, v)).toBeCloseTo(m.scale(v), 9);
  });

  it('makeMapping(kind, [a, a], range) maps everything to the middle of the range, as its scale does, instead of dividing by zero', () => {
    const m = makeMapping('linear', [2, 2], [10, 50]);
    expect(toPixel(m, 2)).toBe(30);
    expect(toPixel(m, 5)).toBe(30);
    expect(m.scale(5)).toBe(30);
  });

  it('symlogTicks(lo, hi, count, c) gives 0 and ±c·10^k, symmetric and within the domain', () => {
    expect(symlogTicks(-150, 150, 10)).toEqual([-100, -10, -1, 0, 1, 10, 100]);
    expect(symlogTicks(0, 5000, 10)).toEqual([0, 1, 10, 100, 1000]);
    expect(symlogTicks(-0.5, 0.5, 10)).toEqual([0]);
  });

  it('symlogTicks(lo, hi, count) thins decades to about count ticks', () => {
    const ticks = symlogTicks(-1e6, 1e6, 7);
    expect(ticks.length).toBeLessThanOrEqual(7);
    expect(ticks).toContain(0);
    expect(ticks.map((t) => -t || 0).sort((a, b) => a - b)).toEqual(ticks);
  });

  it('formatTick(v) is a plain decimal for ordinary sizes and a power of ten otherwise', () => {
    expect(formatTick(0)).toBe('0');
    expect(formatTick(1000)).toBe('1000');
    expect(formatTick(0.25)).toBe('0.25');
    expect(formatTick(1e6)).toBe('10⁶');
    expect(formatTick(-1e6)).toBe('−10⁶');
    expect(formatTick(2.5e-5)).toBe('2.5×10⁻⁵');
  });

  it('ticksFor(m, count) labels linear ticks with d3’s format and a true minus sign', () => {
    const { values, labels } = ticksFor(makeMapping('linear', [-1, 1], [0, 100]), 5);
    expect(values).toEqual([-1, -0.5, 0, 0.5, 1]);
    expect(labels).toEqual(['−1.0', '−0.5', '0.0', '0.5', '1.0']);
  });
});
