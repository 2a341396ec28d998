/**
 * A long integration that stays responsive. Node runs a signal listener only
 * when control returns to the event loop, so a run made of one synchronous
 * loop cannot be interrupted (it used to ignore Ctrl-C until it ended). Here
 * the run is cut into stretches sized by measurement to last about
 * STRETCH_MS each, and returns to the event loop once YIELD_MS have passed:
 * a signal then takes effect within a few tens of milliseconds, and the
 * integration loop itself (Simulation.run, the fused stepper) is untouched.
 * A return to the event loop costs a few microseconds, at most fifty times a
 * second: nothing measurable.
 */
import type { Simulation } from '../../core/index.ts';

/** Aimed-at duration of one synchronous call to Simulation.run. */
const STRETCH_MS = 20;
/** Returns to the event loop once this much time has passed since the last. */
const YIELD_MS = 20;
/** Steps of the first stretch: short even for a slow model, since the step time is not yet known. */
const FIRST_STRIDE = 64;

export interface PacedRunOptions {
  /** writes the rows in simulation.record and clears it; called when the record is full, at each return to the event loop and at the end */
  flush(): void;
  /** called at each return to the event loop, e.g. to draw a progress bar */
  progress?(): void;
  /** checked after each return to the event loop: once aborted, its reason is thrown */
  signal?: AbortSignal;
  /** the time in milliseconds */
  clock?: () => number;
}

const yieldToEventLoop = () => new Promise<void>((resolve) => setImmediate(resolve));

/** Steps that fill the record to its capacity, so no row is dropped before it is flushed. */
function stepsToFill(simulation: Simulation): number {
  const { record, every } = simulation;
  const free = record.capacity - record.length;
  return every - (simulation.steps % every) + (free - 1) * every;
}

/**
 * The next stretch's steps from how long `stride` steps took: aimed at
 * STRETCH_MS, and growing at most fourfold at a time, so that one stretch
 * timed too fast (a coarse clock, a warm cache) cannot make the next one long.
 */
export function nextStride(stride: number, elapsedMs: number): number {
  const aimed = elapsedMs > 0 ? Math.floor((stride * STRETCH_MS) / elapsedMs) : Infinity;
  return Math.max(1, Math.min(4 * stride, aimed));
}

/**
 * Advances `simulation` until it has taken `steps` steps, handing the rows to
 * `flush`. Throws the simulation's BlowUpError if the state stops being
 * finite, and the signal's reason if it is aborted.
 */
export async function pacedRun(simulation: Simulation, steps: number, options: PacedRunOptions): Promise<void> {
  const { flush, progress, signal, clock = () => performance.now() } = options;
  const { record } = simulation;
  let stride = FIRST_STRIDE;
  let lastYield = clock();
  signal?.throwIfAborted();
  while (simulation.steps < steps) {
    const n = Math.min(stride, steps - simulation.steps, stepsToFill(simulation));
    const start = clock();
    simulation.run(n);
    if (simulation.error) throw simulation.error;
    const now = clock();
    // A stretch cut short by the record or the end says little about the step time.
    if (n === stride) stride = nextStride(stride, now - start);
    if (record.length === record.capacity) flush();
    if (now - lastYield >= YIELD_MS) {
      flush();
      progress?.();
      await yieldToEventLoop();
      signal?.throwIfAborted();
      lastYield = clock();
    }
  }
  flush();
}
