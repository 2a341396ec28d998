import { describe, expect, it } from 'vitest';
import {
  contains,
  emptyExtent,
  fitEqualAspect,
  growExtent,
  includePoint,
  isEmpty,
  padInterval,
  stretchGrowth,
} from '../../../widgets/plots/extent.ts';
import { transform, untransform } from '../../../widgets/plots/scale.ts';

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
