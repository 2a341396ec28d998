/**
 * The first stage of a `simulate` or `reproduce` run: from its spec, the
 * model, the set of initial states, the sample times and the meta, all
 * checked before any output is opened. execute.ts then computes it.
 */
import { type Axis, type InitialSet, InputError, type Range, rowColumns, stepsTo, trajectoryCount } from '../../core/index.ts';
import { datasetMeta, type DatasetMeta } from './meta.ts';
import { sampleTimes, type TimesSpec } from './run-task.ts';
import type { DatasetShape } from '../formats/dataset-shape.ts';
import type { ModelRecipe } from '../model/model.ts';
import { factsOfRecipe } from '../model/model-facts.ts';
import { openRunModel, type RunModel } from '../model/run-model.ts';
import { checkRunSize, datasetSize } from './size.ts';
import { shardRange, type RunSpec } from './spec.ts';

export interface PreparedRun {
  spec: RunSpec;
  recipe: ModelRecipe;
  /** the model, here or in its sandbox; close it when the run is over */
  model: RunModel;
  set: InitialSet;
  times: TimesSpec;
  shape: DatasetShape;
  meta: DatasetMeta;
  /** steps per trajectory */
  steps: number;
}

/** The core's set of initial states from the spec's, by the model's state names. */
export function initialSet(spec: RunSpec, names: readonly string[]): InitialSet {
  const { set } = spec;
  const dim = names.length;
  if (set.kind === 'given') {
    if (set.values.length % dim !== 0) throw new InputError(`${set.values.length} initial values do not make whole states of ${dim} (${names.join(', ')})`);
    return { kind: 'given', dim, values: set.values };
  }
  if (set.kind === 'grid') {
    const axes: Axis[] = names.map((n) => ({ lo: set.axes[n][0], hi: set.axes[n][1], n: set.axes[n][2] }));
    return { kind: 'grid', axes };
  }
  const box: Range[] = names.map((n) => ({ lo: set.box[n][0], hi: set.box[n][1] }));
  if (!set.energy) return { kind: 'sample', count: set.count, seed: set.seed, box };
  const component = names.indexOf(set.energy.solveFor);
  if (component < dim / 2) throw new InputError(`--solve-for ${set.energy.solveFor}: name a momentum (${names.slice(dim / 2).join(', ')})`);
  return { kind: 'sample', count: set.count, seed: set.seed, box, energy: { value: set.energy.value, component } };
}

export function timesOf(spec: RunSpec): { times: TimesSpec; steps: number } {
  if (spec.times) {
    const times: TimesSpec = { kind: 'list', t0: spec.t0, dt: spec.dt, times: spec.times };
    const plan = sampleTimes(times);
    const last = plan.count - 1;
    return { times, steps: plan.step(last) + (plan.extra(last) > 0 ? 1 : 0) };
  }
  const steps = stepsTo(spec.t0, spec.tEnd, spec.dt);
  if (!Number.isFinite(steps)) throw new InputError('--t-end / --dt is too many steps to count; raise --dt or lower --t-end');
  if (steps < 0) throw new InputError(`--t-end ${spec.tEnd} is before --t0 ${spec.t0}`);
  return { times: { kind: 'every', t0: spec.t0, dt: spec.dt, steps, every: spec.every }, steps: spec.every * Math.floor(steps / spec.every) };
}

/**
 * Builds everything a run needs from its spec and its model's recipe, and
 * checks it before any output: the size first (a run refused for its size
 * starts no sandbox), then the model, evaluated at a first initial state.
 * `signal` stops a sandbox's first evaluation, which the user's code may
 * never end.
 */
export async function prepareRun(spec: RunSpec, recipe: ModelRecipe, options: { force: boolean; signal?: AbortSignal }): Promise<PreparedRun> {
  const { times, steps } = timesOf(spec);
  const samples = sampleTimes(times).count;
  // What the file says of the model comes from the recipe, not from code that may run in a sandbox.
  const facts = factsOfRecipe(recipe);
  const set = initialSet(spec, facts.names);
  const total = trajectoryCount(set);
  if (spec.shard && spec.shard.index > spec.shard.of) throw new InputError(`--shard ${spec.shard.index}/${spec.shard.of}: the shard number runs from 1 to ${spec.shard.of}`);
  const { first, end } = shardRange(total, spec.shard);
  const count = end - first;
  const columns = rowColumns({ names: facts.names, hamiltonian: facts.hasHamiltonian || undefined }, spec.derivatives);
  const size = datasetSize({ steps, samples, trajectories: count, columns: columns.length + (total > 1 ? 1 : 0), format: spec.format });
  checkRunSize(size, options.force);
  const model = await openRunModel(recipe, options.signal);
  try {
    // The first state of the set, evaluated: a JS H that throws or returns a string, an energy no point reaches, are said now.
    await model.probe(set, first < end ? first : 0, spec.t0);
  } catch (error) {
    await model.close();
    throw error;
  }
  const shape: DatasetShape = { columns, names: facts.names, count, first, total, samples };
  const meta = datasetMeta({ spec, model: facts, steps, samples, columns, total, first, count });
  return { spec, recipe, model, set, times, shape, meta, steps };
}
