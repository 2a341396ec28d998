/**
 * The chaos chapter's truths against independent values: the section's
 * radius by bisection on the Hénon–Heiles energy, the factor against the
 * reduction's kinetic energy expanded numerically, and Kepler's period
 * against a circular orbit's (2πR/v with the force balance mv²/R = k/R²)
 * and against a plain RK4 integration of an eccentric orbit.
 */
import { describe, expect, test } from 'vitest';
import { CHAOS_TRUTHS } from '../../../../../../widgets/chapter/exercise/truths/chaos.ts';

const { henonHeilesSectionRadius, anisotropicFactor, isotropicKeplerPeriod } = CHAOS_TRUTHS;

test('henonHeilesSectionRadius: the largest x on y = 0 with pₓ = p_y = 0 where H = E, by bisection on Hénon & Heiles’s H (1964)', () => {
  const H = (x: number, y: number, px: number, py: number) => (px * px + py * py) / 2 + (x * x + y * y) / 2 + x * x * y - y ** 3 / 3;
  for (const energy of [1 / 12, 1 / 8, 1 / 6]) {
    let [low, high] = [0, 2];
    for (let i = 0; i < 60; i++) {
      const mid = (low + high) / 2;
      if (H(mid, 0, 0, 0) <= energy) low = mid;
      else high = mid;
    }
    expect(henonHeilesSectionRadius.compute({ energy })).toBeCloseTo(low, 12);
  }
});

describe('anisotropicFactor', () => {
  /** The kinetic coefficient along u = c·x1 − x2 of Σp²: |∇u|² in the metric of Σp², computed from the gradient. */
  const along = (c: number) => c * c + (-1) * (-1);
  test('gives a = μ·b with b = 2, the coefficient of p_v for v = y1 − y2, at both signs', () => {
    for (const mu of [1, 9 / 8, 1.625]) {
      for (const sign of [1, -1]) expect(along(anisotropicFactor.compute({ mu, sign })) / 2).toBeCloseTo(mu, 14);
    }
  });
  test('the paper’s factor 1.5 has μ = 6.5/4 (Gutzwiller’s 1.625 for the heavy-to-light ratio)', () => {
    expect(anisotropicFactor.compute({ mu: 1.625, sign: 1 })).toBeCloseTo(1.5, 14);
  });
  test('no real factor gives μ < 1/2 along u', () => {
    expect(anisotropicFactor.compute({ mu: 0.4, sign: 1 })).toBeNaN();
  });
});

describe('isotropicKeplerPeriod', () => {
  test('a circular orbit: R = k/(2|E|), mv²/R = k/R², T = 2πR/v', () => {
    for (const [a, k, energy] of [[2, 1, -0.5], [3.25, 500, -40], [1, 2, -1]]) {
      const m = 1 / (2 * a);
      const R = k / (2 * Math.abs(energy));
      const v = Math.sqrt(k / (m * R));
      expect(isotropicKeplerPeriod.compute({ a, k, energy })).toBeCloseTo((2 * Math.PI * R) / v, 10);
    }
  });
  test('an eccentric orbit integrated by plain RK4 returns to its start after that period', () => {
    const [a, k] = [2, 1];
    // H = a(p_u² + p_v²) − k/r from (1, 0) with p = (0, 0.3): E = 2·0.09 − 1 = −0.82.
    const energy = a * 0.09 - k;
    const T = isotropicKeplerPeriod.compute({ a, k, energy });
    const field = ([u, v, pu, pv]: number[]) => {
      const r3 = Math.hypot(u, v) ** 3;
      return [2 * a * pu, 2 * a * pv, (-k * u) / r3, (-k * v) / r3];
    };
    let x = [1, 0, 0, 0.3];
    const steps = 20_000;
    const h = T / steps;
    for (let n = 0; n < steps; n++) {
      const k1 = field(x);
      const k2 = field(x.map((xi, i) => xi + (h / 2) * k1[i]));
      const k3 = field(x.map((xi, i) => xi + (h / 2) * k2[i]));
      const k4 = field(x.map((xi, i) => xi + h * k3[i]));
      x = x.map((xi, i) => xi + (h / 6) * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]));
    }
    expect(Math.hypot(x[0] - 1, x[1], x[2], x[3] - 0.3)).toBeLessThan(1e-6);
  });
  test('an unbound energy has no period', () => {
    expect(isotropicKeplerPeriod.compute({ a: 2, k: 1, energy: 0.1 })).toBeNaN();
  });
});
