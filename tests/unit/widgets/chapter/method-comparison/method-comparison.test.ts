/**
 * The method comparison's runs (widgets/chapter/method-comparison/method-comparison-run.ts, the
 * worker's work) on the harmonic oscillator H = p²/2 + ω²q²/2, whose
 * numerical maps are known in closed form:
 *
 * - RK 3/8 multiplies u = ωq + ip by R(−iωh), R the degree-4 Taylor
 *   polynomial of exp, so H_n = H₀·(1 − y⁶/72 + y⁸/576)^n with y = ωh;
 * - Störmer–Verlet conserves p² + ω²(1 − h²ω²/4)q² exactly, so from (1, 0)
 *   its relative energy error runs between 0 and (ωh)²/4;
 * - the exact motion is q = cos ωt, p = −ω sin ωt;
 * - Ω, the spectral radius of ∂f/∂x = [[0, 1], [−ω², 0]], is ω.
 *
 * Work counts are the methods' structure: 4, 1 and 3 field evaluations per
 * step for RK 3/8, Verlet and Yoshida; the midpoint rule's and Dormand–
 * Prince's as their steppers count them.
 */
import { describe, expect, it } from 'vitest';
import { pendulumPeriod } from '../../../../../core/analysis/pendulum.ts';
import { compiledModelFor } from '../../../../../core/model/canonical-equations.ts';
import { methodChoice, type MethodName } from '../../../../../core/integrators/methods.ts';
import { judge } from '../../../../../widgets/chapter/theory-check/check-verdict.ts';
import { ComparisonChecks, failed, type MethodRun } from '../../../../../widgets/chapter/method-comparison/method-comparison-result.ts';
import { runComparison, type ComparisonRequest } from '../../../../../widgets/chapter/method-comparison/method-comparison-run.ts';

const OMEGA = 2;
const SPEC = { dof: 1, hamiltonian: 'p^2/2 + omega^2*q^2/2', params: { omega: OMEGA } };
const METHODS: MethodName[] = ['rk38', 'verlet', 'yoshida4', 'midpoint', 'adaptive'];

async function request(dt: number, steps: number, order?: ComparisonRequest['order'], hamiltonian = SPEC.hamiltonian): Promise<ComparisonRequest> {
  const spec = { ...SPEC, hamiltonian };
  const base = await compiledModelFor(spec);
  const models = await Promise.all(
    METHODS.map(async (name) => ({
      choice: methodChoice(name),
      compiled: name === 'rk38' || name === 'adaptive' ? base : await compiledModelFor({ ...spec, method: name }),
    })),
  );
  return { models, base, params: SPEC.params, initial: [1, 0], dt, steps, order };
}

const runOf = (runs: ReturnType<typeof runComparison>['runs'], method: MethodName) => {
  const run = runs.find((r) => r.method === method)!;
  if (failed(run)) throw new Error(run.error);
  return run as MethodRun;
};

