/**
 * Truths for the restricted three-body problem: where the Lagrange points
 * lie, how fast a particle librates about L4, and Routh's critical mass
 * ratio; each from the closed forms and the quintics of core/analysis/three-body.ts.
 */
import { lagrangePoints, ROUTH_MU, triangularModes } from '../../../../core/index.ts';
import type { Truth } from '../truth.ts';

export const THREE_BODY_TRUTHS: Readonly<Record<string, Truth>> = {
  collinearPoint: {
    args: ['mu', 'point'],
    compute: ({ mu, point }) => (point === 1 || point === 2 || point === 3) && mu > 0 && mu <= 0.5 ? lagrangePoints(mu)[point - 1].x : NaN,
    method: 'the root of the collinear point’s quintic in its distance from the nearer primary (Szebehely, Theory of Orbits; Murray & Dermott ch. 3), found by bisection to rounding',
  },
  librationPeriod: {
    args: ['mu'],
    compute: ({ mu }) => {
      const modes = triangularModes(mu);
      return modes.stable ? (2 * Math.PI) / modes.libration : NaN;
    },
    method: 'closed form 2π/ω with ω² the smaller root of ω⁴ − ω² + (27/4)μ(1 − μ) = 0 (Murray & Dermott §3.8), exact',
  },
  routhMu: {
    args: [],
    compute: () => ROUTH_MU,
    method: 'closed form μ = (1 − √(23/27))/2, where the two roots of λ⁴ + λ² + (27/4)μ(1 − μ) = 0 meet (Routh 1875; Murray & Dermott §3.8), exact',
  },
};
