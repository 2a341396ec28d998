/**
 * The energy-drift laws (core/analysis/energy-drift.ts) and Störmer–Verlet's
 * modified Hamiltonian (core/analysis/modified-hamiltonian.ts) against
 * truth:
 *
 * - RK 3/8 on the harmonic oscillator multiplies u = ωq + ip by R(−iωh) per
 *   step, R(z) = 1 + z + z²/2 + z³/6 + z⁴/24 (every 4-stage RK of order 4),
 *   so H_n = |R(iωh)|^{2n} H₀ with |R(iy)|² = 1 − y⁶/72 + y⁸/576 exactly:
 *   an energy error linear in t (Hairer, Nørsett & Wanner I, §IV.2).
 * - Störmer–Verlet (kick–drift–kick) on the harmonic oscillator is the
 *   linear map q' = (1 − h²ω²/2)q + hp, p' = (1 − h²ω²/2)p − hω²(1 − h²ω²/4)q,
 *   which conserves Q = p² + ω²(1 − h²ω²/4)q² exactly (its matrix M has
 *   MᵀSM = S for S = diag(ω²(1 − h²ω²/4), 1), worked by hand); so from
 *   (1, 0) the relative energy error runs between 0 and (ωh)²/4, for ever.
 * - On the pendulum, backward error analysis (Hairer, Lubich & Wanner,
 *   Geometric Numerical Integration, 2nd ed., ch. IX) says H + h²H₂ varies
 *   by O(h⁴) while H varies by O(h²).
 *
 * The verdicts are checked across the regime: small and large steps, an H
 * that depends on t, errors at the rounding floor, a method that cannot run.
 */
import { describe, expect, it } from 'vitest';
import { boundedCheck, driftCheck, energyDrift, modifiedEnergyCheck } from '../../../../core/analysis/energy-drift.ts';
import { fastestRate } from '../../../../core/analysis/fastest-rate.ts';
import { verletCorrection } from '../../../../core/analysis/modified-hamiltonian.ts';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { methodChoice, type MethodName } from '../../../../core/integrators/methods.ts';
import { differenceJacobian } from '../../../../core/integrators/midpoint.ts';
import { judge } from '../../../../widgets/chapter/theory-check/check-verdict.ts';
import { ComparisonChecks } from '../../../../widgets/chapter/method-comparison/method-comparison-result.ts';

interface Run {
  e: Float64Array;
  rate: number;
  states: Float64Array[];
  modified: number;
  h0: number;
}

/** The relative energy error at every step, Ω along the run, and Verlet's h²·max|ΔH₂|/|H₀|. */
async function run(hamiltonian: string, initial: number[], method: MethodName, dt: number, steps: number): Promise<Run> {
  const model = await canonicalEquations({ dof: 1, hamiltonian, method: methodChoice(method) });
  const h = model.hamiltonian!;
  const x = Float64Array.from(initial);
  const h0 = h(0, x);
  const jacobian = differenceJacobian(model.field, 2);
  const correction = verletCorrection(model.field, jacobian, 2);
  const c0 = correction(0, x);
  const e = new Float64Array(steps);
  const states: Float64Array[] = [];
  let modified = 0;
  for (let k = 0; k < steps; k++) {
    model.stepper.advance(x, 1, model.params, 0, k, dt, 1);
    e[k] = (h((k + 1) * dt, x) - h0) / Math.abs(h0);
    modified = Math.max(modified, Math.abs(correction(0, x) - c0));
    if (k % 101 === 0) states.push(Float64Array.from(x));
  }
  return { e, rate: fastestRate(jacobian, 2, states), states, modified: (dt * dt * modified) / Math.abs(h0), h0 };
}

const OSCILLATOR = 'p^2/2 + q^2/2';
const PENDULUM = 'p^2/2 - cos(q)';
const context = (method: string, dt: number, rate: number) => ({ method, dt, rate, autonomous: true });

