/**
 * How a dataset's trajectories are cut into tasks. Only speed and memory
 * depend on the cut: every trajectory's numbers are the same whichever
 * batch, chunk or thread computes them (core/dataset/batch-run.ts), and the
 * writers' output depends only on the rows, so the file is the same.
 *
 * A run is a batch of trajectories integrated from t0 to the last sample,
 * delivered in chunks of rows. In trajectory order, trajectories go in
 * batches small enough that a batch's whole series fits in BLOCK_VALUES
 * numbers, and numerous enough for every worker to have several; a
 * trajectory whose series alone is larger is a run of its own, in chunks. In
 * time order (a wide table), each worker keeps a share of the trajectories
 * for the whole run, a row group at a time.
 *
 * The plan is arithmetic, not a list: a run of 1e12 steps or a set of 1e9
 * trajectories costs no memory to plan.
 */
import type { BlockOrder } from '../formats/dataset-shape.ts';
import type { Task } from './run-task.ts';

/**
 * 128 KB of numbers per task. Each worker keeps a pool of buffers this size,
 * as many as can be out at once (the results the scheduler holds, one being
 * filled, one on its way back), so the largest tasks decide how much memory
 * a run holds beyond the process itself: at 1 MB a task, a run writing every
 * step held 20 MB more on two workers than one writing every 1000th. Even a
 * task of every step is still thousands of steps, far more than its message
 * costs (tens of microseconds).
 */
export const BLOCK_VALUES = 1 << 14;
/**
 * Numbers per task whose rows go out as text: their string (about 20 bytes a
 * number, and more while it is built) lives on the JS heap, and a few tasks
 * wait their turn at once, so a task stays near a megabyte of text.
 */
export const TEXT_BLOCK_VALUES = 1 << 16;

export interface PlanShape {
  first: number;
  count: number;
  samples: number;
  width: number;
}

export interface Plan {
  order: BlockOrder;
  runs: number;
  /** chunks per run, the same for every run */
  chunks: number;
  /** numbers in the largest task */
  maxValues: number;
  /** the task written `seq`-th */
  task(seq: number): Task;
  /** the sequence number of chunk c of run r */
  seq(run: number, chunk: number): number;
}

export function planTasks(shape: PlanShape, order: BlockOrder, workers: number, timeChunkRows: number, blockValues = BLOCK_VALUES): Plan {
  const { first, count, samples, width } = shape;
  let batch: number;
  let chunkRows: number;
  let runs: number;
  if (count === 0) {
    batch = 1;
    chunkRows = Math.max(1, samples);
    runs = 0;
  } else if (order === 'time') {
    runs = Math.min(Math.max(1, workers), count);
    batch = 0;
    chunkRows = Math.max(1, timeChunkRows);
  } else if (samples * width <= blockValues) {
    const fits = Math.max(1, Math.floor(blockValues / (samples * width)));
    batch = Math.max(1, Math.min(fits, Math.ceil(count / (8 * Math.max(1, workers)))));
    chunkRows = samples;
    runs = Math.ceil(count / batch);
  } else {
    batch = 1;
    chunkRows = Math.max(1, Math.floor(blockValues / width));
    runs = count;
  }
  const chunks = Math.max(1, Math.ceil(samples / chunkRows));
  const range = (run: number): [number, number] =>
    order === 'time'
      ? [first + Math.floor((run * count) / runs), first + Math.floor(((run + 1) * count) / runs)]
      : [first + run * batch, Math.min(first + count, first + (run + 1) * batch)];
  const seq = (run: number, chunk: number) => (order === 'time' ? chunk * runs + run : run * chunks + chunk);
  const task = (id: number): Task => {
    const run = order === 'time' ? id % runs : Math.floor(id / chunks);
    const chunk = order === 'time' ? Math.floor(id / runs) : id % chunks;
    const [a, b] = range(run);
    const rowFrom = chunk * chunkRows;
    const rowTo = Math.min(samples, rowFrom + chunkRows);
    return { id, run, first: a, count: b - a, rowFrom, rowTo, last: chunk === chunks - 1 };
  };
  const widest = runs === 0 ? 0 : order === 'time' ? Math.ceil(count / runs) : batch;
  const maxValues = widest * Math.min(chunkRows, samples) * width;
  return { order, runs, chunks, maxValues, task, seq };
}
