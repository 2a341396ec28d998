/**
 * The integrator chapter's truths against independent values: the 3/8
 * rule's fourth moment against the error term of Simpson's 3/8 quadrature
 * (the same weights and nodes), and Verlet's energy band and stability limit
 * against a plain leapfrog loop written here.
 */
import { describe, expect, test } from 'vitest';
import { INTEGRATOR_TRUTHS } from '../../../../../../widgets/chapter/exercise/truths/integrators.ts';

const { rk38WeightMoment, verletEnergyBand, verletStableStep } = INTEGRATOR_TRUTHS;

describe('rk38WeightMoment', () => {
  test('integrates cubics exactly, Σ bᵢcᵢᵏ = 1/(k + 1) for k ≤ 3 (the order conditions of the bushy trees)', () => {
    for (const power of [0, 1, 2, 3]) expect(rk38WeightMoment.compute({ power })).toBeCloseTo(1 / (power + 1), 15);
  });
  test('misses x⁴ by Simpson’s 3/8 error term, −(3/80)h⁵f⁗ with h = 1/3 (Abramowitz & Stegun 25.4.13): 1/5 + 1/270 = 11/54', () => {
    const error = (3 / 80) * (1 / 3) ** 5 * 24;
    expect(rk38WeightMoment.compute({ power: 4 })).toBeCloseTo(1 / 5 + error, 15);
    expect(rk38WeightMoment.compute({ power: 4 })).toBeCloseTo(11 / 54, 15);
  });
  test('has no value for a power that is not a whole number', () => {
    expect(rk38WeightMoment.compute({ power: 1.5 })).toBeNaN();
  });
});

/** Largest |H − H₀|/H₀ of a plain kick–drift–kick loop on p²/2 + ω²q²/2 from (1, 0); Infinity once it overflows. */
function leapfrogEnergyError(omega: number, h: number, steps: number): number {
  let [q, p, worst] = [1, 0, 0];
  const initial = (omega * omega) / 2;
  for (let n = 0; n < steps; n++) {
    p -= (h / 2) * omega * omega * q;
    q += h * p;
    p -= (h / 2) * omega * omega * q;
    const energy = (p * p + omega * omega * q * q) / 2;
    if (!Number.isFinite(energy)) return Infinity;
    worst = Math.max(worst, Math.abs(energy - initial) / initial);
  }
  return worst;
}

describe('verletEnergyBand', () => {
  test('equals the largest energy error of a leapfrog loop over 10⁵ steps, to its sampling of the peak', () => {
    for (const [omega, h] of [[1, 0.1], [2, 0.3], [3, 0.05]]) {
      const measured = leapfrogEnergyError(omega, h, 100_000);
      expect(Math.abs(measured / verletEnergyBand.compute({ omega, h }) - 1)).toBeLessThan(1e-3);
    }
  });
  test('has no value beyond the stability limit', () => {
    expect(verletEnergyBand.compute({ omega: 1, h: 2.5 })).toBeNaN();
  });
});

describe('verletStableStep', () => {
  test('a leapfrog loop stays bounded 1 % below the limit and overflows 1 % above it', () => {
    for (const omega of [1, 1.25, 10]) {
      const limit = verletStableStep.compute({ omega });
      expect(leapfrogEnergyError(omega, 0.99 * limit, 10_000)).toBeLessThan(100);
      expect(leapfrogEnergyError(omega, 1.01 * limit, 10_000)).toBe(Infinity);
    }
  });
});
