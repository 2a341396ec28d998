/**
 * The period integral by quadrature (core/analysis/well-period.ts), against
 * closed forms: the harmonic oscillator's 2π/ω (Landau & Lifshitz §21), the
 * pendulum's 4K(k)/ω (§11, problem 1; Abramowitz & Stegun 17.6), and the
 * anharmonic oscillator's Lindstedt series ω₀ + ω₂b² + (2αω₂/ω₀²)b³
 * (Landau & Lifshitz §28, translated to the paper's coefficients) at small b.
 */
import { describe, expect, test } from 'vitest';
import { completeEllipticK } from '../../../../core/analysis/pendulum.ts';
import { turningPoint, wellPeriod } from '../../../../core/analysis/well-period.ts';

const anharmonic = (omega0: number, alpha: number, beta: number) => (q: number) => (omega0 ** 2 * q * q) / 2 + alpha * q ** 3 + beta * q ** 4;

describe('wellPeriod(V, b)', () => {
  test('a harmonic well gives 2π/ω at any amplitude, to 10⁻⁸', () => {
    for (const [omega, b] of [[10, 1], [3, 0.01], [0.5, 40]]) {
      expect(Math.abs((wellPeriod((q) => (omega * omega * q * q) / 2, b) * omega) / (2 * Math.PI) - 1)).toBeLessThan(1e-8);
    }
  });

  test('the pendulum V = −ω² cos q gives 4K(sin(b/2))/ω, up to b = 3.1 near the separatrix', () => {
    for (const b of [0.1, 1, 2, 3, 3.1]) {
      const exact = (4 * completeEllipticK(Math.sin(b / 2))) / 2;
      expect(wellPeriod((q) => -4 * Math.cos(q), b) / exact - 1).toBeLessThan(1e-9);
      expect(wellPeriod((q) => -4 * Math.cos(q), -b) / exact - 1).toBeLessThan(1e-9);
    }
  });

  test('the anharmonic oscillator at small b follows the Lindstedt series to within its next term, c₄b⁴ with |c₄| ≈ ω₂²/ω₀', () => {
    const [omega0, alpha, beta] = [10, -2, -3];
    const omega2 = (3 * beta) / (2 * omega0) - (15 * alpha ** 2) / (4 * omega0 ** 3);
    for (const b of [0.05, 0.1, 0.2]) {
      const omega = (2 * Math.PI) / wellPeriod(anharmonic(omega0, alpha, beta), b);
      const series = omega0 + omega2 * b ** 2 + ((2 * alpha * omega2) / omega0 ** 2) * b ** 3;
      expect(Math.abs(omega - series)).toBeLessThan(3 * (omega2 ** 2 / omega0) * b ** 4);
    }
  });

  test('released beyond a barrier, or at the bottom, there is no period (NaN)', () => {
    const V = anharmonic(10, -2, -3);
    // The barrier's top is at the root 2.6476 of V'(q)/q = 100 − 6q − 12q².
    expect(wellPeriod(V, 2.64)).toBeGreaterThan(0);
    expect(wellPeriod(V, 2.65)).toBeNaN();
    expect(wellPeriod(V, 0)).toBeNaN();
    expect(wellPeriod((q) => -Math.cos(q), 3.2)).toBeNaN();
  });

  test('turning points solve V(q) = E on each side', () => {
    const V = anharmonic(10, -2, -3);
    const energy = V(1);
    const left = turningPoint(V, energy, 0, -1);
    expect(left).toBeLessThan(0);
    expect(V(left)).toBeCloseTo(energy, 9);
    expect(turningPoint(V, energy, 0, 1)).toBeCloseTo(1, 12);
  });
});
