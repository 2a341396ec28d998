/**
 * The parametric-resonance truths against sources outside the book's code:
 * the edges of the first tongue against the power series of Mathieu's
 * characteristic values (Abramowitz & Stegun, Handbook, 20.2.25), and the
 * growth rate at the band's centre against Landau & Lifshitz's first-order
 * s = uω/4 (§27), good to O(u³ω) there.
 */
import { describe, expect, test } from 'vitest';
import { floquetMultiplier, mathieuTrace, PARAMETRIC_TRUTHS, tongueEdge } from '../../../../../../widgets/chapter/exercise/truths/parametric.ts';

/**
 * q̈ + ω²(1 + u cos γt)q = 0 is Mathieu's y'' + (a − 2q̃ cos 2τ)y = 0 with τ = γt/2 + π/2,
 * a = 4ω²/γ², q̃ = 2ω²u/γ². The first tongue lies between b₁(q̃) and a₁(q̃) (A&S 20.2.25).
 */
const a1 = (q: number) => 1 + q - q ** 2 / 8 - q ** 3 / 64 - q ** 4 / 1536 + (11 * q ** 5) / 36864;
const b1 = (q: number) => 1 - q - q ** 2 / 8 + q ** 3 / 64 - q ** 4 / 1536 - (11 * q ** 5) / 36864;

describe('tongueEdge', () => {
  test.each([0.1, 0.3])('at u = %f both edges lie on Mathieu’s characteristic curves a = b₁(q̃) and a = a₁(q̃)', (u) => {
    const omega = 10;
    for (const [side, curve] of [[1, b1], [-1, a1]] as const) {
      const gamma = tongueEdge(omega, u, side);
      const q = (2 * omega * omega * u) / (gamma * gamma);
      // The series' first neglected term is of order q̃⁶ ≈ 5·10⁻⁶ at u = 0.3.
      expect(Math.abs((4 * omega * omega) / (gamma * gamma) - curve(q))).toBeLessThan(1e-5);
    }
  });
  test('at u = 0.3, ω = 10 the upper edge is below the first-order 21.5, near the second-order 21.4719 (Landau & Lifshitz §27, problem 1)', () => {
    const edge = tongueEdge(10, 0.3, 1);
    expect(Math.abs(edge - (21.5 - (0.09 * 10) / 32))).toBeLessThan(0.3 * 0.028);
    expect(Math.abs(mathieuTrace(10, 0.3, edge))).toBeCloseTo(2, 6);
  });
  test('no depth, no tongue: NaN', () => {
    expect(tongueEdge(10, 0, 1)).toBeNaN();
  });
});

describe('floquetMultiplier and floquetGrowth', () => {
  test('at the centre of a shallow band the growth rate is Landau & Lifshitz’s uω/4', () => {
    for (const u of [0.02, 0.05]) {
      const omega = 10, gamma = 2 * omega - (u * u * omega) / 32;
      const s = PARAMETRIC_TRUTHS.floquetGrowth.compute({ omega, u, gamma });
      expect(Math.abs(s - (u * omega) / 4)).toBeLessThan(u * ((u * u * omega) / 32) + 1e-9);
    }
  });
  test('in the first tongue the larger multiplier is negative, |λ| = e^{sT}; outside it, |λ| = 1 (det M = 1)', () => {
    const lambda = floquetMultiplier(10, 0.3, 20);
    expect(lambda).toBeLessThan(-1);
    const s = PARAMETRIC_TRUTHS.floquetGrowth.compute({ omega: 10, u: 0.3, gamma: 20 });
    expect(Math.log(-lambda)).toBeCloseTo((s * 2 * Math.PI) / 20, 12);
    expect(floquetMultiplier(10, 0.3, 24)).toBe(1);
  });
});
