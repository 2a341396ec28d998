/**
 * The adiabatic chapter's truths against independent values: a plain RK4
 * integration of the ramp, a jump integrated through a very short ramp, and
 * the Floquet multipliers of the modulated oscillator.
 */
import { describe, expect, test } from 'vitest';
import { ADIABATIC_TRUTHS } from '../../../../../../widgets/chapter/exercise/truths/adiabatic.ts';
import { integrateUntil, rk4Step } from './rk4.ts';

const { adiabaticEnergy, suddenActionRatio, fastestModulation } = ADIABATIC_TRUTHS;

describe('adiabaticEnergy', () => {
  test('the paper’s ramp ω = 4 + 0.05t, integrated from (1, 0) to t = 60, ends with E = 14 to the first-order bound ε/2ω₁² (Landau & Lifshitz §49)', () => {
    const omega = (t: number) => 4 + 0.05 * t;
    const { x, t } = integrateUntil((t, [q, p]) => [p, -(omega(t) ** 2) * q], 0, [1, 0], 1e-3, (_, t) => t >= 60 - 1e-9);
    const energy = x[1] ** 2 / 2 + (omega(t) ** 2 * x[0] ** 2) / 2;
    expect(t).toBeCloseTo(60, 6);
    const truth = adiabaticEnergy.compute({ E0: 8, omega0: 4, omega1: 7 });
    expect(Math.abs(energy / truth - 1)).toBeLessThan(0.05 / (2 * 7 ** 2));
  });
});

describe('suddenActionRatio', () => {
  test('at a turning point it is ω₁/ω₀, through q = 0 it is ω₀/ω₁, and its mean over the phase is (ω₁/ω₀ + ω₀/ω₁)/2', () => {
    expect(suddenActionRatio.compute({ omega0: 4, omega1: 8, phase: 0 })).toBeCloseTo(2, 14);
    expect(suddenActionRatio.compute({ omega0: 4, omega1: 8, phase: Math.PI / 2 })).toBeCloseTo(0.5, 14);
    const phases = Array.from({ length: 12 }, (_, j) => suddenActionRatio.compute({ omega0: 4, omega1: 8, phase: (2 * Math.PI * j) / 12 }));
    expect(phases.reduce((a, b) => a + b) / 12).toBeCloseTo(1.25, 12);
  });
  test('a ramp from 4 to 8 over τ = 10⁻⁴, integrated with RK4, gives the sudden limit to order ωτ at several phases', () => {
    const [w0, w1, tau] = [4, 8, 1e-4];
    const omega = (t: number) => w0 + (w1 - w0) * Math.min(1, Math.max(0, t / tau));
    for (const phase of [0, 0.4, 1.3, 2.9]) {
      let x = [Math.cos(phase), -w0 * Math.sin(phase)];
      for (let k = 0; k < 100; k++) x = rk4Step((t, [q, p]) => [p, -(omega(t) ** 2) * q], (k * tau) / 100, x, tau / 100);
      const ratio = (x[1] ** 2 / 2 + (w1 ** 2 * x[0] ** 2) / 2) / w1 / (w0 / 2);
      expect(Math.abs(ratio - suddenActionRatio.compute({ omega0: w0, omega1: w1, phase }))).toBeLessThan(4 * w1 * tau);
    }
  });
});

describe('fastestModulation', () => {
  test('the Floquet growth rate of ω(t) = 4 + 0.5 sin γt, from RK4 over one period of the modulation, peaks within 0.05 of 2ω₀ = 8, and γ = ω₀ grows far slower (Landau & Lifshitz §27)', () => {
    const growth = (gamma: number) => {
      const period = (2 * Math.PI) / gamma, steps = 1000;
      let x = [1, 0, 0, 1];
      for (let k = 0; k < steps; k++) {
        const w2 = (t: number) => (4 + 0.5 * Math.sin(gamma * t)) ** 2;
        x = rk4Step((t, [q, p, q2, p2]) => [p, -w2(t) * q, p2, -w2(t) * q2], (k * period) / steps, x, period / steps);
      }
      const trace = Math.abs(x[0] + x[3]);
      return trace > 2 ? Math.log((trace + Math.sqrt(trace * trace - 4)) / 2) / period : 0;
    };
    let fastest = [0, 0];
    for (let gamma = 7.5; gamma <= 8.6; gamma += 0.01) fastest = growth(gamma) > fastest[1] ? [gamma, growth(gamma)] : fastest;
    expect(Math.abs(fastest[0] - fastestModulation.compute({ omega0: 4 }))).toBeLessThan(0.05);
    // γ = ω₀ is the second tongue, an order of magnitude slower.
    expect(growth(4)).toBeLessThan(fastest[1] / 5);
  });
});
