/**
 * The standard map (core/maps/standard-map.ts) against truths written here:
 * its Jacobian against central differences of the step and its determinant
 * against 1 (a composition of two shears: Chirikov 1979, Phys. Rep. 52, 263,
 * §3); its inverse, written out in this file, undoing it (the map is a
 * bijection of the cylinder); at K = 0 the free rotor in closed form,
 * p_n = p_0, q_n = q_0 + n·p_0 mod 2π.
 */
import { describe, expect, test } from 'vitest';
import { TWO_PI, wrapAngle } from '../../../../core/maps/area-preserving-map.ts';
import { standardMap } from '../../../../core/maps/standard-map.ts';

/** A small linear congruential generator (Numerical Recipes' 32-bit constants), so the random points are the same every run. */
function lcg(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (Math.imul(1664525, s) + 1013904223) >>> 0;
    return s / 4294967296;
  };
}

/** The distance of two angles on the circle. */
const angleGap = (a: number, b: number) => {
  const d = Math.abs(a - b) % TWO_PI;
  return Math.min(d, TWO_PI - d);
};

/** The inverse of the standard map, from p' = p + K sin q, q' = q + p': q = q' − p', then p = p' − K sin q. */
function inverse(K: number, q1: number, p1: number): [number, number] {
  const q = q1 - p1;
  return [q, p1 - K * Math.sin(q)];
}

describe('wrapAngle', () => {
  test('reduces into [0, 2π), negative angles included, and keeps the interval half-open', () => {
    expect(wrapAngle(1)).toBe(1);
    expect(wrapAngle(-1)).toBeCloseTo(TWO_PI - 1, 15);
    expect(wrapAngle(7 * TWO_PI + 0.5)).toBeCloseTo(0.5, 13);
    expect(wrapAngle(TWO_PI)).toBe(0);
    // −10⁻¹⁷ + 2π rounds to 2π, which must come back as 0
    expect(wrapAngle(-1e-17)).toBe(0);
    for (const q of [-1e6, -3.3, 0, 2.2, 1e6]) {
      const w = wrapAngle(q);
      expect(w >= 0 && w < TWO_PI).toBe(true);
      expect(angleGap(w, q)).toBeLessThan(1e-9);
    }
  });
});

describe('standardMap(K)', () => {
  test('the Jacobian matches central differences of the step, and its determinant is 1 (area preservation)', () => {
    const random = lcg(7);
    for (let i = 0; i < 200; i++) {
      const K = 10 * random() - 5;
      const [q, p] = [TWO_PI * random(), 12 * random() - 6];
      const map = standardMap(K);
      const J = map.jacobian(q, p);
      expect(Math.abs(J[0] * J[3] - J[1] * J[2] - 1)).toBeLessThan(8 * Number.EPSILON * (1 + Math.abs(K)));
      const h = 1e-6;
      const at = (dq: number, dp: number) => {
        const s = Float64Array.of(q + dq, p + dp);
        map.step(s);
        return s;
      };
      // q' is reduced mod 2π: its differences are taken on the circle, signed
      const dq = (a: Float64Array, b: Float64Array) => Math.atan2(Math.sin(a[0] - b[0]), Math.cos(a[0] - b[0]));
      const [qPlus, qMinus, pPlus, pMinus] = [at(h, 0), at(-h, 0), at(0, h), at(0, -h)];
      const differences = [dq(qPlus, qMinus), dq(pPlus, pMinus), qPlus[1] - qMinus[1], pPlus[1] - pMinus[1]].map((d) => d / (2 * h));
      for (let k = 0; k < 4; k++) expect(Math.abs(differences[k] - J[k])).toBeLessThan(1e-7 * (1 + Math.abs(K)));
    }
  });

  test('the inverse written here undoes a step to 1e-12, at random points and K', () => {
    const random = lcg(11);
    for (let i = 0; i < 500; i++) {
      const K = 20 * random() - 10;
      const [q, p] = [TWO_PI * random(), 20 * random() - 10];
      const s = Float64Array.of(q, p);
      standardMap(K).step(s);
      const [q0, p0] = inverse(K, s[0], s[1]);
      expect(angleGap(q0, q)).toBeLessThan(1e-12 * (1 + Math.abs(p)));
      expect(Math.abs(p0 - p)).toBeLessThan(1e-12 * (1 + Math.abs(K) + Math.abs(p)));
    }
  });

  test('q is reduced into [0, 2π) and p is not', () => {
    const s = Float64Array.of(Math.PI / 2, 6);
    const map = standardMap(5);
    map.step(s);
    // p' = 6 + 5 sin(π/2) = 11, q' = π/2 + 11 − 2·2π ≈ 0.0044, two turns taken off
    expect(s[1]).toBe(11);
    expect(s[0]).toBeCloseTo(Math.PI / 2 + 11 - 2 * TWO_PI, 13);
    for (let n = 0; n < 1000; n++) {
      map.step(s);
      expect(s[0] >= 0 && s[0] < TWO_PI).toBe(true);
    }
  });

  test('at K = 0, the free rotor: p_n = p_0 and q_n = q_0 + n·p_0 mod 2π', () => {
    const [q0, p0] = [0.3, 2.718281828];
    const s = Float64Array.of(q0, p0);
    const map = standardMap(0);
    for (let n = 1; n <= 1000; n++) {
      map.step(s);
      expect(s[1]).toBe(p0);
      expect(angleGap(s[0], q0 + n * p0)).toBeLessThan(1e-10);
    }
  });

  test('names itself and its coordinates', () => {
    const map = standardMap(0.97);
    expect(map.name).toContain('0.97');
    expect(map.names).toEqual(['q', 'p']);
  });

  test('a K that is not a finite number is refused in words', () => {
    for (const K of [NaN, Infinity, -Infinity, '1' as unknown as number, undefined as unknown as number]) {
      expect(() => standardMap(K)).toThrow(RangeError);
      expect(() => standardMap(K)).toThrow(/K must be a finite number/);
    }
  });
});
