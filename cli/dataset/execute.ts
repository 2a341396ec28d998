/**
 * The second stage of a run: the trajectories of a prepared run (prepare.ts)
 * computed on every core, or here for a small run, as tasks (plan-tasks.ts)
 * dispatched to executors (dispatch.ts, executors.ts) and handed to a writer
 * in its order.
 */
import { availableParallelism } from 'node:os';
import { BLOCK_VALUES, planTasks, TEXT_BLOCK_VALUES } from './plan-tasks.ts';
import { schedule } from './dispatch.ts';
import type { TaskSetup } from './run-task.ts';
import type { DatasetWriter } from '../formats/dataset-shape.ts';
import { progressBar } from '../progress.ts';
import type { PreparedRun } from './prepare.ts';

/**
 * Below this many steps in all, a run left to choose stays in one thread:
 * a worker costs about 65 ms of CPU to start (its code and the model), and
 * 5e6 steps of a one-degree-of-freedom model take about 0.2 s, so two
 * workers just begin to pay. A --workers given is obeyed whatever the size.
 */
const WORKER_THRESHOLD_STEPS = 5_000_000;

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
