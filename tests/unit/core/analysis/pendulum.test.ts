/**
 * The pendulum's action–angle closed forms (core/analysis/pendulum.ts)
 * against independent truths: E(k) against Abramowitz & Stegun Table 17.1,
 * its limits (π/2 at k = 0, A&S 17.3.36's 1 + (k′²/2)(ln(4/k′) − 1/2) as
 * k → 1), Legendre's relation EK′ + E′K − KK′ = π/2 (A&S 17.3.13) and the
 * defining integral by the trapezoid rule here; the action against
 * (1/2π)∮p dq by quadrature here and the harmonic limit E₀/ω(1 + E₀/16ω²)
 * (the series of Landau & Lifshitz §50's integral); the frequency against
 * 2π/T and against dH/dJ by central differences of the action in the energy.
 */
import { describe, expect, test } from 'vitest';
import { completeEllipticE, completeEllipticK, pendulumAction, pendulumFrequency, pendulumPeriod } from '../../../../core/analysis/pendulum.ts';

const degrees = (a: number) => (a * Math.PI) / 180;

/**
 * ∫₀^{π/2} f(θ) dθ by the trapezoid rule on m intervals: for an even,
 * π-periodic smooth f, such as √(1 − k² sin²θ), it converges geometrically
 * (Trefethen & Weideman, SIAM Review 56, 2014).
 */
function quarterPeriod(f: (theta: number) => number, m = 2000): number {
  const h = Math.PI / 2 / m;
  let sum = (f(0) + f(Math.PI / 2)) / 2;
  for (let i = 1; i < m; i++) sum += f(i * h);
  return sum * h;
}

/** H + ω² = p²/2 + ω²(1 − cos q) = p²/2 + 2ω² sin²(q/2), the energy above the bottom of the well. */
const energyAboveBottom = (q: number, p: number, omega: number) => (p * p) / 2 + 2 * omega * omega * Math.sin(q / 2) ** 2;

describe('completeEllipticE(k)', () => {
  test('matches A&S Table 17.1: E(0) = π/2, E(sin 30°) = 1.4674622093, E(sin 60°) = 1.2110560276', () => {
    expect(completeEllipticE(0)).toBe(Math.PI / 2);
    expect(completeEllipticE(Math.sin(degrees(30)))).toBeCloseTo(1.4674622093, 10);
    expect(completeEllipticE(Math.sin(degrees(60)))).toBeCloseTo(1.2110560276, 10);
    expect(completeEllipticE(-Math.sin(degrees(60)))).toBe(completeEllipticE(Math.sin(degrees(60))));
  });

  test('is the integral ∫₀^{π/2} √(1 − k² sin²θ) dθ, summed here by the trapezoid rule', () => {
    for (const k of [0.05, 0.3, 0.7, 0.9, 0.99]) {
      const integral = quarterPeriod((theta) => Math.sqrt(1 - k * k * Math.sin(theta) ** 2));
      expect(Math.abs(completeEllipticE(k) - integral)).toBeLessThan(1e-13);
    }
  });

  test('tends to 1 as k → 1 as 1 + (k′²/2)(ln(4/k′) − 1/2) + (3k′⁴/16)(ln(4/k′) − 13/12) (A&S 17.3.36; the next term is (15k′⁶/128)(ln(4/k′) − 6/5)), and is NaN from k = 1 on', () => {
    for (const kPrime of [0.05, 1e-2, 1e-3, 1e-5]) {
      const k = Math.sqrt(1 - kPrime * kPrime);
      const L = Math.log(4 / kPrime);
      const asymptote = 1 + ((kPrime * kPrime) / 2) * (L - 0.5) + ((3 * kPrime ** 4) / 16) * (L - 13 / 12);
      expect(Math.abs(completeEllipticE(k) - asymptote)).toBeLessThan((15 / 128) * kPrime ** 6 * L + 4e-15); // rounding: E = K·(1 − Σ), K ≈ 12 times the sum’s 10⁻¹⁶
    }
    expect(completeEllipticE(1 - 1e-15)).toBeCloseTo(1, 12);
    expect(completeEllipticE(1)).toBeNaN();
    expect(completeEllipticE(1.5)).toBeNaN();
    expect(completeEllipticE(NaN)).toBeNaN();
  });

  test('satisfies Legendre’s relation E(k)K(k′) + E(k′)K(k) − K(k)K(k′) = π/2, k′ = √(1 − k²) (A&S 17.3.13)', () => {
    for (const k of [0.01, 0.2, Math.SQRT1_2, 0.8, 0.95, 0.999]) {
      const kPrime = Math.sqrt(1 - k * k);
      const [E, K, Ep, Kp] = [completeEllipticE(k), completeEllipticK(k), completeEllipticE(kPrime), completeEllipticK(kPrime)];
      expect(Math.abs(E * Kp + Ep * K - K * Kp - Math.PI / 2)).toBeLessThan(1e-14 * K * Kp);
    }
  });
});

