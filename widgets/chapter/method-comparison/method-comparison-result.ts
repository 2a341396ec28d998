/**
 * What the method comparison measures (method-comparison-worker.ts) and the
 * theory checks made from it with the core's error models
 * (core/analysis/order-study.ts, energy-drift.ts). Pure: no DOM, so the
 * verdicts the chapter shows are the ones the unit tests check.
 */
import { boundedCheck, type CheckInput, driftCheck, type EnergyDrift, METHOD_ORDERS, type MethodName, modifiedEnergyCheck, orderCheck } from '../../../core/index.ts';

export interface MethodRun {
  method: MethodName;
  drift: EnergyDrift;
  /** Ω, the fastest rate of the motion along this run */
  rate: number;
  autonomous: boolean;
  /** the largest |H|/|H₀| along the run */
  scale: number;
  h0: number;
  stepsPerSecond: number;
  evaluationsPerSecond: number;
  evaluationsPerStep: number;
  seconds: number;
  /** for verlet: h²·max|H₂(x_n) − H₂(x₀)|/|H₀|, the modified Hamiltonian's prediction of its energy error */
  modified?: number;
  portrait: { q: number[]; p: number[] };
}

export type MethodOutcome = MethodRun | { method: MethodName; error: string };

export interface OrderRuns {
  T: number;
  /** the steps, each adjusted to divide T */
  steps: number[];
  reference: number;
  referenceName: string;
  size: number;
  studies: { method: MethodName; errors: number[] }[];
}

export interface ComparisonResult {
  dt: number;
  steps: number;
  runs: MethodOutcome[];
  order?: OrderRuns;
}

export const failed = (run: MethodOutcome | undefined): run is { method: MethodName; error: string } => run !== undefined && 'error' in run;

/** A check that cannot be judged because the method could not run: "outside validity", saying why. */
function notRun(method: string, why: string, predicted: number): CheckInput {
  return {
    measured: NaN,
    predicted,
    errors: { measurement: { value: null, why: 'no run' } },
    validity: [{ holds: false, condition: `${method} could not run on this H: ${why}` }],
    method: `${method} did not run`,
    formula: '',
  };
}

/** The checks of a comparison's results, by method. */
export class ComparisonChecks {
  constructor(readonly result: ComparisonResult) {}

  run(method: MethodName): MethodOutcome | undefined {
    return this.result.runs.find((r) => r.method === method);
  }

  /** Ω of the motion: the largest any run found. */
  get rate(): number {
    return Math.max(0, ...this.result.runs.map((r) => (failed(r) ? 0 : r.rate)));
  }

  /** The measured order of `method` against its theoretical order. */
  order(method: MethodName): CheckInput {
    const theory = METHOD_ORDERS[method];
    if (!theory) throw new Error(`the order study covers ${Object.keys(METHOD_ORDERS).join(', ')}, not ${method}`);
    const order = this.result.order;
    const study = order?.studies.find((s) => s.method === method);
    // The order study has runs of its own: a long run that failed at its dt says nothing about them.
    const run = this.run(method);
    if (!study && failed(run)) return notRun(method, run.error, theory.order);
    if (!order || !study) throw new Error(`no order study of ${method}: give order: {T, steps} and include ${method} in methods`);
    return orderCheck({ method, ...theory, T: order.T, steps: order.steps, errors: study.errors, rate: this.rate, size: order.size, reference: order.reference, referenceName: order.referenceName });
  }

  /** The secular drift law of a method that is not symplectic: exponent 1. */
  drift(method: MethodName): CheckInput {
    const run = this.run(method);
    if (!run) throw new Error(`${method} is not among the methods compared`);
    if (failed(run)) return notRun(method, run.error, 1);
    return driftCheck(run.drift, { method, dt: this.result.dt, rate: this.rate, autonomous: run.autonomous, scale: run.scale });
  }

  /** The bound of a symplectic method: the second half's largest error over the first's, 1. */
  bounded(method: MethodName): CheckInput {
    const run = this.run(method);
    if (!run) throw new Error(`${method} is not among the methods compared`);
    if (failed(run)) return notRun(method, run.error, 1);
    const symplectic = method === 'verlet' || method === 'yoshida4' || method === 'midpoint';
    return boundedCheck(run.drift, { method, dt: this.result.dt, rate: this.rate, autonomous: run.autonomous, scale: run.scale, symplectic, separable: true });
  }

  /** Störmer–Verlet's energy error against its modified Hamiltonian's h² term. */
  modified(): CheckInput {
    const run = this.run('verlet');
    if (!run) throw new Error('verlet is not among the methods compared');
    if (failed(run)) return notRun('verlet', run.error, NaN);
    return modifiedEnergyCheck(run.drift, run.modified ?? NaN, { method: 'verlet', dt: this.result.dt, rate: this.rate, autonomous: run.autonomous, scale: run.scale, separable: true });
  }
}
