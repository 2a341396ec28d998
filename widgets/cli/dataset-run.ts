/**
 * A `simulate` run from its spec: the model, the set of initial states, the
 * sample times and the meta, then the trajectories computed on every core
 * (or here, for a small run) and handed to a writer in its order.
 */
import { availableParallelism } from 'node:os';
import { type Axis, type InitialSet, InputError, type Range, rowColumns, stepsTo, trajectoryCount } from '../core/index.ts';
import { datasetMeta, type DatasetMeta } from './dataset-meta.ts';
import { BLOCK_VALUES, planTasks, TEXT_BLOCK_VALUES } from './dataset-plan.ts';
import { schedule } from './dataset-schedule.ts';
import { sampleTimes, type TaskSetup, type TimesSpec } from './dataset-task.ts';
import type { DatasetShape, DatasetWriter } from './formats/dataset-shape.ts';
import type { ModelRecipe } from './model.ts';
import { factsOfRecipe } from './model-facts.ts';
import { progressBar } from './progress.ts';
import { openRunModel, type RunModel } from './run-model.ts';
import { checkRunSize, datasetSize } from './run-size.ts';
import { shardRange, type RunSpec } from './run-spec.ts';

/**
 * Below this many steps in all, a run left to choose stays in one thread:
 * a worker costs about 65 ms of CPU to start (its code and the model), and
 * 5e6 steps of a one-degree-of-freedom model take about 0.2 s, so two
 * workers just begin to pay. A --workers given is obeyed whatever the size.
 */
const WORKER_THRESHOLD_STEPS = 5_000_000;

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

export interface ExecuteOptions {
  /** threads to run on; undefined: every core, once the run is large enough to repay starting them */
  workers?: number;
  signal?: AbortSignal;
  /** rows per chunk in time order (a wide table's row group) */
  timeChunkRows?: number;
  /** a progress bar on a terminal; off for reproduce's quiet run */
  progress?: boolean;
  /** kept up to date with the steps done, summed over the trajectories: where an interrupted run stopped */
  status?: { steps: number };
}

/** The default number of workers: every core. */
export function defaultWorkers(): number {
  return availableParallelism();
}

/** Computes every trajectory of the prepared run and writes them with `writer`, in its order. */
export async function executeRun(run: PreparedRun, writer: DatasetWriter, options: ExecuteOptions): Promise<void> {
  const { shape, spec } = run;
  const total = run.steps * shape.count;
  const wanted = options.workers !== undefined ? Math.max(1, options.workers) : total < WORKER_THRESHOLD_STEPS ? 1 : defaultWorkers();
  // Rows are formatted where they are computed when that is here or a worker thread; a sandbox sends numbers, formatted here.
  const text = run.model.formatsText ? writerText(writer) : undefined;
  const plan = planTasks({ ...shape, width: shape.columns.length }, writer.order, wanted, options.timeChunkRows ?? shape.samples, text ? TEXT_BLOCK_VALUES : BLOCK_VALUES);
  const workers = Math.max(1, Math.min(wanted, plan.runs));
  const ahead = 2 * workers + 2;
  const setup: TaskSetup = {
    times: run.times,
    set: run.set,
    derivatives: spec.derivatives,
    text,
    numberTrajectories: shape.total > 1,
    bufferValues: plan.maxValues,
    // The results held, the tasks queued in a worker, one on its way back.
    spareBuffers: ahead + 3,
  };
  const bar = options.progress === false ? undefined : progressBar();
  let done = 0;
  const label = () =>
    shape.count > 1
      ? `${Math.min(shape.count, Math.floor(done / Math.max(1, run.steps)))}/${shape.count} trajectories`
      : `t = ${(spec.t0 + done * spec.dt).toPrecision(6)}`;
  const advance = (steps: number) => {
    done += steps;
    if (options.status) options.status.steps = done;
    bar?.update(total > 0 ? done / total : 1, label());
  };
  const { executors, ownProgress } = await run.model.executors(workers, setup, { width: shape.columns.length, signal: options.signal, tick: advance });
  try {
    await schedule(plan, executors, {
      order: writer.order,
      ahead,
      write: (task, result) => writer.write({ first: task.first, count: task.count, rowFrom: task.rowFrom, rowTo: task.rowTo, data: result.data, text: result.text }),
      done: ownProgress ? undefined : (result) => advance(result.steps),
      signal: options.signal,
    });
  } finally {
    bar?.done();
    await Promise.all(executors.map((e) => e.close()));
  }
  writer.finish();
}

/** The text format of a writer whose rows a worker may format, if it is one. */
function writerText(writer: DatasetWriter): TaskSetup['text'] {
  const w = writer as DatasetWriter & { textFormat?: TaskSetup['text'] };
  return w.textFormat;
}