describe('pendulumAction(q0, p0, ω)', () => {
  test('is (1/2π)∮p dq, by quadrature here: with sin(q/2) = k sin φ, J = (8ωk²/π)∫₀^{π/2} cos²φ/√(1 − k² sin²φ) dφ', () => {
    for (const omega of [1, 2.5]) {
      for (const k of [0.1, 0.5, 0.8, 0.95]) {
        const integral = quarterPeriod((phi) => Math.cos(phi) ** 2 / Math.sqrt(1 - k * k * Math.sin(phi) ** 2));
        const exact = ((8 * omega * k * k) / Math.PI) * integral;
        // started at the turning point q = 2 asin k, and at the bottom with p = 2ωk: one orbit
        expect(pendulumAction(2 * Math.asin(k), 0, omega) / exact - 1).toBeCloseTo(0, 12);
        expect(pendulumAction(0, 2 * omega * k, omega) / exact - 1).toBeCloseTo(0, 12);
      }
    }
  });

  test('tends to the harmonic oscillator’s E₀/ω for small swings, with the correction E₀/ω·E₀/16ω², to rounding even at k = 10⁻⁶', () => {
    const omega = 1.7;
    for (const k of [1e-6, 1e-4, 1e-2]) {
      const E0 = energyAboveBottom(0, 2 * omega * k, omega);
      const J = pendulumAction(0, 2 * omega * k, omega);
      // J = 2ωk²(1 + k²/8 + 3k⁴/64 + O(k⁶)) from the integral above, E₀/ω = 2ωk² and E₀/16ω² = k²/8: the remainder is 3k⁴/64
      expect(Math.abs(J / (E0 / omega) - 1 - E0 / (16 * omega * omega))).toBeLessThan((3 / 64) * k ** 4 * 1.01 + 1e-15);
    }
  });

  test('is NaN for a rotation, over the top (H ≥ ω²), and for ω = 0', () => {
    expect(pendulumAction(0, 2.5)).toBeNaN();
    expect(pendulumAction(Math.PI, 0)).toBeNaN();
    expect(pendulumAction(0, 1, 0)).toBeNaN();
  });
});

describe('pendulumFrequency(q0, p0, ω)', () => {
  test('is 2π/T, with T from pendulumPeriod, and ω at the bottom', () => {
    for (const q0 of [0.1, 1, 2, 3]) expect(pendulumFrequency(q0, 0, 1.3) / ((2 * Math.PI) / pendulumPeriod(q0, 0, 1.3))).toBeCloseTo(1, 13);
    expect(pendulumFrequency(0, 1e-8, 1.3)).toBeCloseTo(1.3, 14);
    expect(pendulumFrequency(0, 2.7, 1.3)).toBeNaN();
  });

  test('is ∂H/∂J: the central difference 2δ/(J(E₀ + δ) − J(E₀ − δ)) agrees to 10⁻⁷ at k = 0.3, 0.7, 0.95', () => {
    const omega = 1.3;
    for (const k of [0.3, 0.7, 0.95]) {
      // at the bottom, q = 0, E₀ = p²/2 = 2ω²k²
      const E0 = 2 * omega * omega * k * k;
      const delta = 1e-5 * E0;
      const action = (e: number) => pendulumAction(0, Math.sqrt(2 * e), omega);
      const dHdJ = (2 * delta) / (action(E0 + delta) - action(E0 - delta));
      expect(Math.abs(dHdJ / pendulumFrequency(0, 2 * omega * k, omega) - 1)).toBeLessThan(1e-7);
    }
  });
});
