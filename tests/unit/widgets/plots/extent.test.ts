import { describe, expect, it } from 'vitest';
import {
  contains,
  emptyExtent,
  fitEqualAspect,
  growExtent,
  includePoint,
  isEmpty,
  padAndRound,
  padInterval,
  PLANE_POLICY,
  roundOutward,
  stretchGrowth,
  type PaddingPolicy,
} from '../../../../widgets/plots/extent.ts';
import { transform, untransform, type SignedKind } from '../../../../widgets/plots/scale.ts';
import { AUTOSCALE_POLICY } from '../../../../widgets/plots/time/autoscale.ts';

describe('extent', () => {
  it('includePoint(e, x, y) widens an empty extent to the point and ignores non-finite points', () => {
    const e = emptyExtent();
    expect(isEmpty(e)).toBe(true);
    includePoint(e, 1, 2);
    includePoint(e, NaN, 5);
    includePoint(e, -3, Infinity);
    expect(e).toEqual({ x0: 1, x1: 1, y0: 2, y1: 2 });
    includePoint(e, -1, 4);
    expect(e).toEqual({ x0: -1, x1: 1, y0: 2, y1: 4 });
  });

  it('contains(outer, inner) is true for inner rectangles and for an empty inner', () => {
    const outer = { x0: 0, x1: 10, y0: 0, y1: 5 };
    expect(contains(outer, { x0: 1, x1: 10, y0: 0, y1: 4 })).toBe(true);
    expect(contains(outer, { x0: 1, x1: 10.1, y0: 0, y1: 4 })).toBe(false);
    expect(contains(outer, emptyExtent())).toBe(true);
  });

  it('transform(kind, v, c) is d3 symlog’s sgn(v)·ln(1 + |v|/c) and untransform inverts it', () => {
    expect(transform('linear', -7)).toBe(-7);
    expect(transform('symlog', -7, 2)).toBeCloseTo(-Math.log1p(3.5), 14);
    for (const v of [-1e6, -3, -0.25, 0, 0.5, 42, 9e5]) expect(untransform('symlog', transform('symlog', v, 3), 3)).toBeCloseTo(v, 6);
  });

  it('padInterval(lo, hi, headroom) pads each side and rounds outward to tick values', () => {
    const [a, b] = padInterval(-0.3, 9.7, 0.08);
    expect(a).toBeLessThanOrEqual(-0.3 - 0.08 * 10);
    expect(b).toBeGreaterThanOrEqual(9.7 + 0.08 * 10);
    expect([a, b]).toEqual([-2, 11]);
  });

  it('padInterval keeps 0 as the floor of data that are never negative, and as the ceiling of data never positive', () => {
    // a distance from 0.3 to 9.7: padding 8% would reach −0.45, a value it cannot take
    expect(padInterval(0.3, 9.7, 0.08)).toEqual([0, 10.5]);
    expect(padInterval(-9.7, -0.3, 0.08)).toEqual([-10.5, 0]);
    expect(padInterval(0.01, 80, 0.25, 'symlog')[0]).toBe(0);
    // data crossing zero are padded on both sides as before
    expect(padInterval(-0.3, 9.7, 0.08)[0]).toBeLessThan(-0.3);
  });

  it('padInterval(v, v, h) gives a single value a width of 10% of its size each way', () => {
    const [a, b] = padInterval(5, 5, 0);
    expect(a).toBeCloseTo(4.5, 12);
    expect(b).toBeCloseTo(5.5, 12);
    const [c, d] = padInterval(0, 0, 0);
    expect(d - c).toBeGreaterThan(0);
  });

  it('padInterval(lo, hi, h, "symlog") pads in the transformed space, so it stays symmetric in decades', () => {
    const [a, b] = padInterval(-100, 100, 0.1, 'symlog');
    expect(a).toBeCloseTo(-b, 9);
    expect(transform('symlog', b)).toBeCloseTo(transform('symlog', 100) * 1.2, 9);
  });

  it('growExtent(current, data, h) covers both and is padded', () => {
    const e = growExtent({ x0: 0, x1: 1, y0: 0, y1: 1 }, { x0: -2, x1: 0.5, y0: 0.5, y1: 3 }, 0.05);
    expect(contains(e, { x0: -2, x1: 1, y0: 0, y1: 3 })).toBe(true);
    expect(e.x0).toBeLessThan(-2);
  });

  it('fitEqualAspect(e, w, h) keeps the centre and gives x and y the same data units per pixel', () => {
    const e = fitEqualAspect({ x0: 0, x1: 10, y0: 0, y1: 2 }, 400, 200);
    expect((e.x1 - e.x0) / 400).toBeCloseTo((e.y1 - e.y0) / 200, 12);
    expect((e.x0 + e.x1) / 2).toBeCloseTo(5, 12);
    expect((e.y0 + e.y1) / 2).toBeCloseTo(1, 12);
    expect(contains(e, { x0: 0, x1: 10, y0: 0, y1: 2 })).toBe(true);
  });

  it('stretchGrowth(previous, next, f) grows an axis that outgrew previous to f× its span, on the side that grew', () => {
    const previous = { x0: 0, x1: 10, y0: 0, y1: 10 };
    const next = { x0: 0, x1: 11, y0: 0, y1: 10 };
    const e = stretchGrowth(previous, next, 1.5);
    expect(e.x0).toBe(0);
    expect(e.x1).toBeCloseTo(15, 12);
    expect([e.y0, e.y1]).toEqual([0, 10]);
    const both = stretchGrowth(previous, { x0: -1, x1: 11, y0: 0, y1: 10 }, 1.5);
    expect(both.x1 - both.x0).toBeCloseTo(15, 12);
    expect(both.x0).toBeCloseTo(-2.5, 12);
    expect(stretchGrowth(previous, { x0: -20, x1: 20, y0: 0, y1: 10 }, 1.5).x1).toBe(20);
    expect(stretchGrowth(emptyExtent(), next, 1.5)).toBe(next);
  });
});

