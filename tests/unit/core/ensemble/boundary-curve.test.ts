/**
 * The initial disc's boundary (core/ensemble/boundary-curve.ts) against the
 * ellipse's equation, its orientation (s = ¼ is the top, p = c_p + r_p, for
 * a counter-clockwise curve) and its area πr_q r_p.
 */
import { describe, expect, test } from 'vitest';
import { discArea, discBoundary } from '../../../../core/ensemble/boundary-curve.ts';
import { polygonArea, polygonAreaError } from '../../../../core/ensemble/polygon-area.ts';

describe('discBoundary', () => {
  test('its points lie on the ellipse ((q − c_q)/r_q)² + ((p − c_p)/r_p)² = 1, counter-clockwise from s = 0', () => {
    const curve = discBoundary([1.5, -0.25], [0.5, 0.2]);
    const out = new Float64Array(2);
    for (let i = 0; i < 100; i++) {
      curve.point(i / 100, out);
      expect(((out[0] - 1.5) / 0.5) ** 2 + ((out[1] + 0.25) / 0.2) ** 2).toBeCloseTo(1, 14);
    }
    curve.point(0, out);
    expect([...out]).toEqual([2, -0.25]);
    curve.point(0.25, out);
    expect(out[0]).toBeCloseTo(1.5, 15);
    expect(out[1]).toBeCloseTo(-0.05, 15);
  });

  test('a fine polygon on it encloses πr_q r_p, positive', () => {
    const curve = discBoundary([3, 4], [0.5, 2]);
    const n = 4096;
    const q = new Float64Array(n);
    const p = new Float64Array(n);
    const out = new Float64Array(2);
    for (let i = 0; i < n; i++) {
      curve.point(i / n, out);
      [q[i], p[i]] = out;
    }
    expect(discArea([0.5, 2])).toBe(Math.PI);
    expect(Math.abs(polygonArea(q, p) - Math.PI)).toBeLessThanOrEqual(polygonAreaError(q, p));
    expect(discArea(0.3)).toBeCloseTo(Math.PI * 0.09, 15);
  });

  test('for two degrees of freedom it is a loop in the (q0, p0) plane, the other components held at the centre', () => {
    const curve = discBoundary([1, 2, 3, 4], 0.5);
    const out = new Float64Array(4);
    curve.point(0.25, out);
    expect(out[0]).toBeCloseTo(1, 15);
    expect([out[1], out[2], out[3]]).toEqual([2, 3.5, 4]);
  });

  test('a centre that is not a state, or a radius that is not positive, is refused', () => {
    expect(() => discBoundary([1, 2, 3], 1)).toThrow(/2·dof/);
    expect(() => discBoundary([0, 0], 0)).toThrow(/radius/);
    expect(() => discBoundary([0, 0], [1, -1])).toThrow(/radius/);
  });
});