describe('RK 3/8 on the harmonic oscillator: the energy error is the closed form 1 − |R(iωh)|^{2n}', () => {
  it('step by step, and its drift law agrees with exponent 1', async () => {
    const dt = 0.2;
    const steps = 50_000;
    const { e } = await run(OSCILLATOR, [1, 0], 'rk38', dt, steps);
    const y = dt;
    const shrink = 1 - y ** 6 / 72 + y ** 8 / 576;
    for (const n of [1, 10, 1000, steps]) expect(e[n - 1] / (shrink ** n - 1)).toBeCloseTo(1, 6);
    const drift = energyDrift(e, dt);
    const verdict = judge(driftCheck(drift, context('rk38', dt, 1)));
    expect(verdict.verdict, verdict.reason).toBe('agrees');
    expect(Math.abs(drift.exponent - 1)).toBeLessThan(0.02);
  });
});

describe('Störmer–Verlet on the harmonic oscillator: the exact invariant and the exact bound (ωh)²/4', () => {
  it('conserves p² + ω²(1 − h²ω²/4)q² to rounding, and its largest energy error is (ωh)²/4', async () => {
    const omega = 3;
    const dt = 0.05;
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + omega^2*q^2/2', params: { omega }, method: methodChoice('verlet') });
    const x = Float64Array.from([1, 0]);
    const Q = (s: Float64Array) => s[1] ** 2 + omega ** 2 * (1 - (dt * omega) ** 2 / 4) * s[0] ** 2;
    const q0 = Q(x);
    let most = 0;
    let largest = 0;
    for (let k = 0; k < 20_000; k++) {
      model.stepper.advance(x, 1, model.params, 0, k, dt, 1);
      most = Math.max(most, Math.abs(Q(x) - q0) / q0);
      largest = Math.max(largest, Math.abs(model.hamiltonian!(0, x) - omega ** 2 / 2) / (omega ** 2 / 2));
    }
    expect(most).toBeLessThan(1e-12);
    // Sampled once a step, the peak is missed by at most (ωh)²/2 of it.
    const bound = (omega * dt) ** 2 / 4;
    expect(largest).toBeLessThanOrEqual(bound * (1 + 1e-9));
    expect(largest).toBeGreaterThan(bound * (1 - (omega * dt) ** 2 / 2));
  });

  it('its drift checks agree: bounded, and of the size its modified Hamiltonian gives', async () => {
    const dt = 0.1;
    const r = await run(OSCILLATOR, [1, 0], 'verlet', dt, 100_000);
    const drift = energyDrift(r.e, dt);
    expect(judge(boundedCheck(drift, { ...context('verlet', dt, r.rate), symplectic: true, separable: true })).verdict).toBe('agrees');
    const size = judge(modifiedEnergyCheck(drift, r.modified, { ...context('verlet', dt, r.rate), separable: true }));
    expect(size.verdict, size.reason).toBe('agrees');
    expect(r.rate).toBeCloseTo(1, 6);
  });
});

describe('the modified Hamiltonian of Störmer–Verlet on the pendulum', () => {
  it('H + h²H₂ varies by O(h⁴) (ratio 16 when h halves), H itself by O(h²) (ratio 4)', async () => {
    const variation = async (dt: number) => {
      const model = await canonicalEquations({ dof: 1, hamiltonian: PENDULUM, method: methodChoice('verlet') });
      const H2 = verletCorrection(model.field, differenceJacobian(model.field, 2), 2);
      const x = Float64Array.from([2, 0]);
      const h0 = model.hamiltonian!(0, x);
      const m0 = h0 + dt * dt * H2(0, x);
      let plain = 0;
      let modified = 0;
      for (let k = 0; k < Math.round(200 / dt); k++) {
        model.stepper.advance(x, 1, model.params, 0, k, dt, 1);
        const h = model.hamiltonian!(0, x);
        plain = Math.max(plain, Math.abs(h - h0));
        modified = Math.max(modified, Math.abs(h + dt * dt * H2(0, x) - m0));
      }
      return { plain, modified };
    };
    const a = await variation(0.1);
    const b = await variation(0.05);
    expect(Math.log2(a.plain / b.plain)).toBeCloseTo(2, 1);
    expect(Math.log2(a.modified / b.modified)).toBeCloseTo(4, 0);
    expect(a.modified).toBeLessThan(a.plain / 100);
  });
});

