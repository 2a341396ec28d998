/**
 * The restricted three-body problem's closed forms and roots
 * (core/analysis/three-body.ts), against independent truths: the collinear
 * points against the force balance ∂Ω/∂x = 0 solved here by its own
 * bisection, against the Earth–Moon values as mission designers tabulate
 * them (μ = 0.012150585) and against Hill's limit γ → (μ/3)^{1/3} with its
 * next term (Murray & Dermott ch. 3); L4's roots against the characteristic polynomial
 * of the linearised equations, built here from Ω's second derivatives by
 * finite differences; Routh's μ against 27μ(1 − μ) = 1.
 */
import { describe, expect, test } from 'vitest';
import { effectivePotential, jacobiConstant, lagrangePoints, ROUTH_MU, triangularModes, zeroVelocityCurve } from '../../../../core/analysis/three-body.ts';

/** ∂Ω/∂x on the axis, written out from Ω = x²/2 + (1 − μ)/|x + μ| + μ/|x − 1 + μ|. */
const axialForce = (x: number, mu: number) => x - ((1 - mu) * (x + mu)) / Math.abs(x + mu) ** 3 - (mu * (x - 1 + mu)) / Math.abs(x - 1 + mu) ** 3;

function bisect(f: (x: number) => number, a: number, b: number): number {
  let lo = a;
  let hi = b;
  for (let i = 0; i < 200; i++) {
    const mid = (lo + hi) / 2;
    if (Math.sign(f(mid)) === Math.sign(f(lo))) lo = mid;
    else hi = mid;
  }
  return (lo + hi) / 2;
}

describe('lagrangePoints(μ)', () => {
  test('L1, L2, L3 balance the forces on the axis, for μ from 10⁻⁶ to 1/2', () => {
    for (const mu of [1e-6, 1e-3, 0.0121505856, 0.1, 0.3, 0.5]) {
      const [l1, l2, l3] = lagrangePoints(mu);
      const eps = 1e-9;
      expect(Math.abs(l1.x - bisect((x) => axialForce(x, mu), -mu + eps, 1 - mu - eps))).toBeLessThan(1e-12);
      expect(Math.abs(l2.x - bisect((x) => axialForce(x, mu), 1 - mu + eps, 3))).toBeLessThan(1e-12);
      expect(Math.abs(l3.x - bisect((x) => axialForce(x, mu), -3, -mu - eps))).toBeLessThan(1e-12);
    }
  });

  test('the Earth–Moon points, μ = 0.012150585: L1 = 0.836915, L2 = 1.155682, L3 = −1.005063', () => {
    const [l1, l2, l3] = lagrangePoints(0.012150585);
    expect(l1.x).toBeCloseTo(0.836915, 5);
    expect(l2.x).toBeCloseTo(1.155682, 5);
    expect(l3.x).toBeCloseTo(-1.005063, 5);
  });

  test('for small μ, L1 and L2 tend to Hill’s distance (μ/3)^{1/3} from m2, and L3 to x = −1 − 5μ/12', () => {
    const mu = 1e-9;
    const hill = Math.cbrt(mu / 3);
    const [l1, l2, l3] = lagrangePoints(mu);
    // the next term is ∓hill²/3 (Hill's series, Murray & Dermott ch. 3)
    expect(Math.abs(1 - mu - l1.x - (hill - hill ** 2 / 3))).toBeLessThan(hill ** 3);
    expect(Math.abs(l2.x - (1 - mu) - (hill + hill ** 2 / 3))).toBeLessThan(hill ** 3);
    expect(Math.abs(-mu - l3.x - (1 - (7 * mu) / 12))).toBeLessThan(1e-12);
  });

  test('L4 and L5 are equidistant from both primaries, at distance 1, and all five are equilibria', () => {
    const mu = 0.2;
    for (const p of lagrangePoints(mu)) {
      const h = 1e-6;
      const gx = (effectivePotential(p.x + h, p.y, mu) - effectivePotential(p.x - h, p.y, mu)) / (2 * h);
      const gy = (effectivePotential(p.x, p.y + h, mu) - effectivePotential(p.x, p.y - h, mu)) / (2 * h);
      expect(Math.hypot(gx, gy)).toBeLessThan(1e-8);
      // at rest in the rotating frame: px = −y, py = x, and C = 2Ω
      expect(jacobiConstant([p.x, p.y, -p.y, p.x], mu)).toBeCloseTo(p.jacobi, 12);
    }
    const l4 = lagrangePoints(mu)[3];
    expect(Math.hypot(l4.x + mu, l4.y)).toBeCloseTo(1, 14);
    expect(Math.hypot(l4.x - 1 + mu, l4.y)).toBeCloseTo(1, 14);
  });

  test('a mass ratio outside (0, 1/2] is refused in words', () => {
    expect(() => lagrangePoints(0)).toThrow(/μ must lie/);
    expect(() => lagrangePoints(0.7)).toThrow(/μ must lie/);
    expect(() => lagrangePoints(NaN)).toThrow(/μ must lie/);
  });
});

