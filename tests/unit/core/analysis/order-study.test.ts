/**
 * The order study (core/analysis/order-study.ts) against truth: the
 * harmonic oscillator's exact solution q = cos t, p = −sin t, and the
 * pendulum's exact period 4K(k)/ω (Landau & Lifshitz §11), after which the
 * exact state is the initial one. The verdicts are checked across the
 * regime: agreement with small steps, "outside validity" with steps too
 * large or errors at the rounding floor, and disagreement when the order
 * claimed is wrong.
 */
import { describe, expect, it } from 'vitest';
import { fitLine } from '../../../../core/analysis/line-fit.ts';
import { localSlopes, METHOD_ORDERS, orderCheck, type OrderStudyInput } from '../../../../core/analysis/order-study.ts';
import { completeEllipticK, pendulumPeriod } from '../../../../core/analysis/pendulum.ts';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { methodChoice, type MethodName } from '../../../../core/integrators/methods.ts';
import { judge } from '../../../../widgets/chapter/theory-check/check-verdict.ts';

describe('the pendulum in closed form', () => {
  it('K(k) by the AGM matches tabulated values (Abramowitz & Stegun 17.6 and Table 17.1)', () => {
    expect(completeEllipticK(0)).toBe(Math.PI / 2);
    // K(1/√2) = Γ(1/4)²/(4√π), the lemniscatic case.
    expect(completeEllipticK(Math.SQRT1_2)).toBeCloseTo(1.8540746773013719, 14);
    // K(sin 80°) from A&S Table 17.1: 3.1533852520.
    expect(completeEllipticK(Math.sin((80 * Math.PI) / 180))).toBeCloseTo(3.153385252, 9);
    expect(completeEllipticK(1)).toBeNaN();
  });

  it('the period tends to 2π/ω(1 + q₀²/16) for small swings (Landau & Lifshitz §11, problem 1; the next term, 11q₀⁴/3072, is below 1e-7 here) and is NaN over the top', () => {
    for (const q0 of [0.01, 0.05]) expect(pendulumPeriod(q0, 0, 2) / (Math.PI * (1 + q0 ** 2 / 16))).toBeCloseTo(1, 6);
    expect(pendulumPeriod(0, 2.5)).toBeNaN();
  });

  it('is the time after which RK 3/8 at a small step returns to its start', async () => {
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 - cos(q)' });
    const T = pendulumPeriod(2, 0);
    const n = 20000;
    const x = Float64Array.from([2, 0]);
    model.stepper.advance(x, 1, model.params, 0, 0, T / n, n);
    expect(Math.abs(x[0] - 2) + Math.abs(x[1])).toBeLessThan(1e-12);
  });
});

describe('fitLine', () => {
  it('recovers a line exactly, and its weights carry a change of one y to the slope', () => {
    const x = [0, 1, 2, 4];
    const fit = fitLine(x, x.map((v) => 3 - 2 * v));
    expect(fit.slope).toBeCloseTo(-2, 14);
    expect(fit.intercept).toBeCloseTo(3, 14);
    expect(fit.slopeError).toBeLessThan(1e-14);
    const moved = fitLine(x, x.map((v, i) => 3 - 2 * v + (i === 3 ? 0.1 : 0)));
    expect(moved.slope - fit.slope).toBeCloseTo(0.1 * fit.weights[3], 14);
  });
});

interface Problem {
  hamiltonian: string;
  initial: [number, number];
  T: number;
  exact: [number, number];
  rate: number;
}

const OSCILLATOR: Problem = { hamiltonian: 'p^2/2 + q^2/2', initial: [1, 0], T: 10, exact: [Math.cos(10), -Math.sin(10)], rate: 1 };
const PENDULUM: Problem = { hamiltonian: 'p^2/2 - cos(q)', initial: [2, 0], T: pendulumPeriod(2, 0), exact: [2, 0], rate: 1 };