describe('the drift checks on the pendulum, across the regime', () => {
  it('dt = 0.1, 10⁵ steps: RK 3/8 drifts with exponent 1, Verlet stays bounded at its modified-Hamiltonian size', async () => {
    const dt = 0.1;
    const rk = await run(PENDULUM, [2, 0], 'rk38', dt, 100_000);
    const rkDrift = energyDrift(rk.e, dt);
    const d = judge(driftCheck(rkDrift, context('rk38', dt, rk.rate)));
    expect(d.verdict, d.reason).toBe('agrees');
    const verlet = await run(PENDULUM, [2, 0], 'verlet', dt, 100_000);
    const vDrift = energyDrift(verlet.e, dt);
    expect(judge(boundedCheck(vDrift, { ...context('verlet', dt, verlet.rate), symplectic: true, separable: true })).verdict).toBe('agrees');
    expect(judge(modifiedEnergyCheck(vDrift, verlet.modified, { ...context('verlet', dt, verlet.rate), separable: true })).verdict).toBe('agrees');
    // The laws tell the methods apart: RK 3/8 is not bounded, Verlet does not drift.
    expect(judge(boundedCheck(rkDrift, { ...context('rk38', dt, rk.rate), symplectic: true, separable: true })).verdict).toBe('disagrees');
    const none = judge(driftCheck(vDrift, context('verlet', dt, verlet.rate)));
    expect(none.verdict).toBe('outside');
    expect(none.reason).toMatch(/no drift shows/);
  });

  it('dt = 0.5: the bound still agrees, but the h² term no longer leads (outside validity)', async () => {
    const dt = 0.5;
    const verlet = await run(PENDULUM, [2, 0], 'verlet', dt, 20_000);
    const drift = energyDrift(verlet.e, dt);
    expect(judge(boundedCheck(drift, { ...context('verlet', dt, verlet.rate), symplectic: true, separable: true })).verdict).toBe('agrees');
    const size = judge(modifiedEnergyCheck(drift, verlet.modified, { ...context('verlet', dt, verlet.rate), separable: true }));
    expect(size.verdict).toBe('outside');
    expect(size.reason).toMatch(/Ω·h = 0\.5/);
  });

  it('dt = 0.005 over T = 100: RK 3/8’s drift does not yet show above its bounded part, outside validity', async () => {
    const dt = 0.005;
    const rk = await run(PENDULUM, [2, 0], 'rk38', dt, 20_000);
    const verdict = judge(driftCheck(energyDrift(rk.e, dt), context('rk38', dt, rk.rate)));
    expect(verdict.verdict).toBe('outside');
    expect(verdict.reason).toMatch(/no drift shows/);
  });

  it('dt = 2.5, beyond Verlet’s stability limit ωh < 2: outside validity, never an error the check cannot state', async () => {
    const dt = 2.5;
    const verlet = await run(PENDULUM, [2, 0], 'verlet', dt, 2000);
    const check = boundedCheck(energyDrift(verlet.e, dt), { ...context('verlet', dt, verlet.rate), symplectic: true, separable: true });
    for (const term of Object.values(check.errors)) expect(term.value === null || term.value >= 0 || Number.isNaN(term.value)).toBe(true);
    expect(judge(check).verdict).toBe('outside');
  });

  it('an H that depends on t is outside validity', async () => {
    const dt = 0.1;
    const rk = await run('p^2/2 - (1 + 0.1*cos(t))*cos(q)', [2, 0], 'rk38', dt, 10_000);
    expect(judge(driftCheck(energyDrift(rk.e, dt), { ...context('rk38', dt, 1), autonomous: false })).verdict).toBe('outside');
  });

  it('Verlet on an H that does not separate cannot run, and its checks say so (outside validity)', async () => {
    const hamiltonian = '(1 + 0.2*cos(q))*p^2/2 - cos(q)';
    await expect(canonicalEquations({ dof: 1, hamiltonian, method: methodChoice('verlet') })).rejects.toThrow(/T\(p\) \+ V\(q, t\)/);
    const checks = new ComparisonChecks({ dt: 0.1, steps: 1000, runs: [{ method: 'verlet', error: 'the method verlet needs H = T(p) + V(q, t)' }] });
    for (const check of [checks.bounded('verlet'), checks.modified(), checks.order('verlet')]) {
      const verdict = judge(check);
      expect(verdict.verdict).toBe('outside');
      expect(verdict.reason).toMatch(/T\(p\) \+ V\(q, t\)/);
    }
  });
});
