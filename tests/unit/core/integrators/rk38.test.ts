import { describe, expect, it } from 'vitest';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { Simulation } from '../../../../core/simulation.ts';
import { rk38 } from '../../../../core/integrators/rk38.ts';

/** Largest |a_i − b_i| over the samples of a record column against a function of t. */
function worstError(sim: Simulation, column: string, truth: (t: number) => number): number {
  const c = sim.record.columnIndex(column);
  let worst = 0;
  for (let i = 0; i < sim.record.length; i++) {
    worst = Math.max(worst, Math.abs(sim.record.get(i, c) - truth(sim.record.time(i))));
  }
  return worst;
}

describe('rk38 on closed-form motions', () => {
  it('simulation.run(steps) follows the harmonic oscillator q = cos t, p = −sin t on [0, 100]', async () => {
    // H = p²/2 + q²/2 from (1, 0): q = cos t, p = −sin t exactly.
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + q^2/2' });
    const sim = new Simulation(model, { initial: [1, 0], every: 100 });
    sim.run(200_000);
    expect(sim.t).toBe(100);
    expect(worstError(sim, 'q', Math.cos)).toBeLessThan(1e-11);
    expect(worstError(sim, 'p', (t) => -Math.sin(t))).toBeLessThan(1e-11);
  });

  it('simulation.run(steps) follows the relativistic particle H = √(p² + 10) − 0.8q (paper 7.4)', async () => {
    // ṗ = 0.8 gives p = p0 + 0.8t; q̇ = p/√(p² + 10) integrates to
    // q = q0 + (√(p² + 10) − √(p0² + 10))/0.8 (Landau & Lifshitz, The Classical Theory of Fields, §9).
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'sqrt(p^2 + 10) - 0.8 q' });
    const sim = new Simulation(model, { initial: [-10, -10], every: 200 });
    sim.run(100_000);
    const p = (t: number) => -10 + 0.8 * t;
    const q = (t: number) => -10 + (Math.sqrt(p(t) ** 2 + 10) - Math.sqrt(110)) / 0.8;
    // RK 3/8 is exact for linear p(t); what remains is rounding: 1e5 additions to |p| ≤ 30 bound it by n·ε·|p| ≈ 7e-10.
    expect(worstError(sim, 'p', p)).toBeLessThan(7e-10);
    expect(worstError(sim, 'q', q)).toBeLessThan(7e-10);
    // The speed approaches c = 1 and never exceeds it.
    const v = new Float64Array(2);
    model.field(sim.t, sim.state, v);
    expect(v[0]).toBeGreaterThan(0.99);
    expect(v[0]).toBeLessThan(1);
  });

  it('the fused RK 3/8 stepper of an expression model is fourth order: halving dt divides the error by about 16', async () => {
    // The harmonic oscillator to t = 10 against cos t, at steps large enough for truncation to dominate rounding.
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + q^2/2' });
    const errorAt = (dt: number) => {
      const x = new Float64Array([1, 0]);
      const steps = Math.round(10 / dt);
      model.stepper.advance(x, 1, model.params, 0, 0, dt, steps);
      return Math.hypot(x[0] - Math.cos(10), x[1] + Math.sin(10));
    };
    const errors = [0.2, 0.1, 0.05, 0.025].map(errorAt);
    for (let i = 1; i < errors.length; i++) {
      const ratio = errors[i - 1] / errors[i];
      expect(ratio).toBeGreaterThan(14);
      expect(ratio).toBeLessThan(18);
    }
  });

  it('rk38(field, dim) itself is fourth order on a field that depends on the state: the harmonic oscillator', () => {
    // The test above runs the fused stepper and the one below a field that ignores the state, so neither
    // would notice a wrong stage coefficient of rk38(). Here every stage feeds the next through the state:
    // q̇ = p, ṗ = −q from (1, 0) is q = cos t, p = −sin t (Landau & Lifshitz, Mechanics, §21). One wrong
    // coefficient breaks an order condition of order 1 or 2, and the error ratio on halving dt falls to
    // about 2 or 4. At these steps the ratio is 16 to within 0.005 (the next term of the error is
    // O(dt) relative); the tolerance of 0.5 leaves room for that and still catches any lower order.
    const oscillator = (_t: number, x: Float64Array, dxdt: Float64Array) => {
      dxdt[0] = x[1];
      dxdt[1] = -x[0];
    };
    const stepper = rk38(oscillator, 2);
    const errorAt = (dt: number) => {
      const x = new Float64Array([1, 0]);
      stepper.advance(x, 1, new Float64Array(0), 0, 0, dt, Math.round(10 / dt));
      return Math.hypot(x[0] - Math.cos(10), x[1] + Math.sin(10));
    };
    const errors = [0.2, 0.1, 0.05, 0.025].map(errorAt);
    for (let i = 1; i < errors.length; i++) expect(Math.abs(errors[i - 1] / errors[i] - 16)).toBeLessThan(0.5);
  });

  it('rk38(field, dim) is fourth order on a time-dependent quadrature (Simpson’s 3/8 rule)', async () => {
    // For q̇ = cos t the RK 3/8 rule is Simpson's 3/8 rule, error ∝ dt⁴; truth q = sin t.
    const field = (t: number, _x: Float64Array, dxdt: Float64Array) => {
      dxdt[0] = Math.cos(t);
      dxdt[1] = 0;
    };
    const stepper = rk38(field, 2);
    const errorAt = (dt: number) => {
      const x = new Float64Array(2);
      stepper.advance(x, 1, new Float64Array(0), 0, 0, dt, Math.round(3 / dt));
      return Math.abs(x[0] - Math.sin(3));
    };
    const ratio = errorAt(0.1) / errorAt(0.05);
    expect(ratio).toBeGreaterThan(14);
    expect(ratio).toBeLessThan(18);
  });

  it('the fused stepper of an explicitly time-dependent H follows the driven oscillator, in one run and in chunks', async () => {
    // H = p²/2 + q²/2 − q·cos 2t from (1, 0): q̈ + q = cos 2t, so q = (4/3)cos t − (1/3)cos 2t and
    // p = q̇ = −(4/3)sin t + (2/3)sin 2t (undetermined coefficients). cos 2t depends on time alone, so the
    // stepper computes it once per stage time and carries the fourth stage's value into the next step:
    // a carry that went wrong (across chunks, or a stale stage time) would show here at O(dt), not O(dt⁴).
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + q^2/2 - q*cos(w*t)', params: { w: 2 } });
    const q = (t: number) => (4 / 3) * Math.cos(t) - Math.cos(2 * t) / 3;
    const p = (t: number) => (-4 / 3) * Math.sin(t) + (2 / 3) * Math.sin(2 * t);
    const dt = 1e-3;
    const steps = 10_000;
    const whole = new Float64Array([1, 0]);
    model.stepper.advance(whole, 1, model.params, 0, 0, dt, steps);
    // RK 3/8's global error here is of order t·dt⁴ ≈ 1e-11; rounding over 1e4 steps is below 1e-12.
    expect(Math.abs(whole[0] - q(10))).toBeLessThan(1e-10);
    expect(Math.abs(whole[1] - p(10))).toBeLessThan(1e-10);
    const chunked = new Float64Array([1, 0]);
    for (let k = 0; k < steps; k += 333) model.stepper.advance(chunked, 1, model.params, 0, k, dt, Math.min(333, steps - k));
    expect(Array.from(chunked)).toEqual(Array.from(whole));
    // A changed parameter reaches the hoisted term: w = 0 leaves q̈ + q = 1, q = 1 from (1, 0).
    model.params[0] = 0;
    const still = new Float64Array([1, 0]);
    model.stepper.advance(still, 1, model.params, 0, 0, dt, 1000);
    expect(Math.abs(still[0] - 1)).toBeLessThan(1e-12);
  });

  it('stepper.advance(x, count, …) moves a batch exactly as it moves each trajectory alone', async () => {
    // Independent trajectories of one model must not interact: compare a batch of 3 with three single runs.
    const model = await canonicalEquations({ dof: 2, hamiltonian: 'p0^2 + p1^2 + 30/sqrt(q0^2 + q1^2)' });
    const starts = [-20, -0.3, 4, 0, -20, 0.6, 4, 0, -20, 2.1, 4, 0];
    const batch = Float64Array.from(starts);
    model.stepper.advance(batch, 3, model.params, 0, 0, 5e-4, 4000);
    for (let m = 0; m < 3; m++) {
      const one = Float64Array.from(starts.slice(4 * m, 4 * m + 4));
      model.stepper.advance(one, 1, model.params, 0, 0, 5e-4, 4000);
      expect(Array.from(batch.slice(4 * m, 4 * m + 4))).toEqual(Array.from(one));
    }
  });

  it('stepper.advance(…, k0, …) computes t = t0 + k·dt, so chunked runs equal one long run', async () => {
    // A time-dependent H (the paper's eq. 7) makes any error in t visible in the state.
    const model = await canonicalEquations({
      dof: 1,
      hamiltonian: 'p^2/2 + omega^2*(1 + u*cos(gamma*t))*q^2/2 - f*q*cos(kappa*t + beta)',
      params: { u: 0.3, gamma: 21.7, beta: 0.2, kappa: 8, omega: 10, f: 20 },
    });
    const whole = new Float64Array([2, 0]);
    model.stepper.advance(whole, 1, model.params, 0, 0, 5e-4, 10_000);
    const chunked = new Float64Array([2, 0]);
    for (let k = 0; k < 10_000; k += 997) {
      model.stepper.advance(chunked, 1, model.params, 0, k, 5e-4, Math.min(997, 10_000 - k));
    }
    expect(Array.from(chunked)).toEqual(Array.from(whole));
  });
});
