/**
 * What the page and the simulation worker (simulation-worker.ts) say to each
 * other, and the page's bookkeeping of the samples the worker sends ahead.
 *
 * The worker integrates a simulation of a generated model (portable-model.ts) from a state the
 * page gives it ('start'), always ahead of what the page shows: the page
 * asks it to reach a step ('advance') a fraction of a second beyond the
 * current one, and it answers in chunks, each holding the samples of a
 * stretch of steps as one transferable Float64Array and the state at its
 * end. Every 'start' carries a new generation number; a chunk of any other
 * generation (integrated before a restart, a new dt, a step taken on the
 * page) is dropped unseen, so no stale sample ever reaches the record.
 *
 * Pure: no DOM, no worker; the client (worker-integrator.ts) and the tests
 * drive it.
 */
import type { PortableModel } from './portable-model.ts';

/** Page → worker: integrate from this state, under generation `gen`, dropping all earlier work. */
export interface StartRequest {
  type: 'start';
  gen: number;
  model: PortableModel;
  params: Float64Array;
  /** the trajectories' state, count·dim values */
  state: Float64Array;
  /** steps already taken: t = t0 + steps·dt */
  steps: number;
  t0: number;
  dt: number;
  every: number;
  /** whether samples carry H per trajectory after the states (as the page's record does first among its derived series) */
  energy: boolean;
}

/** Page → worker: keep integrating until step `target`. */
export interface AdvanceRequest {
  type: 'advance';
  gen: number;
  target: number;
}

export type WorkerRequest = StartRequest | AdvanceRequest;

/** Where and how the state stopped being finite (the fields of a BlowUpError). */
export interface BlowUp {
  t: number;
  component: string;
  value: number;
  trajectory?: number;
}

/**
 * Worker → page: the steps (from, end], with a row for every sample step
 * (a multiple of `every`) in that range, in the record's layout [t, state…,
 * H…], and the state after step `end` when that is not a sample (and is
 * small: a huge batch's state would only load the page with copies, so its
 * page advances a sample at a time). With `error`, step end + 1 blew up and
 * `state` is the first non-finite state.
 */
export interface Chunk {
  type: 'chunk';
  gen: number;
  from: number;
  end: number;
  /** row-major samples, `width` values each */
  rows: Float64Array;
  width: number;
  state?: Float64Array;
  error?: BlowUp;
  /** the worker's integration time for the chunk, ms */
  ms: number;
}

/** Worker → page: it cannot integrate this model (it failed to build it): the page integrates it itself. */
export interface Failure {
  type: 'failed';
  gen: number;
  message: string;
}

/** Worker → page, once its module has loaded: from now on it can take work. */
export interface Ready {
  type: 'ready';
}

export type WorkerReply = Chunk | Failure | Ready;

/** Sample steps in (from, end]: the multiples of `every` there. */
export function samplesBetween(from: number, end: number, every: number): number {
  return Math.max(0, Math.floor(end / every) - Math.floor(from / every));
}

/** The first sample step after `from`. */
export function nextSample(from: number, every: number): number {
  return (Math.floor(from / every) + 1) * every;
}

/** A place the page can advance to: a recorded sample, or the end of a chunk. */
export interface Point {
  /** the step count after this point */
  step: number;
  /** the sample to record, at rows[offset …] of its chunk */
  row?: { data: Float64Array; offset: number };
  /** the state at `step` (a view into the chunk) */
  state: Float64Array;
  error?: BlowUp;
}

/**
 * The chunks the page has received and not yet shown, in order. `reset`
 * starts a generation at a position; `accept` takes a chunk only when it is
 * of that generation and continues exactly where the last one ended; `take`
 * hands out points in step order.
 */
export class ChunkQueue {
  gen = 0;
  /** steps shown so far: where the next point starts from */
  position = 0;
  /** the end of the last chunk accepted */
  received = 0;
  private readonly chunks: Chunk[] = [];
  /** index of the next row in chunks[0], or the row count when only its end is left */
  private row = 0;
  private stopped = false;

