/**
 * The shoelace area (core/ensemble/polygon-area.ts) against areas known in
 * closed form: a right triangle, a square, the regular n-gon of
 * circumradius r, (n/2)r² sin(2π/n), and the same polygons moved far from
 * the origin, where a plain shoelace sum loses every digit. Its error bound
 * against the area between a polygon and the circle or ellipse its vertices
 * lie on, known exactly: πab less the inscribed polygon's area, summed side
 * by side as ½ab·sin Δθ_i.
 */
import { describe, expect, test } from 'vitest';
import { polygonArea, polygonAreaError, polygonAreaShortfall } from '../../../../core/ensemble/polygon-area.ts';

/** Vertices at the angles θ_i on the ellipse q = c_q + a cos θ, p = c_p + b sin θ. */
function onEllipse(angles: readonly number[], a = 1, b = a, center: readonly [number, number] = [0, 0]) {
  const q = Float64Array.from(angles, (t) => center[0] + a * Math.cos(t));
  const p = Float64Array.from(angles, (t) => center[1] + b * Math.sin(t));
  return { q, p };
}

const even = (n: number) => Array.from({ length: n }, (_, i) => (2 * Math.PI * i) / n);

/** The area of the polygon inscribed in the ellipse at the angles θ_i: each side's triangle with the centre is ½ab sin Δθ. */
function inscribedArea(angles: readonly number[], a: number, b: number): number {
  let area = 0;
  for (let i = 0; i < angles.length; i++) {
    const next = i + 1 < angles.length ? angles[i + 1] : angles[0] + 2 * Math.PI;
    area += 0.5 * a * b * Math.sin(next - angles[i]);
  }
  return area;
}

describe('polygonArea', () => {
  test('a right triangle of legs 1 and a square of side 2', () => {
    expect(polygonArea([0, 1, 0], [0, 0, 1])).toBe(0.5);
    expect(polygonArea([0, 2, 2, 0], [0, 0, 2, 2])).toBe(4);
  });

  test('the regular n-gon of circumradius r encloses (n/2)r² sin(2π/n)', () => {
    for (const n of [3, 4, 6, 100, 1000, 10_000]) {
      const r = 1.7;
      const { q, p } = onEllipse(even(n), r);
      const exact = (n / 2) * r * r * Math.sin((2 * Math.PI) / n);
      expect(Math.abs(polygonArea(q, p) - exact) / exact).toBeLessThan(1e-14);
    }
  });

  test('clockwise vertices give the negative area', () => {
    const { q, p } = onEllipse(even(50), 2);
    expect(polygonArea(q.reverse(), p.reverse())).toBeCloseTo(-25 * 4 * Math.sin((2 * Math.PI) / 50), 13);
  });

  test('moved 1e8 from the origin, the area keeps its digits (a plain shoelace keeps none)', () => {
    const n = 1000;
    const { q, p } = onEllipse(even(n), 1);
    const far = onEllipse(even(n), 1, 1, [1e8, -1e8]);
    const exact = (n / 2) * Math.sin((2 * Math.PI) / n);
    // Each vertex far away is its near one rounded to 1e8·2⁻⁵³ ≈ 1.5e-8: the area can be no better than that.
    expect(Math.abs(polygonArea(far.q, far.p) - exact) / exact).toBeLessThan(1e-7);
    expect(Math.abs(polygonArea(q, p) - exact) / exact).toBeLessThan(1e-14);
  });

  test('only the first n vertices count', () => {
    expect(polygonArea([0, 1, 0, 57, -3], [0, 0, 1, 9, 12], 3)).toBe(0.5);
    expect(polygonArea([0, 1], [0, 0])).toBe(0);
  });
});

