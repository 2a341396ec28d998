import { describe, expect, it } from 'vitest';
import { extent, fit, grow, settle } from '../../../../../widgets/plots/time/autoscale.ts';

describe('plots/autoscale', () => {
  it('fit(lo, hi, "linear") pads and rounds outward to round numbers', () => {
    const [a, b] = fit(-0.93, 2.04, 'linear');
    expect(a).toBeLessThanOrEqual(-0.93);
    expect(b).toBeGreaterThanOrEqual(2.04);
    // d3 nice() on steps for about 20 ticks (0.2 here): round ends that waste little of the height
    expect([a, b]).toEqual([-1.2, 2.2]);
  });

  it('fit hugs the data: the padded, rounded range wastes at most a fifth of its span, at any magnitude', () => {
    for (let e = -12; e <= 15; e++) {
      for (const [lo, hi] of [[-0.93, 2.04], [-1.04, 1], [3.3, 3.9], [-7.1, -2.2]]) {
        const [a, b] = fit(lo * 10 ** e, hi * 10 ** e, 'linear');
        expect(a).toBeLessThanOrEqual(lo * 10 ** e);
        expect(b).toBeGreaterThanOrEqual(hi * 10 ** e);
        expect((hi - lo) * 10 ** e).toBeGreaterThan(0.8 * (b - a));
      }
    }
  });

  it('fit keeps 0 as the floor of data never negative (a distance r) and as the ceiling of data never positive', () => {
    // Kepler's r from 0.5 to 80: 5% padding would reach −3.5
    expect(fit(0.5, 80, 'linear')[0]).toBe(0);
    expect(fit(0.01, 80, 'symlog')[0]).toBe(0);
    expect(fit(-80, -0.5, 'linear')[1]).toBe(0);
    // growth keeps it: the grown range is the fit of the union with the old one
    expect(grow([0, 90], 0.4, 200, 'linear')![0]).toBe(0);
    expect(fit(-0.5, 80, 'linear')[0]).toBeLessThan(-0.5);
  });

  it('settle(domain, lo, hi) refits a range growth left loose, and leaves a snug one', () => {
    // the nonlinear oscillator's q in [−1.04, 1] on the [−2, 2.5] that growth from its first samples left
    const settled = settle([-2, 2.5], -1.04, 1, 'linear')!;
    expect(settled[0]).toBeLessThanOrEqual(-1.04);
    expect(settled[1]).toBeGreaterThanOrEqual(1);
    expect(settled[1] - settled[0]).toBeLessThan(2.5);
    expect(settle(settled, -1.04, 1, 'linear')).toBeNull();
    // the range a busy machine's first frames left it on: a quarter empty above the data, and refitted
    const busy = settle([-1, 1.7], -0.96, 1, 'linear')!;
    expect(busy[0]).toBeLessThanOrEqual(-0.96);
    expect(busy[1]).toBeGreaterThanOrEqual(1);
    expect(1.96 / (busy[1] - busy[0])).toBeGreaterThanOrEqual(0.8);
    expect(settle([-1.2, 1.2], -1.04, 1, 'linear')).toBeNull();
    expect(settle([-1e4, 1e4], -5, 7, 'symlog')).not.toBeNull();
    expect(settle([-1, 1], NaN, NaN, 'linear')).toBeNull();
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

  it('extent(values) ignores NaN and infinities', () => {
    expect(extent([3, NaN, -2, Infinity, -Infinity, 7])).toEqual([-2, 7]);
    expect(extent([])).toEqual([Infinity, -Infinity]);
  });
});
