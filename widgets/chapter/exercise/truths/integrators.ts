/**
 * Truths for “How the simulator integrates”: the 3/8 rule's quadrature
 * moments (its order conditions for the bushy trees), and Störmer–Verlet on
 * the harmonic oscillator, where its step is a linear map whose invariant
 * and stability are found by hand. Each is a closed form, computed without
 * running any integrator.
 */
import type { Truth } from '../truth.ts';

/** The 3/8 rule's weights and nodes (Kutta 1901; Hairer, Nørsett & Wanner I, §II.1, Table 1.2). */
const WEIGHTS = [1 / 8, 3 / 8, 3 / 8, 1 / 8];
const NODES = [0, 1 / 3, 2 / 3, 1];

export const INTEGRATOR_TRUTHS: Readonly<Record<string, Truth>> = {
  rk38WeightMoment: {
    args: ['power'],
    compute: ({ power }) => (Number.isInteger(power) && power >= 0 ? WEIGHTS.reduce((sum, b, i) => sum + b * NODES[i] ** power, 0) : NaN),
    method: 'Σ bᵢcᵢᵏ from the 3/8 rule’s tableau (Hairer, Nørsett & Wanner I, §II.1 and §II.2, the condition of the bushy tree), exact to rounding',
  },
  verletEnergyBand: {
    args: ['omega', 'h'],
    // From a turning point the step conserves p² + ω²(1 − h²ω²/4)q², so H/H₀ ranges over [1 − (ωh)²/4, 1].
    compute: ({ omega, h }) => ((omega * h) ** 2 < 4 ? (omega * h) ** 2 / 4 : NaN),
    method: 'closed form (ωh)²/4: Störmer–Verlet on H = p²/2 + ω²q²/2 conserves p² + ω²(1 − h²ω²/4)q² exactly (the step’s invariant, from its 2 × 2 matrix; Störmer–Verlet in Hairer, Lubich & Wanner, Geometric Numerical Integration, §I.3), so from a turning point H falls at most by that share of H₀',
  },
  verletStableStep: {
    args: ['omega'],
    compute: ({ omega }) => 2 / Math.abs(omega),
    method: 'closed form h = 2/ω: the Verlet step on the harmonic oscillator is a matrix of determinant 1 and trace 2 − (ωh)², bounded while |trace| ≤ 2 (the linear stability of the leapfrog, Hairer, Lubich & Wanner, §I.3), exact',
  },
};
