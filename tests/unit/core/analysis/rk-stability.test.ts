/**
 * The stability of four-stage fourth-order Runge–Kutta methods on an
 * oscillation (core/analysis/rk-stability.ts): the limit against its closed
 * form ωΔt = 2√2 (Hairer & Wanner II, §IV.2), and the amplification against
 * one step of the 3/8 rule's own Butcher tableau (Hairer, Nørsett & Wanner
 * I, §II.1), applied to ż = iωz in complex arithmetic.
 */
import { describe, expect, test } from 'vitest';
import { rk4Amplification, rk4StabilityLimit } from '../../../../core/analysis/rk-stability.ts';

type Complex = [number, number];
const mul = ([a, b]: Complex, [c, d]: Complex): Complex => [a * c - b * d, a * d + b * c];
const add = (...zs: Complex[]): Complex => zs.reduce(([a, b], [c, d]) => [a + c, b + d], [0, 0]);
const scale = (s: number, [a, b]: Complex): Complex => [s * a, s * b];

/** |z₁| after one step of the 3/8 rule on ż = λz, z₀ = 1, λΔt = iy. */
function threeEighthsStep(y: number): number {
  const f = (z: Complex) => mul([0, y], z);
  const z0: Complex = [1, 0];
  const k1 = f(z0);
  const k2 = f(add(z0, scale(1 / 3, k1)));
  const k3 = f(add(z0, scale(-1 / 3, k1), k2));
  const k4 = f(add(z0, k1, scale(-1, k2), k3));
  const [re, im] = add(z0, scale(1 / 8, add(k1, scale(3, k2), scale(3, k3), k4)));
  return Math.hypot(re, im);
}

describe('RK4-family stability', () => {
  test('the limit is ωΔt = 2√2', () => {
    expect(rk4StabilityLimit()).toBeCloseTo(2 * Math.SQRT2, 12);
  });

  test('the amplification is one step of the 3/8 rule on an oscillation', () => {
    for (const y of [0.1, 1, 2.5, 2.8, 2.9, 5]) expect(rk4Amplification(y)).toBeCloseTo(threeEighthsStep(y), 12);
  });

  test('below the limit a step never grows the amplitude, above it always does', () => {
    expect(rk4Amplification(2.8)).toBeLessThan(1);
    expect(rk4Amplification(2.86)).toBeGreaterThan(1);
  });
});
