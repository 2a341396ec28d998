/**
 * Truths for the special-relativity chapter: the speed at a given momentum,
 * and the turning point of hyperbolic motion under a constant force, read
 * forwards (where does it turn?) and backwards (which start turns there?).
 */
import type { Truth } from '../truth.ts';

export const RELATIVITY_TRUTHS: Readonly<Record<string, Truth>> = {
  relativisticSpeed: {
    args: ['p', 'm'],
    compute: ({ p, m }) => p / Math.hypot(p, m),
    method: 'closed form v = p/√(p² + m²) in units c = 1 (Landau & Lifshitz, Fields, §9), exact',
  },
  hyperbolicTurningPoint: {
    args: ['q0', 'p0', 'm', 'F'],
    // It turns where p = p₀ + Ft = 0, which it reaches only when the force opposes the start's momentum.
    compute: ({ q0, p0, m, F }) => (p0 * F < 0 ? q0 + (Math.abs(m) - Math.hypot(p0, m)) / F : NaN),
    method: 'closed form from energy conservation, √(p² + m²) − Fq constant, at p = 0: q = q₀ + (m − √(p₀² + m²))/F (Landau & Lifshitz, Fields, §20), exact',
  },
  startMomentumToTurnAt: {
    args: ['q0', 'qTurn', 'm', 'F'],
    compute: ({ q0, qTurn, m, F }) => {
      // The force pushes it back towards +F: it turns on the far side from F, at an energy m + |F|·|q₀ − q_turn| held at the start.
      const distance = (q0 - qTurn) * Math.sign(F);
      if (!(distance > 0)) return NaN;
      const energy = Math.abs(m) + Math.abs(F) * distance;
      return -Math.sign(F) * Math.sqrt(energy * energy - m * m);
    },
    method: 'closed form from energy conservation, √(p₀² + m²) = m + F(q₀ − q_turn) (Landau & Lifshitz, Fields, §20), exact',
  },
};
