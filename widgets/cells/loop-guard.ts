/**
 * Stops a runaway loop in a cell before it freezes the page, as CodePen and
 * JS Bin do: every loop in a cell's code starts each iteration with a call
 * to the page's guard (cell-definition.ts puts it there), which breaks the loop once
 * the synchronous run it is part of has lasted LOOP_LIMIT_MS.
 *
 * A "run" is one uninterrupted stretch of JavaScript: it ends when control
 * returns to the browser, so a generator that loops around `yield`, or an
 * async function around `await`, starts a new one each time it resumes. The
 * guard breaks out of the loop (`break` cannot be caught, unlike a throw),
 * and every guarded loop in the same run breaks too; the cell whose code was
 * running then fails with {@link LoopStopped}, naming the cell of the loop.
 */

/** How long one uninterrupted run of cell code may loop. */
export const LOOP_LIMIT_MS = 2000;

export class LoopStopped extends Error {
  override name = 'RuntimeError';
  constructor(readonly cell: string) {
    super(`a loop in ${cell} ran for more than ${LOOP_LIMIT_MS / 1000} s without finishing and was stopped, so the page would not freeze`);
  }
}

/** The page's guard: one clock for all cells, since a run is the page's, not a cell's. */
export class LoopGuard {
  #runStart = 0;
  #inRun = false;
  /** The cell whose loop was stopped in the current run, or null. */
  #stopped: string | null = null;
  /** Stops ever, so a cell can tell whether one happened while it ran. */
  #count = 0;
  #lastStop: LoopStopped | null = null;
  /** Iterations until the next look at the clock; fast loops look rarely, slow ones every time. */
  #stride = 1;
  #untilCheck = 1;
  #lastCheck = 0;
  readonly #now: () => number;
  readonly #limitMs: number;

  constructor(now: () => number = () => performance.now(), limitMs = LOOP_LIMIT_MS) {
    this.#now = now;
    this.#limitMs = limitMs;
  }

  /** The function a cell's loops call: true means "break". */
  forCell(label: string): () => boolean {
    return () => this.#check(label);
  }

  /** Stops so far; compare before and after running a cell with {@link stoppedSince}. */
  get count(): number {
    return this.#count;
  }

  /** The error for a stop that happened after `count` was read, or null. */
  stoppedSince(count: number): LoopStopped | null {
    return this.#count !== count ? this.#lastStop : null;
  }

  #check(label: string): boolean {
    if (!this.#inRun) this.#beginRun();
    if (this.#stopped !== null) return true;
    if (--this.#untilCheck > 0) return false;
    const now = this.#now();
    // Iterations faster than a tenth of a millisecond are counted, not timed, in growing strides.
    this.#stride = now - this.#lastCheck < 0.1 ? Math.min(this.#stride * 2, 4096) : 1;
    this.#untilCheck = this.#stride;
    this.#lastCheck = now;
    if (now - this.#runStart <= this.#limitMs) return false;
    this.#stopped = label;
    this.#count++;
    this.#lastStop = new LoopStopped(label);
    return true;
  }

  #beginRun(): void {
    this.#inRun = true;
    this.#stopped = null;
    this.#runStart = this.#lastCheck = this.#now();
    this.#stride = this.#untilCheck = 1;
    // Runs once the current stretch of JavaScript has finished: the next guarded iteration is a new run.
    queueMicrotask(() => {
      this.#inRun = false;
    });
  }
}
