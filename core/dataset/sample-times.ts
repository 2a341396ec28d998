import { InputError } from '../errors.ts';

/**
 * When a run writes its samples. The integration always takes whole steps
 * of dt from t0, step k starting at t0 + k·dt; a sample is the state after
 * `step(i)` steps, advanced by one more RK 3/8 step of the remainder
 * `extra(i)` when the time asked for lies between two steps (a step of a
 * copy: the run itself stays on its grid). Sampled times are thus exact,
 * and a time on the grid costs nothing extra.
 */
export interface SampleTimes {
  readonly kind: 'every' | 'list';
  /** number of samples */
  readonly count: number;
  /** whole steps to the i-th sample */
  step(i: number): number;
  /** the remainder t_i − (t0 + step(i)·dt), ≥ 0 */
  extra(i: number): number;
  /** the time of the i-th sample, as written */
  time(i: number): number;
}

/** Steps to t-end: t-end is reached by whole steps; a hair of tolerance keeps 10/5e-4 from losing its last step. */
export function stepsTo(t0: number, tEnd: number, dt: number): number {
  return Math.floor((tEnd - t0) / dt + 1e-9);
}

/** A sample every `every` steps from t0 up to `steps` steps. */
export function everyKSteps(t0: number, dt: number, steps: number, every: number): SampleTimes {
  const count = Math.floor(steps / every) + 1;
  return {
    kind: 'every',
    count,
    step: (i) => i * every,
    extra: () => 0,
    time: (i) => t0 + i * every * dt,
  };
}

/** Samples at the given times, which must increase and not precede t0. */
export function listedTimes(t0: number, dt: number, times: readonly number[]): SampleTimes {
  if (times.length === 0) throw new InputError('the list of output times is empty');
  const steps: number[] = [];
  const extras: number[] = [];
  times.forEach((t, i) => {
    if (!Number.isFinite(t)) throw new InputError(`output time ${i + 1} is ${t}, not a finite number`);
    if (t < t0) throw new InputError(`output time ${t} is before t0 = ${t0}`);
    if (i > 0 && !(t > times[i - 1])) throw new InputError(`output times must increase, but ${t} follows ${times[i - 1]}`);
    // The last grid time at or before t, however (t − t0)/dt rounds.
    let k = Math.floor((t - t0) / dt);
    while (t0 + (k + 1) * dt <= t) k++;
    while (k > 0 && t0 + k * dt > t) k--;
    steps.push(k);
    extras.push(t - (t0 + k * dt));
  });
  return {
    kind: 'list',
    count: times.length,
    step: (i) => steps[i],
    extra: (i) => extras[i],
    time: (i) => times[i],
  };
}
