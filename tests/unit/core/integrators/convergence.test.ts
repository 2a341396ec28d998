/**
 * Order of convergence of every fixed-step method, measured: the global
 * error at t = 10 against a closed form for dt = 0.2, 0.1, 0.05, 0.025, and
 * the least-squares slope of log(error) against log(dt). A method of order
 * p has error C·dt^p + O(dt^(p+1)) over a fixed time (Hairer, Nørsett &
 * Wanner, Solving ODEs I, Thm II.3.6), so the slope is p up to the next
 * term's share, which at these dt is below 0.15 for every method here.
 */
import { describe, expect, it } from 'vitest';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { methodChoice, type MethodName } from '../../../../core/integrators/methods.ts';

const STEPS = [0.2, 0.1, 0.05, 0.025];
const T = 10;

/** Least-squares slope of y against x. */
function slope(x: number[], y: number[]): number {
  const n = x.length;
  const mx = x.reduce((a, b) => a + b) / n;
  const my = y.reduce((a, b) => a + b) / n;
  let sxy = 0;
  let sxx = 0;
  for (let i = 0; i < n; i++) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) ** 2;
  }
  return sxy / sxx;
}

interface Problem {
  hamiltonian: string;
  params?: Record<string, number>;
  initial: [number, number];
  /** the exact (q, p) at t */
  exact: (t: number) => [number, number];
}

// H = p²/2 + q²/2 from (1, 0): q = cos t, p = −sin t.
const OSCILLATOR: Problem = { hamiltonian: 'p^2/2 + q^2/2', initial: [1, 0], exact: (t) => [Math.cos(t), -Math.sin(t)] };

// H = p²/2 + q²/2 − F·q·cos(Ωt), a driven oscillator whose V depends on t: q̈ + q = F cos Ωt
// from (1, 0) gives q = (1 − C) cos t + C cos Ωt with C = F/(1 − Ω²) (Landau & Lifshitz, Mechanics §22).
const F = 0.5;
const OMEGA = 2;
const C = F / (1 - OMEGA ** 2);
const DRIVEN: Problem = {
  hamiltonian: 'p^2/2 + q^2/2 - F*q*cos(Omega*t)',
  params: { F, Omega: OMEGA },
  initial: [1, 0],
  exact: (t) => [(1 - C) * Math.cos(t) + C * Math.cos(OMEGA * t), -(1 - C) * Math.sin(t) - C * OMEGA * Math.sin(OMEGA * t)],
};

async function measuredOrder(problem: Problem, method: MethodName): Promise<{ order: number; errors: number[] }> {
  const model = await canonicalEquations({ dof: 1, hamiltonian: problem.hamiltonian, params: problem.params, method: methodChoice(method) });
  const errors = STEPS.map((dt) => {
    const x = Float64Array.from(problem.initial);
    const steps = Math.round(T / dt);
    expect(model.stepper.advance(x, 1, model.params, 0, 0, dt, steps)).toBe(steps);
    const [q, p] = problem.exact(steps * dt);
    return Math.max(Math.abs(x[0] - q), Math.abs(x[1] - p));
  });
  return { order: slope(STEPS.map(Math.log), errors.map(Math.log)), errors };
}

const ORDERS: [MethodName, number][] = [
  ['rk38', 4],
  ['verlet', 2],
  ['yoshida4', 4],
  ['midpoint', 2],
];

describe('order of convergence, error against dt on closed forms', () => {
  for (const [method, order] of ORDERS) {
    it(`${method} has order ${order} on the harmonic oscillator`, async () => {
      const { order: measured, errors } = await measuredOrder(OSCILLATOR, method);
      expect(Math.abs(measured - order), `measured ${measured.toFixed(3)} from errors ${errors.map((e) => e.toExponential(2)).join(', ')}`).toBeLessThan(0.15);
    });
    it(`${method} keeps order ${order} when V depends on t (driven oscillator)`, async () => {
      // A kick at the wrong time would cost the splittings their order: a t-error of O(dt) in V is an O(dt) method.
      const { order: measured } = await measuredOrder(DRIVEN, method);
      expect(Math.abs(measured - order), `measured ${measured.toFixed(3)}`).toBeLessThan(0.15);
    });
  }
});
