/**
 * Truths for action–angle variables: the harmonic oscillator's action E/ω,
 * and the pendulum's action and frequency released at rest from q0, from
 * the complete elliptic integrals of core/analysis/pendulum.ts.
 */
import { pendulumAction, pendulumFrequency } from '../../../../core/index.ts';
import type { Truth } from '../truth.ts';

export const ACTION_ANGLE_TRUTHS: Readonly<Record<string, Truth>> = {
  harmonicAction: {
    args: ['E', 'omega'],
    compute: ({ E, omega }) => (E >= 0 && omega > 0 ? E / omega : NaN),
    method: 'closed form J = E/ω, the area 2πE/ω of the ellipse H = E over 2π (Landau & Lifshitz §49), exact',
  },
  pendulumAction: {
    args: ['q0', 'omega'],
    compute: ({ q0, omega }) => pendulumAction(q0, 0, omega),
    method: 'closed form J = (8ω/π)[E(k) − (1 − k²)K(k)], k = sin(q₀/2) (Landau & Lifshitz §50), with K and E by the arithmetic–geometric mean to rounding',
  },
  pendulumFrequency: {
    args: ['q0', 'omega'],
    compute: ({ q0, omega }) => pendulumFrequency(q0, 0, omega),
    method: 'closed form ω = πω₀/2K(k), k = sin(q₀/2) (Landau & Lifshitz §11), with K by the arithmetic–geometric mean to rounding',
  },
};