describe('triangularModes(μ)', () => {
  /** λ⁴ + (4 − Ωxx − Ωyy)λ² + ΩxxΩyy − Ωxy² of the linearised equations at L4, by finite differences of Ω. */
  function characteristic(mu: number) {
    const [x, y] = [0.5 - mu, Math.sqrt(3) / 2];
    const h = 1e-4;
    const O = (a: number, b: number) => effectivePotential(a, b, mu);
    const xx = (O(x + h, y) - 2 * O(x, y) + O(x - h, y)) / h ** 2;
    const yy = (O(x, y + h) - 2 * O(x, y) + O(x, y - h)) / h ** 2;
    const xy = (O(x + h, y + h) - O(x + h, y - h) - O(x - h, y + h) + O(x - h, y - h)) / (4 * h * h);
    return { b: 4 - xx - yy, c: xx * yy - xy * xy };
  }

  test('below Routh’s μ, ±iω solve the characteristic polynomial of the linearised motion (both roots)', () => {
    for (const mu of [1e-4, 0.01, 0.0121505856, 0.03]) {
      const m = triangularModes(mu);
      if (!m.stable) throw new Error(`μ = ${mu} is below Routh's value`);
      const { b, c } = characteristic(mu);
      for (const omega of [m.libration, m.epicycle]) expect(Math.abs(omega ** 4 - b * omega ** 2 + c)).toBeLessThan(1e-6);
      expect(m.libration).toBeLessThan(m.epicycle);
    }
    // small μ: the libration frequency tends to √(27μ/4), the epicycle to 1 (Murray & Dermott §3.8)
    const small = triangularModes(1e-8);
    if (!small.stable) throw new Error('μ = 1e-8 is stable');
    expect(small.libration / Math.sqrt((27 * 1e-8) / 4)).toBeCloseTo(1, 6);
    expect(small.epicycle).toBeCloseTo(1, 6);
  });

  test('above Routh’s μ, a ± ib with a > 0 solves it (a complex root), and a grows from 0 at μ_Routh', () => {
    for (const mu of [0.04, 0.1, 0.5]) {
      const m = triangularModes(mu);
      if (m.stable) throw new Error(`μ = ${mu} is above Routh's value`);
      const { b, c } = characteristic(mu);
      // λ² = (a + ib)² = a² − b² + 2iab; |λ⁴ + bλ² + c| from its real and imaginary parts
      const [re, im] = [m.growth ** 2 - m.rotation ** 2, 2 * m.growth * m.rotation];
      const [re2, im2] = [re * re - im * im, 2 * re * im];
      expect(Math.hypot(re2 + b * re + c, im2 + b * im)).toBeLessThan(1e-6);
      expect(m.growth).toBeGreaterThan(0);
    }
    expect(triangularModes(ROUTH_MU * (1 + 1e-9)).growth).toBeLessThan(1e-3);
  });

  test('Routh’s value solves 27μ(1 − μ) = 1 and is 0.0385209', () => {
    expect(27 * ROUTH_MU * (1 - ROUTH_MU)).toBeCloseTo(1, 14);
    expect(ROUTH_MU).toBeCloseTo(0.0385209, 7);
    expect(triangularModes(ROUTH_MU * 0.999).stable).toBe(true);
    expect(triangularModes(ROUTH_MU * 1.001).stable).toBe(false);
  });
});

describe('zeroVelocityCurve(μ, C)', () => {
  test('its points lie on 2Ω = C to the grid’s interpolation error, and the forbidden points below it', () => {
    const mu = 0.1;
    const C = 3.6;
    const { curve, forbidden } = zeroVelocityCurve(mu, C);
    expect(curve.length).toBeGreaterThan(100);
    // linear interpolation over a spacing h = 0.02 errs by about h²|∂²(2Ω)| / 8 relative to |∇(2Ω)|: well under 1 %
    for (const [x, y] of curve) expect(Math.abs(2 * effectivePotential(x, y, mu) - C) / C).toBeLessThan(0.01);
    expect(forbidden.length).toBeGreaterThan(10);
    for (const [x, y] of forbidden) expect(2 * effectivePotential(x, y, mu)).toBeLessThan(C);
  });

  test('below the Jacobi constant at L4, 3 − μ(1 − μ), no point is forbidden and there is no curve (Ω is least at L4 and L5)', () => {
    const mu = 0.01;
    const { curve, forbidden } = zeroVelocityCurve(mu, 3 - mu * (1 - mu) - 1e-6);
    expect(curve).toEqual([]);
    expect(forbidden).toEqual([]);
  });
});
