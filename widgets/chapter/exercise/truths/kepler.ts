/**
 * Truths for the Kepler chapter, from the two stars' state as the chapter
 * writes it, (x1, y1, x2, y2, px1, py1, px2, py2), each of mass 1/2, and the
 * strength k of the attraction: the period by Kepler's third law, the length
 * of the Laplace–Runge–Lenz vector, and the strength below which the stars
 * part for good. All closed forms of the reduced one-body problem (Landau &
 * Lifshitz, Mechanics, §§13–15), independent of any simulation.
 */
import { keplerOrbit } from '../../../../core/index.ts';
import type { Truth } from '../truth.ts';

const STATE = ['x1', 'y1', 'x2', 'y2', 'px1', 'py1', 'px2', 'py2'] as const;
const state = (args: Readonly<Record<string, number>>) => STATE.map((name) => args[name]);

export const KEPLER_TRUTHS: Readonly<Record<string, Truth>> = {
  keplerPeriod: {
    args: [...STATE, 'k'],
    compute: (args) => keplerOrbit(state(args), args.k).period,
    method: 'Kepler’s third law T = 2π√(μa³/k) with a = −k/2E, μ = 1/4 (Landau & Lifshitz §15), exact for two bodies; NaN when E ≥ 0',
  },
  lenzLength: {
    args: [...STATE, 'k'],
    compute: (args) => Math.hypot(...keplerOrbit(state(args), args.k).lenz),
    method: 'the Laplace–Runge–Lenz vector A = p × L − μk r/r at the start, from its definition (Goldstein §3.9), exact',
  },
  unboundStrength: {
    args: [...STATE],
    // With k = 0 the relative motion's energy is its kinetic energy p²/2μ; E = p²/2μ − k/r reaches 0 at k = r·p²/2μ.
    compute: (args) => {
      const [x1, y1, x2, y2] = state(args);
      return Math.hypot(x1 - x2, y1 - y2) * keplerOrbit(state(args), 0).energy;
    },
    method: 'the closed form k = r·p²/2μ at which the energy E = p²/2μ − k/r of the relative motion is zero, the boundary between ellipses and hyperbolas (Landau & Lifshitz §15), exact',
  },
};
