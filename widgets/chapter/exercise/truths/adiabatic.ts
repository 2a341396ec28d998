/**
 * Truths for the adiabatic-invariants chapter: the energy an oscillator
 * keeps in proportion to its frequency under a slow change, the action after
 * a sudden one, and the modulation that resonates with it.
 */
import type { Truth } from '../truth.ts';

export const ADIABATIC_TRUTHS: Readonly<Record<string, Truth>> = {
  adiabaticEnergy: {
    args: ['E0', 'omega0', 'omega1'],
    // I = E/ω is the invariant, so E follows ω.
    compute: ({ E0, omega0, omega1 }) => (E0 * omega1) / omega0,
    method: 'the adiabatic invariant I = E/ω kept through a slow change, E₁ = E₀ω₁/ω₀ (Landau & Lifshitz, Mechanics, §49), exact in the limit of a slow ramp; for the paper’s ramp I moves by at most ε/2ω² ≈ 0.16 %',
  },
  suddenActionRatio: {
    args: ['omega0', 'omega1', 'phase'],
    // q and p do not move during the jump: the old state is measured with the new H, at the phase φ of q = √(2I/ω)cos φ.
    compute: ({ omega0, omega1, phase }) => (omega0 / omega1) * Math.sin(phase) ** 2 + (omega1 / omega0) * Math.cos(phase) ** 2,
    method: 'closed form of the sudden limit: q and p are continuous across an instantaneous jump, so I₁/I₀ = (ω₀/ω₁)sin²φ + (ω₁/ω₀)cos²φ (Landau & Lifshitz §49–50, action–angle variables), exact',
  },
  fastestModulation: {
    args: ['omega0'],
    compute: ({ omega0 }) => 2 * Math.abs(omega0),
    method: 'the centre of the first instability tongue of a modulated frequency, γ = 2ω₀ (Landau & Lifshitz §27), exact to first order in the modulation’s depth',
  },
};
