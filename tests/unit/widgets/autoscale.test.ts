import { describe, expect, it } from 'vitest';
import { extent, fit, grow, roundOutward } from '../../../widgets/plots/autoscale.ts';

describe('plots/autoscale', () => {
  it('fit(lo, hi, "linear") pads and rounds outward to round numbers', () => {
    const [a, b] = fit(-0.93, 2.04, 'linear');
    expect(a).toBeLessThanOrEqual(-0.93);
    expect(b).toBeGreaterThanOrEqual(2.04);
    expect([a, b]).toEqual([-1.5, 2.5]); // d3 nice() with about 8 ticks: steps of 0.5
  });

  it('fit(v, v, kind) makes a range around a single value; fit of nothing is [−1, 1]', () => {
    const [a, b] = fit(2, 2, 'linear');
    expect(a).toBeLessThan(2);
    expect(b).toBeGreaterThan(2);
    expect(fit(Infinity, -Infinity, 'linear')).toEqual([-1, 1]);
    expect(fit(NaN, 3, 'symlog')).toEqual([-1, 1]);
  });

  it('fit(lo, hi, "symlog") rounds outward on the 1-2-5 ladder', () => {
    const [a, b] = fit(-3, 7000, 'symlog');
    expect(a).toBeLessThanOrEqual(-3);
    expect(b).toBeGreaterThanOrEqual(7000);
    for (const v of [a, b]) {
      const m = Math.abs(v) / 10 ** Math.floor(Math.log10(Math.abs(v)));
      expect([1, 2, 5]).toContain(Math.round(m * 1e9) / 1e9);
    }
  });

  it('grow(domain, lo, hi, kind) is null while the data fits, and a larger range with headroom when not', () => {
    expect(grow([-1, 1], -0.5, 1, 'linear')).toBeNull();
    const grown = grow([-1, 1], -0.5, 1.5, 'linear')!;
    expect(grown[0]).toBeLessThanOrEqual(-1);
    expect(grown[1]).toBeGreaterThanOrEqual(1.5 + 0.2 * 2.5);
    expect(grow([-1, 1], NaN, NaN, 'linear')).toBeNull();
  });

  it('grow(…) on exponential growth redraws only O(log) times', () => {
    let domain: readonly [number, number] = [-1, 1];
    let redraws = 0;
    for (let t = 0; t < 60; t += 0.01) {
      const amplitude = Math.exp(t);
      const next = grow(domain, -amplitude, amplitude, 'symlog');
      if (next) {
        domain = next;
        redraws++;
      }
    }
    expect(redraws).toBeLessThan(40);
  });

  it('roundOutward(v, direction) moves away from zero only in the given direction', () => {
    expect(roundOutward(3.7, 1)).toBe(5);
    expect(roundOutward(3.7, -1)).toBe(2);
    expect(roundOutward(-3.7, -1)).toBe(-5);
    expect(roundOutward(-3.7, 1)).toBe(-2);
    expect(roundOutward(2, 1)).toBe(2);
    expect(roundOutward(0, 1)).toBe(0);
  });

  it('extent(values) ignores NaN and infinities', () => {
    expect(extent([3, NaN, -2, Infinity, -Infinity, 7])).toEqual([-2, 7]);
    expect(extent([])).toEqual([Infinity, -Infinity]);
  });
});
