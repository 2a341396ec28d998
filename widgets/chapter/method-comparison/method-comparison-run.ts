/**
 * The runs of the method comparison (method-comparison.ts), apart from the
 * worker that hosts them (method-comparison-worker.ts), so that the unit
 * tests run them in Node: for each method a timed run and a run recorded
 * step by step (energy error, portrait, Ω, Verlet's modified-Hamiltonian
 * prediction), then the order study's runs. The models come compiled (by
 * the build or on the page), so nothing here needs mathjs.
 */
import { type CompiledModel, differenceJacobian, energyDrift, fastestRate, type MethodChoice, type MethodName, type Model, modelFromCompiled, verletCorrection } from '../../../core/index.ts';
import type { ComparisonResult, MethodRun, OrderRuns } from './method-comparison-result.ts';

export interface ComparisonRequest {
  /** the model compiled for each method (the adaptive method's is RK 3/8's code) */
  models: { choice: MethodChoice; compiled: CompiledModel }[];
  /** RK 3/8's compiled model, for the reference run of the order study */
  base: CompiledModel;
  params: Record<string, number>;
  initial: number[];
  dt: number;
  steps: number;
  order?: { T: number; steps: number[]; exact?: number[] };
}

/** Vector-field evaluations per step of the fixed-step methods; the others count their own. */
const EVALUATIONS: Partial<Record<MethodName, number>> = { rk38: 4, verlet: 1, yoshida4: 3 };
/** Points of each phase portrait. */
const PORTRAIT = 3000;
/** Steps per timed chunk: long enough that the clock's resolution does not matter, short enough to report progress. */
const CHUNK = 20_000;

interface Counted {
  stats?: { evaluations?: number; iterations?: number; steps?: number };
}

/** The evaluations the model's stepper has counted so far (midpoint: one guess per step and one per Newton iteration). */
function counted(model: Model): number | undefined {
  const stats = (model.stepper as unknown as Counted).stats;
  if (!stats) return undefined;
  if (stats.evaluations !== undefined) return stats.evaluations;
  return (stats.steps ?? 0) + (stats.iterations ?? 0);
}

/** Does H depend on t? Evaluated at the start at three times. */
function autonomous(model: Model, x: Float64Array): boolean {
  const h = model.hamiltonian!;
  const h0 = h(0, x);
  return [0.7371, 3.1416, 11.83].every((t) => Math.abs(h(t, x) - h0) <= 1e-14 * Math.max(1, Math.abs(h0)));
}

export function runMethod(request: ComparisonRequest, choice: MethodChoice, compiled: CompiledModel, report: (fraction: number) => void): MethodRun {
  const { dt, steps } = request;
  const model = modelFromCompiled(compiled, request.params, undefined, choice);
  if (!model.hamiltonian) throw new Error('the model has no H to measure');
  const dim = model.dim;
  const start = Float64Array.from(request.initial);
  if (start.length !== dim) throw new Error(`the initial state has ${start.length} numbers, but the model's state has ${dim}`);

  // Timed: the whole run in long chunks, as the simulator runs it.
  const timed = Float64Array.from(start);
  const before = counted(model) ?? 0;
  let elapsed = 0;
  for (let k = 0; k < steps; k += CHUNK) {
    const n = Math.min(CHUNK, steps - k);
    const t0 = performance.now();
    const done = model.stepper.advance(timed, 1, model.params, 0, k, dt, n);
    elapsed += performance.now() - t0;
    if (done < n) break;
    report((0.5 * (k + n)) / steps);
  }
  const evaluations = EVALUATIONS[choice.name] !== undefined ? EVALUATIONS[choice.name]! * steps : (counted(model) ?? 0) - before;

  // Recorded: step by step, the relative energy error at every step and the portrait.
  const h = model.hamiltonian;
  const x = Float64Array.from(start);
  const h0 = h(0, x);
  const e = new Float64Array(steps);
  const stride = Math.max(1, Math.ceil(steps / PORTRAIT));
  const q: number[] = [x[0]];
  const p: number[] = [x[dim / 2]];
  const sampled: Float64Array[] = [Float64Array.from(x)];
  const field = model.field;
  const jacobian = differenceJacobian(field, dim);
  const symplecticBound = choice.name === 'verlet';
  const correction = symplecticBound ? verletCorrection(field, jacobian, dim) : null;
  const c0 = correction ? correction(0, x) : 0;
  let modified = 0;
  let largest = Math.abs(h0);
  let blewUp = -1;
  for (let k = 0; k < steps; k++) {
    if (model.stepper.advance(x, 1, model.params, 0, k, dt, 1) < 1) {
      blewUp = k;
      break;
    }
    const t = (k + 1) * dt;
    const hk = h(t, x);
    e[k] = (hk - h0) / Math.abs(h0);
    largest = Math.max(largest, Math.abs(hk));
    if (correction) modified = Math.max(modified, Math.abs(correction(t, x) - c0));
    if ((k + 1) % stride === 0) {
      q.push(x[0]);
      p.push(x[dim / 2]);
      if (sampled.length < 400) sampled.push(Float64Array.from(x));
    }
    if (k % CHUNK === 0) report(0.5 + (0.5 * k) / steps);
  }
  if (blewUp >= 0) throw new Error(`${choice.name} blew up at t = ${((blewUp + 1) * dt).toPrecision(4)}: take a smaller dt`);
  return {
    method: choice.name,
    drift: energyDrift(e, dt),
    rate: fastestRate(jacobian, dim, sampled),
    autonomous: autonomous(model, start),
    scale: largest / Math.abs(h0),
    h0,
    stepsPerSecond: elapsed > 0 ? (steps / elapsed) * 1000 : NaN,
    evaluationsPerSecond: elapsed > 0 ? (evaluations / elapsed) * 1000 : NaN,
    evaluationsPerStep: evaluations / steps,
    seconds: elapsed / 1000,
    modified: correction ? (dt * dt * modified) / Math.abs(h0) : undefined,
    portrait: { q, p },
  };
}

