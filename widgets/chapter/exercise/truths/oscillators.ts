/**
 * Truths for the introduction, the template's pendulum and the nonlinear
 * oscillator: harmonic and pendulum periods, a linear system's forced
 * response, RK stability, and the anharmonic well.
 */
import { pendulumPeriod, rk4StabilityLimit, wellPeriod } from '../../../../core/index.ts';
import type { Truth } from '../truth.ts';

/** The anharmonic well of the nonlinear-oscillator chapter, V = ω₀²q²/2 + αq³ + βq⁴. */
const anharmonic = ({ omega0, alpha, beta }: Readonly<Record<string, number>>) => (q: number) => (omega0 * omega0 * q * q) / 2 + alpha * q ** 3 + beta * q ** 4;

export const OSCILLATOR_TRUTHS: Readonly<Record<string, Truth>> = {
  harmonicPeriod: {
    args: ['omega'],
    compute: ({ omega }) => (2 * Math.PI) / Math.abs(omega),
    method: 'closed form T = 2π/ω (Landau & Lifshitz, Mechanics, §21), exact',
  },
  driveFrequency: {
    args: ['kappa'],
    compute: ({ kappa }) => Math.abs(kappa) / (2 * Math.PI),
    method: 'closed form κ/2π: a linear equation responds at exactly the drive’s frequency (Landau & Lifshitz §22), exact',
  },
  rk4StableStep: {
    args: ['omega'],
    compute: ({ omega }) => rk4StabilityLimit() / Math.abs(omega),
    method: 'the largest ωΔt with |R(iωΔt)| ≤ 1 for R(z) = 1 + z + z²/2 + z³/6 + z⁴/24, the stability polynomial of every four-stage fourth-order Runge–Kutta method (Hairer & Wanner II, §IV.2), found by bisection to rounding',
  },
  pendulumPeriod: {
    args: ['q0', 'omega'],
    compute: ({ q0, omega }) => pendulumPeriod(q0, 0, omega),
    method: 'closed form T = 4K(sin(q₀/2))/ω with the complete elliptic integral K (Landau & Lifshitz §11, problem 1), exact to rounding',
  },
  pendulumTopMomentum: {
    args: ['omega'],
    compute: ({ omega }) => 2 * Math.abs(omega),
    method: 'closed form: from the bottom, H = p₀²/2 − ω² reaches the top’s ω² when p₀ = 2ω (energy conservation), exact',
  },
  wellFrequency: {
    args: ['omega0', 'alpha', 'beta', 'b'],
    compute: (args) => (2 * Math.PI) / wellPeriod(anharmonic(args), args.b),
    method: 'quadrature of the period integral T = √2∮dq/√(E − V) (Landau & Lifshitz §11, eq. 11.5), independent of any simulation and of the perturbation series, to 10⁻⁸',
  },
  escapeAmplitude: {
    args: ['omega0', 'alpha', 'beta'],
    compute: ({ omega0, alpha, beta }) => {
      // The barrier on the positive side: the root q > 0 of V'(q)/q = ω₀² + 3αq + 4βq² (none when β ≥ 0 and α ≥ 0).
      const roots = [-1, 1].map((s) => (-3 * alpha + s * Math.sqrt(9 * alpha * alpha - 16 * beta * omega0 * omega0)) / (8 * beta));
      const positive = roots.filter((q) => q > 0);
      return positive.length ? Math.min(...positive) : NaN;
    },
    method: 'closed form: the barrier’s top, the positive root of V′(q) = q(ω₀² + 3αq + 4βq²) = 0, from which a particle released at rest no longer returns; exact',
  },
};