  constructor(private readonly every: number) {}

  reset(gen: number, position: number): void {
    this.gen = gen;
    this.position = position;
    this.received = position;
    this.chunks.length = 0;
    this.row = 0;
    this.stopped = false;
  }

  /** Steps received and not yet taken. */
  get buffered(): number {
    return this.received - this.position;
  }

  /** True once a chunk with an error was accepted: nothing follows it. */
  get ended(): boolean {
    return this.stopped;
  }

  /**
   * Keeps a chunk when it is of the current generation and starts where the
   * last one ended, its rows filling exactly its sample steps; returns
   * whether it was kept. Anything else is stale or damaged, and dropped.
   */
  accept(chunk: Chunk): boolean {
    if (chunk.gen !== this.gen || this.stopped || chunk.from !== this.received || !(chunk.end >= chunk.from)) return false;
    if (chunk.rows.length !== samplesBetween(chunk.from, chunk.end, this.every) * chunk.width) return false;
    if (chunk.end === chunk.from && !chunk.error) return true;
    this.chunks.push(chunk);
    this.received = chunk.end;
    if (chunk.error) this.stopped = true;
    return true;
  }

  /** The step count after the next point, or Infinity when there is none yet. */
  peek(): number {
    for (;;) {
      const chunk = this.chunks[0];
      if (!chunk) return Infinity;
      const rows = chunk.rows.length / chunk.width;
      if (this.row < rows) return nextSample(chunk.from, this.every) + this.row * this.every;
      // A blow-up is met on the step after `end`, as the page's own run meets it.
      if (chunk.error) return chunk.end + 1;
      if (chunk.state) return chunk.end;
      // An end without its state is no place to stop: the next chunk goes on from it.
      this.shift();
    }
  }

  /** Takes the next point (call only when peek() is finite). */
  take(stateLength: number): Point {
    this.peek();
    const chunk = this.chunks[0];
    const rows = chunk.rows.length / chunk.width;
    if (this.row < rows) {
      const step = nextSample(chunk.from, this.every) + this.row * this.every;
      const offset = this.row * chunk.width;
      this.row++;
      // The chunk's last row is its end: nothing more to take from it (unless it ends in a blow-up).
      if (this.row === rows && step === chunk.end && !chunk.error) this.shift();
      this.position = step;
      return { step, row: { data: chunk.rows, offset }, state: chunk.rows.subarray(offset + 1, offset + 1 + stateLength) };
    }
    this.shift();
    this.position = chunk.end;
    const state = chunk.state!;
    return chunk.error ? { step: chunk.end, state, error: chunk.error } : { step: chunk.end, state };
  }

  /**
   * Drops every point up to `step`, which the page reached by itself (the
   * same numbers: it runs the same code); true once a point beyond it is
   * there, and the queue then goes on from `step`.
   */
  skipTo(step: number, stateLength: number): boolean {
    while (this.peek() <= step) this.take(stateLength);
    if (this.peek() === Infinity) return false;
    this.position = step;
    return true;
  }

  private shift(): void {
    this.chunks.shift();
    this.row = 0;
  }
}

/** How far ahead of the page the worker integrates, and how much it may hold there. */
export const LOOKAHEAD_SECONDS = 0.25;
/** Bytes of samples the worker may hold ahead of the page, so a fast model does not flood it. */
export const LOOKAHEAD_BYTES = 8 * 2 ** 20;

/**
 * The step the worker should be asked to reach: LOOKAHEAD_SECONDS of real
 * time ahead of `position` at `stepsPerSecond`, but no more samples than
 * LOOKAHEAD_BYTES hold, and at least one sample.
 */
export function lookaheadTarget(position: number, stepsPerSecond: number, rowBytes: number, every: number): number {
  const byTime = Math.ceil(stepsPerSecond * LOOKAHEAD_SECONDS);
  const byBytes = Math.max(1, Math.floor(LOOKAHEAD_BYTES / Math.max(8, rowBytes))) * every;
  return position + Math.max(every, Math.min(byTime, byBytes));
}
