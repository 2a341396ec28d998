/**
 * The action–angle truths (widgets/chapter/exercise/truths/action-angle.ts)
 * against quadratures written here: the area of the loop H = E over 2π,
 * (1/2π)∮p dq, with q = a sin φ for the oscillator and sin(q/2) = k sin φ for
 * the pendulum, so that each integrand is smooth and periodic in φ and the
 * trapezoid rule is exact to rounding (Landau & Lifshitz §49, §50); and the
 * pendulum's frequency 2π/T from its period T = ∮dq/p by the same change of
 * variable.
 */
import { expect, test } from 'vitest';
import { computeTruth } from '../../../../../../widgets/chapter/exercise/truths.ts';

const value = (name: string, args: Record<string, number>) => {
  const truth = computeTruth(name, args);
  if (!('value' in truth)) throw new Error(truth.error);
  return truth.value;
};

/** The trapezoid rule over a whole period [0, 2π) of a smooth periodic integrand. */
const aroundLoop = (f: (phi: number) => number, n = 512) => ((2 * Math.PI) / n) * Array.from({ length: n }, (_, i) => f((2 * Math.PI * i) / n)).reduce((a, b) => a + b, 0);

test('harmonicAction is the ellipse’s area over 2π: q = a sin φ, p = aω cos φ, dq = a cos φ dφ', () => {
  for (const [E, omega] of [[2, 4], [0.5, 1], [3, 0.2]]) {
    const a = Math.sqrt(2 * E) / omega;
    const area = aroundLoop((phi) => a * omega * Math.cos(phi) * a * Math.cos(phi));
    expect(value('harmonicAction', { E, omega })).toBeCloseTo(area / (2 * Math.PI), 12);
  }
});

test('pendulumAction and pendulumFrequency are the loop’s area over 2π and 2π over its period, by quadrature', () => {
  for (const [q0, omega] of [[0.5, 1], [2, 1], [3, 2.5]]) {
    const k = Math.sin(q0 / 2);
    const root = (phi: number) => Math.sqrt(1 - k * k * Math.sin(phi) ** 2);
    // p = 2ωk cos φ, dq = 2k cos φ dφ / √(1 − k² sin²φ); dt = dq/p = dφ/(ω√(1 − k² sin²φ))
    const area = aroundLoop((phi) => (4 * omega * k * k * Math.cos(phi) ** 2) / root(phi));
    const period = aroundLoop((phi) => 1 / (omega * root(phi)));
    expect(value('pendulumAction', { q0, omega }) / (area / (2 * Math.PI))).toBeCloseTo(1, 12);
    expect(value('pendulumFrequency', { q0, omega }) / ((2 * Math.PI) / period)).toBeCloseTo(1, 12);
  }
});

test('released at rest from the top, on the separatrix, the pendulum has neither: its period is infinite', () => {
  expect(value('pendulumAction', { q0: Math.PI, omega: 1 })).toBeNaN();
  expect(value('pendulumFrequency', { q0: Math.PI, omega: 1 })).toBeNaN();
});