describe('polygonAreaError', () => {
  test('for the regular n-gon in a circle it holds the true error πr² − (n/2)r² sin(2π/n), within a factor 1.5', () => {
    for (const n of [64, 256, 1024, 4096]) {
      const r = 0.8;
      const { q, p } = onEllipse(even(n), r);
      const truth = Math.PI * r * r - (n / 2) * r * r * Math.sin((2 * Math.PI) / n);
      const bound = polygonAreaError(q, p);
      expect(bound).toBeGreaterThanOrEqual(truth);
      expect(bound).toBeLessThan(1.5 * truth);
    }
  });

  test('it is the same for either orientation', () => {
    const { q, p } = onEllipse(even(128), 1);
    expect(polygonAreaError(q.slice().reverse(), p.slice().reverse())).toBeCloseTo(polygonAreaError(q, p), 15);
  });

  test('sides alternating in length 1 : 2 (a refined boundary’s) are still bounded, where a plain third of the triangles falls short', () => {
    // Angles stepping by δ, 2δ, δ, 2δ, …: 2n sides over the circle.
    const n = 100;
    const delta = (2 * Math.PI) / (3 * n);
    const angles = Array.from({ length: 2 * n }, (_, i) => Math.floor(i / 2) * 3 * delta + (i % 2) * delta);
    const { q, p } = onEllipse(angles, 1);
    const truth = Math.PI - inscribedArea(angles, 1, 1);
    const bound = polygonAreaError(q, p);
    expect(bound).toBeGreaterThanOrEqual(truth);
    expect(bound).toBeLessThan(1.5 * truth);
  });

  test('an ellipse of axes 3 and 0.5, its vertices even in angle, whose curvature varies 200-fold along it', () => {
    for (const n of [128, 1024]) {
      const angles = even(n);
      const { q, p } = onEllipse(angles, 3, 0.5, [5, -2]);
      const truth = Math.PI * 1.5 - inscribedArea(angles, 3, 0.5);
      const bound = polygonAreaError(q, p);
      expect(bound).toBeGreaterThanOrEqual(truth);
      expect(bound).toBeLessThan(1.5 * truth);
    }
  });

  test('a vertex repeated adds nothing, and fewer than three vertices have no error', () => {
    const { q, p } = onEllipse(even(64), 1);
    const repeated = { q: Float64Array.from([...q.slice(0, 10), q[9], ...q.slice(10)]), p: Float64Array.from([...p.slice(0, 10), p[9], ...p.slice(10)]) };
    const bound = polygonAreaError(q, p);
    // Each side lies in two triangles at half weight; the repeat leaves the two sides about it in one each.
    expect(polygonAreaError(repeated.q, repeated.p)).toBeGreaterThan(0.9 * bound);
    expect(polygonAreaError(repeated.q, repeated.p)).toBeLessThanOrEqual(bound);
    expect(polygonAreaError([0, 1], [0, 1])).toBe(0);
  });
});

describe('polygonAreaShortfall', () => {
  test('for the regular n-gon it is the true shortfall to within θ²/5 of it (θ = 2π/n), and of the sign of the orientation', () => {
    for (const n of [64, 1024]) {
      const { q, p } = onEllipse(even(n), 1);
      const truth = Math.PI - (n / 2) * Math.sin((2 * Math.PI) / n);
      const theta = (2 * Math.PI) / n;
      expect(Math.abs(polygonAreaShortfall(q, p) - truth)).toBeLessThan((theta * theta * truth) / 4);
      expect(polygonAreaShortfall(q.slice().reverse(), p.slice().reverse())).toBeCloseTo(-polygonAreaShortfall(q, p), 15);
    }
  });

  test('a bean, convex in part and concave in part: its errors of either sign cancel as the true ones do', () => {
    // r = 1 + 0.3 cos 3θ bends the wrong way about its three dents (r² + 2r′² − r r″ < 0 there). Its area ∫ r²/2 dθ = π(1 + 0.3²/2).
    const n = 512;
    const angles = even(n);
    const r = angles.map((t) => 1 + 0.3 * Math.cos(3 * t));
    const q = angles.map((t, i) => r[i] * Math.cos(t));
    const p = angles.map((t, i) => r[i] * Math.sin(t));
    const truth = Math.PI * (1 + 0.045) - polygonArea(q, p);
    expect(Math.abs(polygonAreaShortfall(q, p) - truth)).toBeLessThan(0.05 * truth);
    expect(polygonAreaError(q, p)).toBeGreaterThanOrEqual(truth);
  });
});
