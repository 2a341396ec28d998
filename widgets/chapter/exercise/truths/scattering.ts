/**
 * Truths for the scattering chapter: Rutherford's angle, the turning point
 * of a head-on particle, and the impact parameter that turns a particle of
 * the beam through a right angle from its actual start.
 */
import { deflectionFrom, rutherfordAngle } from '../../../../core/index.ts';
import type { Truth } from '../truth.ts';

/** The energy of a particle started at (x0, 0) with momentum p0 along the axis: kinetic, plus the potential it already holds there. */
const startEnergy = ({ alpha, p0, mass, x0 }: Readonly<Record<string, number>>) => (p0 * p0) / (2 * mass) + alpha / Math.abs(x0);

export const SCATTERING_TRUTHS: Readonly<Record<string, Truth>> = {
  rutherfordDeflection: {
    args: ['alpha', 'E', 'b'],
    compute: ({ alpha, E, b }) => (E > 0 && b !== 0 ? rutherfordAngle(b, E, Math.abs(alpha)) : NaN),
    method: 'Rutherford’s formula tan(θ/2) = |α|/2Eb for a particle from infinity (Landau & Lifshitz, Mechanics, §19), exact',
  },
  headOnTurningPoint: {
    args: ['alpha', 'p0', 'mass', 'x0'],
    compute: (args) => {
      // Energy conservation along the axis: the particle stops where α/r = E, on its own side of the centre.
      const E = startEnergy(args);
      return args.alpha > 0 && E > 0 ? Math.sign(args.x0) * (args.alpha / E) : NaN;
    },
    method: 'closed form from energy conservation: the head-on particle stops where α/r equals its energy E = p₀²/2m + α/|x₀| (Landau & Lifshitz §18), exact',
  },
  rightAngleImpact: {
    args: ['alpha', 'p0', 'mass', 'x0'],
    compute: ({ alpha, p0, mass, x0 }) => {
      // The exact orbit's deflection falls from π at b → 0 to 0 as b grows: bisect for π/2.
      const deflection = (b: number) => deflectionFrom(x0, b, p0, 0, alpha, mass);
      let [low, high] = [1e-9, Math.abs(x0)];
      if (!(alpha > 0 && deflection(low) > Math.PI / 2 && deflection(high) < Math.PI / 2)) return NaN;
      for (let k = 0; k < 80; k++) {
        const mid = (low + high) / 2;
        if (deflection(mid) > Math.PI / 2) low = mid;
        else high = mid;
      }
      return (low + high) / 2;
    },
    method: 'the root of θ(b) = π/2 by bisection, θ from the exact orbit through the particle’s start, whose outgoing asymptote the Laplace–Runge–Lenz vector gives (Goldstein §3.9), to rounding',
  },
};
