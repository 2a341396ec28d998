/**
 * The growth rate of an oscillating exponential (core/analysis/exponential-growth.ts),
 * against the rate it was made with: e^{at}(2 + cos 2bt) and a pure e^{at},
 * and the bound it reports, which must contain the true error.
 */
import { expect, test } from 'vitest';
import { exponentialGrowth } from '../../../../core/analysis/exponential-growth.ts';

const sampled = (f: (t: number) => number, end: number, h = 0.01) => {
  const t = Float64Array.from({ length: Math.round(end / h) + 1 }, (_, i) => i * h);
  return { t, size: t.map(f) };
};

test('a pure exponential gives its rate to rounding, with a bound near zero', () => {
  const { t, size } = sampled((t) => 1e-6 * Math.exp(0.3 * t), 40);
  const g = exponentialGrowth(t, size, 1e-6, 1e-2);
  expect(Math.abs(g.rate - 0.3)).toBeLessThan(1e-12);
  expect(g.bound).toBeLessThan(1e-10);
  // only up to the size 1e-2: ln(1e4)/0.3 ≈ 30.7 time units
  expect(g.span).toBeCloseTo(Math.log(1e4) / 0.3, 1);
});

test('an oscillating exponential gives its rate within the bound it reports, and the bound shrinks with the span', () => {
  for (const [a, b] of [[0.18, 0.73], [0.5, 0.9], [0.05, 1]]) {
    const f = (t: number) => 1e-9 * Math.exp(a * t) * (2 + Math.cos(2 * b * t));
    const short = exponentialGrowth(...Object.values(sampled(f, 200)) as [Float64Array, Float64Array], 1e-9, 1e-6);
    const long = exponentialGrowth(...Object.values(sampled(f, 400)) as [Float64Array, Float64Array], 1e-9, 1e-3);
    for (const g of [short, long]) {
      expect(Math.abs(g.rate - a)).toBeLessThanOrEqual(g.bound);
      expect(g.bound).toBeGreaterThan(0);
    }
    expect(long.bound).toBeLessThan(short.bound);
  }
});

test('fewer than three samples in range give NaN', () => {
  const { t, size } = sampled((t) => Math.exp(t), 1);
  expect(exponentialGrowth(t, size, 100, 1000).rate).toBeNaN();
});