describe('padAndRound, the padding shared by the plane and the time plots', () => {
  it('roundOutward(v, direction) moves away from zero only in the given direction', () => {
    expect(roundOutward(3.7, 1)).toBe(5);
    expect(roundOutward(3.7, -1)).toBe(2);
    expect(roundOutward(-3.7, -1)).toBe(-5);
    expect(roundOutward(-3.7, 1)).toBe(-2);
    expect(roundOutward(2, 1)).toBe(2);
    expect(roundOutward(0, 1)).toBe(0);
  });

  const policies: [string, PaddingPolicy][] = [
    ['plane', PLANE_POLICY],
    ['autoscale', AUTOSCALE_POLICY],
  ];
  const pad = (lo: number, hi: number, policy: PaddingPolicy, padding: number, kind: SignedKind = 'linear', c = 1) =>
    padAndRound(lo, hi, { ...policy, padding, kind, c });

  it.each(policies)('under the %s policy, padding never crosses zero, on either axis kind', (_, policy) => {
    // [1, 5.2] padded by half its span (2.1): −1.1 is cut to 0; 7.3 goes to 7.5, on steps of 0.5 (7.3 / 16 and 7.3 / 20 both round up to 0.5)
    expect(pad(1, 5.2, policy, 0.5)).toEqual([0, 7.5]);
    expect(pad(-5.2, -1, policy, 0.5)).toEqual([-7.5, 0]);
    // symlog: ln 1.01 − 0.25·(ln 81 − ln 1.01) < 0, so the floor is 0 again (and the ceiling for the mirrored data)
    expect(pad(0.01, 80, policy, 0.25, 'symlog')[0]).toBe(0);
    expect(pad(-80, -0.01, policy, 0.25, 'symlog')[1]).toBe(0);
    // data that cross zero are padded on both sides: 0.1·(5 + 1) = 0.6 below −1
    expect(pad(-1, 5, policy, 0.1)[0]).toBeLessThanOrEqual(-1.6);
  });

  it('a zero span is widened by a tenth of its size and then padded (plane) or widened instead of padded (autoscale)', () => {
    // 5 ± 0.5 = [4.5, 5.5]; the plane pads that by 0.5·1 more each way, to [4, 6]; autoscale stops at [4.5, 5.5] (steps of 0.1 and 0.05)
    expect(pad(5, 5, PLANE_POLICY, 0.5)).toEqual([4, 6]);
    expect(pad(5, 5, AUTOSCALE_POLICY, 0.5)).toEqual([4.5, 5.5]);
    // at 0 a tenth of nothing: the plane keeps a hair of 1e-6 each way, autoscale takes ±1
    const [a, b] = pad(0, 0, PLANE_POLICY, 0);
    expect(a).toBeCloseTo(-1e-6, 15);
    expect(b).toBeCloseTo(1e-6, 15);
    expect(pad(0, 0, AUTOSCALE_POLICY, 0)).toEqual([-1, 1]);
  });

  it('on symlog a zero span gets at least half a transformed unit each way (plane) or exactly half (autoscale)', () => {
    // at 0: T = ±0.5, so ±(√e − 1) ≈ ±0.6487; autoscale's ladder rounds that out to ±1
    const [a, b] = pad(0, 0, PLANE_POLICY, 0, 'symlog');
    expect(a).toBeCloseTo(-(Math.sqrt(Math.E) - 1), 12);
    expect(b).toBeCloseTo(Math.sqrt(Math.E) - 1, 12);
    expect(pad(0, 0, AUTOSCALE_POLICY, 0, 'symlog')).toEqual([-1, 1]);
    // at T = 10 the plane's tenth (1) beats 0.5: [e⁹ − 1, e¹¹ − 1]; autoscale's 0.5 gives e^9.5 − 1 ≈ 13359 and e^10.5 − 1 ≈ 36314, rounded out to 10000 and 50000
    const v = Math.expm1(10);
    const [c, d] = pad(v, v, PLANE_POLICY, 0, 'symlog');
    expect(c / Math.expm1(9)).toBeCloseTo(1, 12);
    expect(d / Math.expm1(11)).toBeCloseTo(1, 12);
    expect(pad(v, v, AUTOSCALE_POLICY, 0, 'symlog')).toEqual([10000, 50000]);
  });

  it('symlog with a constant c ≠ 1 pads in ln(1 + |v|/c) and maps back through the same c', () => {
    for (const c of [0.01, 3, 1000]) {
      // no padding: the ends come back as the data
      for (const [lo, hi] of [[-250, 7], [0.5, 4e4], [-9e5, -2]]) {
        const [a, b] = pad(lo, hi, PLANE_POLICY, 0, 'symlog', c);
        expect(a / lo).toBeCloseTo(1, 12);
        expect(b / hi).toBeCloseTo(1, 12);
      }
      // ±c(e² − 1) is T = ±2: a span of 4, padded by a quarter (1) to T = ±3, that is ±c(e³ − 1)
      const [a, b] = pad(-c * Math.expm1(2), c * Math.expm1(2), PLANE_POLICY, 0.25, 'symlog', c);
      expect(a / (-c * Math.expm1(3))).toBeCloseTo(1, 12);
      expect(b / (c * Math.expm1(3))).toBeCloseTo(1, 12);
    }
    // c = 3: [0, 3(e² − 1)] padded by half (1) reaches 3(e³ − 1) ≈ 57.3, which the ladder rounds out to 100
    expect(pad(0, 3 * Math.expm1(2), AUTOSCALE_POLICY, 0.5, 'symlog', 3)).toEqual([0, 100]);
  });

  it('each policy rounds to round numbers: d3 nice steps on linear, the 1-2-5 ladder or nothing on symlog', () => {
    // [0, 5.3]: 5.3 / 16 ≈ 0.33 rounds to steps of 0.5 (ends at 5.5); 5.3 / 20 ≈ 0.27 to steps of 0.2 (ends at 5.4)
    expect(pad(0, 5.3, PLANE_POLICY, 0)).toEqual([0, 5.5]);
    expect(pad(0, 5.3, AUTOSCALE_POLICY, 0)).toEqual([0, 5.4]);
    // [0, 99] is T = [0, ln 100]; half of it again is ln 1000, that is 999: left there by the plane, 1000 on the ladder
    const [, top] = pad(0, 99, PLANE_POLICY, 0.5, 'symlog');
    expect(top).toBeCloseTo(999, 9);
    expect(pad(0, 99, AUTOSCALE_POLICY, 0.5, 'symlog')).toEqual([0, 1000]);
    // [−3, 7000] unpadded: −3 out to −5, 7000 out to 10000
    expect(pad(-3, 7000, AUTOSCALE_POLICY, 0, 'symlog')).toEqual([-5, 10000]);
  });
});
