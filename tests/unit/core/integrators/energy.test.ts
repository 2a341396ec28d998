/**
 * Long-time energy behaviour, against theory: a symplectic method applied to
 * an autonomous H conserves a modified energy H̃ = H + O(dt^p) exactly up to
 * exponentially small terms, so |H − H₀| stays bounded, with no drift, over
 * exponentially long times (backward error analysis: Hairer, Lubich &
 * Wanner, Geometric Numerical Integration, 2nd ed., Thm IX.8.1; for the
 * pendulum and Kepler, their §I.1–I.2 and Fig. I.2.3). A non-symplectic
 * method such as RK 3/8 has no such H̃: its energy error grows linearly in
 * t (HLW §IX.8, the "linear drift" of non-symplectic methods).
 *
 * Measured here: the largest |H − H₀|/|H₀| over the first and over the last
 * tenth of the run (ten samples each). Bounded means the two agree within
 * 10%; the linear law predicts RK 3/8's last tenth at 10× its first (the
 * maxima are at t = T/10 and t = T), which the test takes within 7–13×.
 */
import { describe, expect, it } from 'vitest';
import { canonicalEquations, type HamiltonianSpec } from '../../../../core/model/canonical-equations.ts';
import { methodChoice, type MethodName } from '../../../../core/integrators/methods.ts';

const PENDULUM: HamiltonianSpec = { dof: 1, hamiltonian: 'p^2/2 - cos(q)' };
/** From q = 2 rad at rest: a large swing, far from the harmonic regime. */
const PENDULUM_START = [2, 0];
const KEPLER: HamiltonianSpec = { dof: 2, hamiltonian: 'px^2/2 + py^2/2 - 1/sqrt(x^2 + y^2)', coordinates: ['x', 'y'], momenta: ['px', 'py'] };
/** Pericentre of the orbit of eccentricity 0.5 and a = 1 (GM = 1): r = a(1 − e), v = √((1 + e)/(a(1 − e))); period 2π. */
const E = 0.5;
const KEPLER_START = [1 - E, 0, 0, Math.sqrt((1 + E) / (1 - E))];

interface Drift {
  first: number;
  last: number;
}

/** The worst relative energy error over the first and the last tenth of `steps` steps. */
async function energyError(spec: HamiltonianSpec, start: number[], method: MethodName, dt: number, steps: number): Promise<Drift> {
  const model = await canonicalEquations({ ...spec, method: methodChoice(method) });
  const h = model.hamiltonian!;
  const x = Float64Array.from(start);
  const h0 = h(0, x);
  const samples = 100;
  const stride = steps / samples;
  const worst: number[] = [];
  for (let s = 0; s < samples; s++) {
    expect(model.stepper.advance(x, 1, model.params, 0, s * stride, dt, stride)).toBe(stride);
    worst.push(Math.abs(h(0, x) - h0) / Math.abs(h0));
  }
  return { first: Math.max(...worst.slice(0, 10)), last: Math.max(...worst.slice(-10)) };
}

const cases: [string, HamiltonianSpec, number[], number][] = [
  ['the pendulum', PENDULUM, PENDULUM_START, 0.1],
  ['Kepler (e = 0.5)', KEPLER, KEPLER_START, 0.01],
];

describe('energy error over long runs: bounded for the symplectic methods, drifting for RK 3/8', () => {
  for (const [name, spec, start, dt] of cases) {
    it(`RK 3/8 drifts linearly on ${name}: 1e6 steps of dt = ${dt}`, async () => {
      const { first, last } = await energyError(spec, start, 'rk38', dt, 1_000_000);
      expect(last / first).toBeGreaterThan(7);
      expect(last / first).toBeLessThan(13);
    });
    for (const method of ['verlet', 'yoshida4'] as const) {
      it(`${method} keeps the energy error bounded on ${name}: 1e6 steps of dt = ${dt}`, async () => {
        const symplectic = await energyError(spec, start, method, dt, 1_000_000);
        expect(symplectic.last / symplectic.first).toBeLessThan(1.1);
        expect(symplectic.last / symplectic.first).toBeGreaterThan(1 / 1.1);
      });
    }
    it(`midpoint keeps the energy error bounded on ${name}: 2e5 steps of dt = ${dt}`, async () => {
      const { first, last } = await energyError(spec, start, 'midpoint', dt, 200_000);
      expect(last / first).toBeLessThan(1.1);
      expect(last / first).toBeGreaterThan(1 / 1.1);
    });
  }

  it('the bounded errors have the size of the methods’ order: O(dt²) for verlet and midpoint, O(dt⁴) for yoshida4', async () => {
    // H̃ − H = O(dt^p) (HLW Thm IX.8.1): halving dt divides the bounded error by about 2^p. Here the largest
    // |H − H₀| is taken over every step of t ∈ [0, 1000], so the sampling cannot miss the error's peaks.
    const worst = async (method: MethodName, dt: number) => {
      const model = await canonicalEquations({ ...PENDULUM, method: methodChoice(method) });
      const x = Float64Array.from(PENDULUM_START);
      const h0 = model.hamiltonian!(0, x);
      let most = 0;
      const steps = Math.round(1000 / dt);
      for (let k = 0; k < steps; k++) {
        model.stepper.advance(x, 1, model.params, 0, k, dt, 1);
        most = Math.max(most, Math.abs(model.hamiltonian!(0, x) - h0));
      }
      return most;
    };
    const order = async (method: MethodName) => Math.log2((await worst(method, 0.1)) / (await worst(method, 0.05)));
    expect(Math.abs((await order('verlet')) - 2)).toBeLessThan(0.2);
    expect(Math.abs((await order('yoshida4')) - 4)).toBeLessThan(0.3);
    expect(Math.abs((await order('midpoint')) - 2)).toBeLessThan(0.2);
  });
});