async function study(problem: Problem, method: MethodName, requested: number[]): Promise<OrderStudyInput> {
  const model = await canonicalEquations({ dof: 1, hamiltonian: problem.hamiltonian, method: methodChoice(method) });
  const steps = requested.map((h) => problem.T / Math.round(problem.T / h));
  const errors = steps.map((h) => {
    const x = Float64Array.from(problem.initial);
    const n = Math.round(problem.T / h);
    model.stepper.advance(x, 1, model.params, 0, 0, h, n);
    return Math.max(Math.abs(x[0] - problem.exact[0]), Math.abs(x[1] - problem.exact[1]));
  });
  return { method, ...METHOD_ORDERS[method], T: problem.T, steps, errors, rate: problem.rate, size: 2, reference: 0, referenceName: 'the closed form' };
}

const SMALL_STEPS = [0.05, 0.025, 0.0125, 0.00625];
const METHODS: MethodName[] = ['rk38', 'verlet', 'yoshida4', 'midpoint'];

describe('the measured order agrees with the theory in the asymptotic regime', () => {
  for (const [name, problem] of [['harmonic oscillator', OSCILLATOR], ['pendulum over one exact period', PENDULUM]] as const) {
    for (const method of METHODS) {
      it(`${method} on the ${name}`, async () => {
        const input = await study(problem, method, SMALL_STEPS);
        const check = orderCheck(input);
        const verdict = judge(check);
        expect(verdict.verdict, `${check.measured} ± ${verdict.allowed}; ${verdict.reason}; errors ${input.errors}`).toBe('agrees');
        // The allowance stays a real test: well under one order.
        expect(verdict.allowed).toBeLessThan(0.3);
      });
    }
  }
});

describe('the verdict across the regime', () => {
  it('steps too large for the asymptotic regime (Ωh > 1/3) are outside validity', async () => {
    for (const method of METHODS) {
      const verdict = judge(orderCheck(await study(PENDULUM, method, [0.8, 0.4, 0.2])));
      expect(verdict.verdict).toBe('outside');
      expect(verdict.reason).toMatch(/Ω·h/);
    }
  });

  it('local slopes that have not settled are outside validity (RK 3/8 from h = 0.2 on the pendulum)', async () => {
    const input = await study(PENDULUM, 'rk38', [0.3, 0.15, 0.075]);
    const verdict = judge(orderCheck({ ...input, rate: 1 }));
    expect(verdict.verdict).toBe('outside');
    expect(localSlopes(input.steps, input.errors).length).toBe(2);
  });

  it('errors at the rounding floor are outside validity (Yoshida 4 at h ≤ 2e-3)', async () => {
    const verdict = judge(orderCheck(await study(PENDULUM, 'yoshida4', [0.002, 0.001, 0.0005])));
    expect(verdict.verdict).toBe('outside');
    expect(verdict.reason).toMatch(/rounding/);
  });

  it('a wrong order is not excused: RK 3/8 claimed as order 3, and errors that fall like h³ claimed as order 4', async () => {
    const input = await study(OSCILLATOR, 'rk38', SMALL_STEPS);
    expect(judge(orderCheck({ ...input, order: 3 })).verdict).toBe('disagrees');
    const cubic = SMALL_STEPS.map((h) => 0.1 * h ** 3);
    expect(judge(orderCheck({ ...input, steps: SMALL_STEPS, errors: cubic })).verdict).toBe('disagrees');
  });

  it('a reference run’s own error widens the allowance, and too large a one puts the study outside validity', async () => {
    const input = await study(PENDULUM, 'verlet', SMALL_STEPS);
    const exact = judge(orderCheck(input));
    const referenced = judge(orderCheck({ ...input, reference: 1e-8, referenceName: 'a reference run' }));
    expect(referenced.allowed).toBeGreaterThan(exact.allowed);
    expect(judge(orderCheck({ ...input, reference: 1e-4, referenceName: 'a poor reference' })).verdict).toBe('outside');
  });
});