describe('runComparison on the harmonic oscillator', () => {
  it('measures the energy errors the closed forms give, Ω = ω, and the work per step', async () => {
    const dt = 0.05;
    const steps = 20_000;
    const result = runComparison(await request(dt, steps));
    const y = OMEGA * dt;
    const rk = runOf(result.runs, 'rk38');
    expect(rk.drift.atEnd / (1 - (1 - y ** 6 / 72 + y ** 8 / 576) ** steps)).toBeCloseTo(1, 6);
    const verlet = runOf(result.runs, 'verlet');
    const bound = y ** 2 / 4;
    for (const half of [verlet.drift.first, verlet.drift.second]) {
      expect(half).toBeLessThanOrEqual(bound * (1 + 1e-9));
      expect(half).toBeGreaterThan(bound * (1 - y ** 2 / 2));
    }
    // h²·max|ΔH₂| over the numerical orbit, whose p at q = 0 is ω√(1 − y²/4): with H₂ = ω²p²/12 − ω⁴q²/24
    // that is (ωh)²/4·(1 − y²/6), short of the exact bound by the h⁴ term of H̃.
    expect(1 - verlet.modified! / bound).toBeCloseTo(y ** 2 / 6, 6);
    for (const method of METHODS) {
      const run = runOf(result.runs, method);
      expect(run.rate).toBeCloseTo(OMEGA, 6);
      expect(run.autonomous).toBe(true);
      expect(run.stepsPerSecond).toBeGreaterThan(0);
      expect(run.portrait.q.length).toBeGreaterThan(1000);
    }
    expect(runOf(result.runs, 'rk38').evaluationsPerStep).toBe(4);
    expect(runOf(result.runs, 'verlet').evaluationsPerStep).toBe(1);
    expect(runOf(result.runs, 'yoshida4').evaluationsPerStep).toBe(3);
    // Newton from an explicit guess: the guess and two to four iterations.
    const midpoint = runOf(result.runs, 'midpoint').evaluationsPerStep;
    expect(midpoint).toBeGreaterThanOrEqual(3);
    expect(midpoint).toBeLessThanOrEqual(5);
    // Dormand–Prince: 6 new evaluations per accepted step (first same as last), several steps per sample at rtol 1e-9.
    expect(runOf(result.runs, 'adaptive').evaluationsPerStep).toBeGreaterThan(6);
  });

  it('its checks agree with the theory: drift for RK 3/8, bound and modified-Hamiltonian size for Verlet, the orders against the exact solution', async () => {
    const T = 5;
    const result = runComparison(await request(0.1, 100_000, { T, steps: [0.05, 0.025, 0.0125, 0.00625], exact: [Math.cos(OMEGA * T), -OMEGA * Math.sin(OMEGA * T)] }));
    const checks = new ComparisonChecks(result);
    for (const check of [checks.drift('rk38'), checks.bounded('verlet'), checks.modified(), ...(['rk38', 'verlet', 'yoshida4', 'midpoint'] as const).map((m) => checks.order(m))]) {
      const verdict = judge(check);
      expect(verdict.verdict, `${check.method}: ${verdict.reason}`).toBe('agrees');
    }
    expect(result.order!.studies.map((s) => s.method)).toEqual(['rk38', 'verlet', 'yoshida4', 'midpoint']);
  });

  it('without a closed form, the reference run of Dormand–Prince gives the errors the exact solution gives', async () => {
    const T = 5;
    const steps = [0.05, 0.025, 0.0125];
    const exact = [Math.cos(OMEGA * T), -OMEGA * Math.sin(OMEGA * T)];
    const closed = runComparison(await request(0.1, 1000, { T, steps, exact })).order!;
    const referenced = runComparison(await request(0.1, 1000, { T, steps })).order!;
    expect(referenced.referenceName).toMatch(/Dormand–Prince/);
    expect(referenced.reference).toBeLessThan(1e-12);
    closed.studies.forEach((study, i) =>
      study.errors.forEach((e, j) => expect(Math.abs(referenced.studies[i].errors[j] - e)).toBeLessThan(1e-11 + 1e-6 * e)),
    );
  });

  it('a long run that fails (the midpoint rule at a step too large for Newton) leaves the order study, whose runs are its own, to be judged', async () => {
    // The pendulum p²/2 − ω² cos q from q = 1 over one exact period, 4K(sin ½)/ω.
    const T = pendulumPeriod(1, 0, OMEGA);
    const result = runComparison(await request(1.5, 200, { T, steps: [0.05, 0.025, 0.0125, 0.00625], exact: [1, 0] }, 'p^2/2 - omega^2*cos(q)'));
    const midpoint = result.runs.find((r) => r.method === 'midpoint')!;
    expect(failed(midpoint) && midpoint.error).toMatch(/Newton/);
    expect(judge(new ComparisonChecks(result).order('midpoint')).verdict).toBe('agrees');
  });

  it('finds an H that depends on t, and reports a method that cannot run in its place', async () => {
    const driven = runComparison(await request(0.1, 2000, undefined, 'p^2/2 + omega^2*(1 + 0.1*cos(t))*q^2/2'));
    expect(runOf(driven.runs, 'rk38').autonomous).toBe(false);
    expect(judge(new ComparisonChecks(driven).drift('rk38')).verdict).toBe('outside');
    const wrong = await request(0.1, 100);
    const result = runComparison({ ...wrong, initial: [1, 0, 0] });
    for (const run of result.runs) expect(failed(run) && run.error).toMatch(/3 numbers/);
  });
});
