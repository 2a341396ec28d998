/**
 * The crossings of a model's orbit through a plane x_i = 0 taken upward
 * (ẋ_i > 0): the section of any model, where poincare.ts serves the planar
 * systems written in closed form. The crossing is located by Hénon's trick
 * (Hénon 1982, Physica D 5, 412; see poincare.ts): once a step has carried
 * x_i through 0, one RK 3/8 step of the equations with x_i as the
 * independent variable, dS/dx_i = f(S)/f_i(S), lands on the plane, with the
 * time carried as one more dependent variable, dt/dx_i = 1/f_i, so that a
 * model whose H depends on t is served too and each crossing has its time.
 */
import { rk38 } from '../integrators/rk38.ts';
import { InputError } from '../errors.ts';
import type { Model } from '../types.ts';

export interface ModelSectionOptions {
  /** the index of the state component whose zero is the plane (0: the first coordinate) */
  index?: number;
  dt: number;
  /** stop after this many crossings */
  count: number;
  /** or after this many steps */
  maxSteps?: number;
  t0?: number;
}

export interface ModelSection {
  /** the full state at each crossing, dim numbers each */
  states: Float64Array;
  /** the time of each crossing */
  times: Float64Array;
  /** crossings found (≤ count when the steps ran out first) */
  count: number;
  /** steps taken */
  steps: number;
  /** true when a step reached a non-finite state */
  failed: boolean;
}

/** Integrates `model` from `start` with its own stepper and records the upward crossings of x_index = 0. */
export function modelSection(model: Model, start: ArrayLike<number>, options: ModelSectionOptions): ModelSection {
  const { index = 0, dt, count, maxSteps = 1e8, t0 = 0 } = options;
  const { dim, field, params } = model;
  if (!(Number.isInteger(index) && index >= 0 && index < dim)) throw new InputError(`the section's index must be a state component, 0 to ${dim - 1}, not ${index}`);
  if (!(dt > 0 && Number.isFinite(dt))) throw new InputError(`the section's step must be a positive number, not ${dt}`);
  const rate = new Float64Array(dim);
  // [x…, t] with x_index as the independent variable: the field over its rate across the plane.
  const byPlane = rk38((_, s, out) => {
    field(s[dim], s, rate);
    const across = rate[index];
    for (let i = 0; i < dim; i++) out[i] = rate[i] / across;
    out[dim] = 1 / across;
  }, dim + 1);
  const none = new Float64Array(0);
  const x = Float64Array.from(start);
  const before = new Float64Array(dim);
  const hit = new Float64Array(dim + 1);
  const states = new Float64Array(count * dim);
  const times = new Float64Array(count);
  let found = 0;
  let k = 0;
  for (; k < maxSteps && found < count; k++) {
    before.set(x);
    if (model.stepper.advance(x, 1, params, t0, k, dt, 1) < 1) return { states, times, count: found, steps: k, failed: true };
    const a = before[index];
    const b = x[index];
    if (!(a < 0 && b >= 0)) continue;
    // From the endpoint nearer the plane, where the step in x_index is shortest.
    const nearer = -a < b ? before : x;
    hit.set(nearer);
    hit[dim] = t0 + (nearer === before ? k : k + 1) * dt;
    field(hit[dim], hit, rate);
    if (!(rate[index] > 0)) continue;
    byPlane.advance(hit, 1, none, 0, 0, -hit[index], 1);
    states.set(hit.subarray(0, dim), found * dim);
    times[found] = hit[dim];
    found++;
  }
  return { states, times, count: found, steps: k, failed: false };
}
