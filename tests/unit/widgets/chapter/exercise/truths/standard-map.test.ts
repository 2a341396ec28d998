/**
 * The standard-map truths (widgets/chapter/exercise/truths/standard-map.ts)
 * against the stability of the orbits themselves, computed here: the
 * eigenvalues of the product of the map's Jacobians [[1 + K cos q, 1],
 * [K cos q, 1]] along the orbit leave the unit circle just above each limit
 * and not just below it (Greene 1979); and Chirikov's overlap, the K at
 * which two pendulum separatrices of half-width 2√K, 2π apart, touch.
 */
import { expect, test } from 'vitest';
import { computeTruth } from '../../../../../../widgets/chapter/exercise/truths.ts';

const value = (name: string) => {
  const truth = computeTruth(name, {});
  if (!('value' in truth)) throw new Error(truth.error);
  return truth.value;
};

type Matrix = [number, number, number, number];
const jacobian = (K: number, q: number): Matrix => [1 + K * Math.cos(q), 1, K * Math.cos(q), 1];
const times = ([a, b, c, d]: Matrix, [e, f, g, h]: Matrix): Matrix => [a * e + b * g, a * f + b * h, c * e + d * g, c * f + d * h];
/** Stable when both eigenvalues lie on the unit circle: |trace| < 2 for determinant 1. */
const stable = (m: Matrix) => Math.abs(m[0] + m[3]) < 2;

test('mainIslandLimit: the fixed point (π, 0) is stable just below it and unstable just above', () => {
  const K = value('mainIslandLimit');
  expect(stable(jacobian(K * 0.999, Math.PI))).toBe(true);
  expect(stable(jacobian(K * 1.001, Math.PI))).toBe(false);
});

test('halfResonanceLimit: the period-2 orbit (0, π) → (π, π) is an orbit, stable just below the limit and unstable above', () => {
  const K = value('halfResonanceLimit');
  // (0, π) → p' = π + K sin 0 = π, q' = π → p'' = π + K sin π = π, q'' = 2π: back at the start
  let [q, p] = [0, Math.PI];
  for (let n = 0; n < 2; n++) {
    p += K * Math.sin(q);
    q += p;
  }
  expect(Math.abs(p - Math.PI)).toBeLessThan(1e-12);
  expect(Math.abs(q - 2 * Math.PI)).toBeLessThan(1e-12);
  const around = (k: number) => times(jacobian(k, Math.PI), jacobian(k, 0));
  expect(stable(around(K * 0.999))).toBe(true);
  expect(stable(around(K * 1.001))).toBe(false);
});

test('primaryOverlap: the separatrices of half-width 2√K about p = 0 and p = 2π touch', () => {
  const K = value('primaryOverlap');
  expect(2 * Math.sqrt(K) + 2 * Math.sqrt(K)).toBeCloseTo(2 * Math.PI, 12);
});
