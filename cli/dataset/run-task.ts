/**
 * The unit of work of a dataset run, the same in the main thread and in a
 * worker: rows [rowFrom, rowTo) of trajectories [first, first + count) of
 * one run (a run is a batch of trajectories integrated from t0 to the last
 * sample, a chunk of rows at a time), returned as numbers or, for a text
 * format, as the formatted rows.
 */
import { BatchRun, everyKSteps, fillInitial, type InitialSet, listedTimes, type Model, type SampleTimes } from '../../core/index.ts';
import { formatRows, textCapacity, type TextFormat } from '../formats/text-rows.ts';

/** How sample times are made, as data a worker can receive. */
export type TimesSpec = { kind: 'every'; t0: number; dt: number; steps: number; every: number } | { kind: 'list'; t0: number; dt: number; times: number[] };

export function sampleTimes(spec: TimesSpec): SampleTimes {
  return spec.kind === 'every' ? everyKSteps(spec.t0, spec.dt, spec.steps, spec.every) : listedTimes(spec.t0, spec.dt, spec.times);
}

export interface TaskSetup {
  times: TimesSpec;
  set: InitialSet;
  derivatives: boolean;
  /** set when blocks go out as text, formatted where they are computed */
  text?: { format: TextFormat; numbered: boolean };
  /** whether blow-ups name the trajectory (the set has more than one) */
  numberTrajectories: boolean;
  /**
   * Numbers in the plan's largest task: every buffer is made that large, so
   * one serves any task and none is dropped for being too small (a dropped
   * buffer is memory held until the next collection).
   */
  bufferValues?: number;
  /**
   * Buffers a runner keeps for reuse: as many as can be out at once (the
   * results the scheduler holds, one being filled, one on its way back), so
   * that a burst of returns is kept rather than dropped and made again.
   */
  spareBuffers?: number;
}

export interface Task {
  id: number;
  /** the run this chunk belongs to: its first chunk starts it, its last ends it */
  run: number;
  first: number;
  count: number;
  rowFrom: number;
  rowTo: number;
  last: boolean;
}

export interface TaskResult {
  id: number;
  data?: Float64Array;
  /** the rows as CSV or JSON bytes */
  text?: Uint8Array;
  /** steps taken for this chunk, summed over its trajectories */
  steps: number;
}

/** Runs tasks against live runs, keeping each run's state from one chunk to the next. */
export class TaskRunner {
  private readonly runs = new Map<number, BatchRun>();
  private readonly times: SampleTimes;
  /** Buffers of results already written, to be filled again: a run allocates no memory per task once it is going. */
  private readonly spare: ArrayBuffer[] = [];

  constructor(
    private readonly model: Model,
    private readonly setup: TaskSetup,
  ) {
    this.times = sampleTimes(setup.times);
  }

  private batch(task: Task): BatchRun {
    let run = this.runs.get(task.run);
    if (!run) {
      const { model, setup } = this;
      const initial = new Float64Array(task.count * model.dim);
      fillInitial(setup.set, task.first, task.count, initial, { dim: model.dim, hamiltonian: model.hamiltonian, t0: setup.times.t0, names: model.names });
      run = new BatchRun(model, this.times, initial, setup.times.t0, setup.times.dt, {
        first: setup.numberTrajectories ? task.first : undefined,
        derivatives: setup.derivatives,
      });
      this.runs.set(task.run, run);
    }
    return run;
  }

  /** A buffer for the task's rows, and how wide a row is. */
  begin(task: Task): { out: Float64Array; width: number; run: BatchRun } {
    const run = this.batch(task);
    const n = task.count * (task.rowTo - task.rowFrom) * run.width;
    const i = this.spare.findIndex((b) => b.byteLength >= 8 * n);
    const buffer = i >= 0 ? this.spare.splice(i, 1)[0] : new ArrayBuffer(8 * Math.max(n, this.setup.bufferValues ?? 0));
    const out = new Float64Array(buffer, 0, n);
    return { out, width: run.width, run };
  }

  /** Takes back the buffer of a result that has been written. */
  recycle(buffer: ArrayBuffer): void {
    if (buffer.byteLength === 0) return;
    if (this.spare.length < (this.setup.spareBuffers ?? 4)) {
      this.spare.push(buffer);
      return;
    }
    // Full: keep the larger, so that small buffers (a run's short last chunk) never crowd out the ones tasks need.
    let smallest = 0;
    for (let i = 1; i < this.spare.length; i++) if (this.spare[i].byteLength < this.spare[smallest].byteLength) smallest = i;
    if (this.spare[smallest].byteLength < buffer.byteLength) this.spare[smallest] = buffer;
  }

  /** Produces `rows` more rows of the task, from row `done` of it, into `out`. */
  produce(task: Task, out: Float64Array, done: number, rows: number): number {
    const run = this.runs.get(task.run)!;
    const before = run.stepsDone;
    const span = task.rowTo - task.rowFrom;
    run.produce(rows, out, { base: done * run.width, trajectoryStride: span * run.width, rowStride: run.width });
    return run.stepsDone - before;
  }

  /** The task's result, the run forgotten after its last chunk. */
  end(task: Task, out: Float64Array, steps: number): TaskResult {
    const run = this.runs.get(task.run)!;
    if (task.last) this.runs.delete(task.run);
    const text = this.setup.text;
    if (!text) return { id: task.id, data: out, steps };
    const block = { first: task.first, count: task.count, rowFrom: task.rowFrom, rowTo: task.rowTo, data: out };
    const need = textCapacity(block, run.width);
    const i = this.spare.findIndex((b) => b.byteLength >= need);
    const into = i >= 0 ? new Uint8Array(this.spare.splice(i, 1)[0]) : undefined;
    const bytes = formatRows(text.format, block, run.width, text.numbered, into);
    // The numbers are done with: their buffer serves the next task.
    this.recycle(out.buffer as ArrayBuffer);
    return { id: task.id, text: bytes, steps };
  }

  /** The whole task at once, as a worker does it. */
  runWhole(task: Task): TaskResult {
    const { out } = this.begin(task);
    const steps = this.produce(task, out, 0, task.rowTo - task.rowFrom);
    return this.end(task, out, steps);
  }
}