/** The distance in the max norm. */
const distance = (a: ArrayLike<number>, b: ArrayLike<number>) => {
  let d = 0;
  for (let i = 0; i < a.length; i++) d = Math.max(d, Math.abs(a[i] - b[i]));
  return d;
};

/** The end state at T of the base model run by the adaptive method at tolerance `rtol`. */
function adaptiveEnd(request: ComparisonRequest, T: number, rtol: number): Float64Array {
  const model = modelFromCompiled(request.base, request.params, undefined, { name: 'adaptive', rtol, atol: rtol * 1e-3 });
  const x = Float64Array.from(request.initial);
  if (model.stepper.advance(x, 1, model.params, 0, 0, T, 1) < 1) throw new Error('the reference run blew up');
  return x;
}

export function runOrder(request: ComparisonRequest, report: (fraction: number) => void): OrderRuns {
  const { T, exact } = request.order!;
  // Each step divides T exactly, so that every run ends at T.
  const steps = request.order!.steps.map((h) => T / Math.max(1, Math.round(T / h)));
  let truth: ArrayLike<number>;
  let reference = 0;
  let referenceName = 'the closed form';
  if (exact) {
    truth = exact;
  } else {
    // A different method, much finer: Dormand–Prince at the tightest tolerance it accepts (methods.ts,
    // LEAST_RTOL). Its error is estimated from a run at 100× the tolerance, which by tolerance
    // proportionality errs about 100× as much; a tenth of their difference is allowed, to be safe.
    truth = adaptiveEnd(request, T, 1e-14);
    reference = distance(adaptiveEnd(request, T, 1e-12), truth) / 10;
    referenceName = 'Dormand–Prince 5(4) at rtol 1e-14';
  }
  let size = 0;
  for (const v of request.initial) size = Math.max(size, Math.abs(v));
  const studies = request.models
    .filter(({ choice }) => choice.name !== 'adaptive')
    .map(({ choice, compiled }, j, all) => {
      const model = modelFromCompiled(compiled, request.params, undefined, choice);
      const errors = steps.map((h) => {
        const x = Float64Array.from(request.initial);
        const n = Math.round(T / h);
        try {
          return model.stepper.advance(x, 1, model.params, 0, 0, h, n) < n ? NaN : distance(x, truth);
        } catch {
          // The midpoint rule's Newton iteration can fail at a large step: that run has no error to show.
          return NaN;
        }
      });
      report((j + 1) / all.length);
      return { method: choice.name, errors };
    });
  return { T, steps, reference, referenceName, size, studies };
}

/** The whole comparison: every method, then the order study; `report` hears the fraction done and the stage. */
export function runComparison(request: ComparisonRequest, report: (fraction: number, stage: string) => void = () => {}): ComparisonResult {
  const runs: (MethodRun | { method: MethodName; error: string })[] = [];
  const total = request.models.length + (request.order ? 1 : 0);
  request.models.forEach(({ choice, compiled }, i) => {
    try {
      runs.push(runMethod(request, choice, compiled, (f) => report((i + f) / total, choice.name)));
    } catch (error) {
      runs.push({ method: choice.name, error: (error as Error).message });
    }
  });
  const order = request.order ? runOrder(request, (f) => report((request.models.length + f) / total, 'order study')) : undefined;
  return { dt: request.dt, steps: request.steps, runs, order };
}
