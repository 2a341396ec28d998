/**
 * Stops a runaway loop in a cell before it freezes the page, as CodePen and
 * JS Bin do: every loop in a cell's code starts each iteration with a call
 * to the page's guard (cell-definition.ts puts it there), which breaks the
 * loop once its cell has kept the page busy for LOOP_LIMIT_MS in one task.
 *
 * The page is frozen for as long as one task (a macrotask, with all the
 * microtasks that follow it) runs, so that is what the guard measures: an
 * `await` inside a loop resumes in a microtask of the same task, and
 * `while (true) { await 0 }` never lets the browser draw or take a click.
 * A task ends only when the browser gets control back, which the guard
 * learns from a message it posts to itself when a task first runs a guarded
 * loop: a generator that yields a frame, or an `await` of a timer, a fetch
 * or an animation frame, starts afresh in a new task.
 *
 * Time is charged cell by cell, so that one cell's long but finite loop
 * does not count against the next cell the runtime computes in the same
 * task: a cell is charged the time between its loop's checks, and the time
 * since another cell's check when its loop resumes after it (two endless
 * async loops taking turns are both charged); the stretch before a cell's
 * first check in a task is the page's, not the cell's.
 *
 * The guard breaks out of the loop (`break` cannot be caught, unlike a
 * throw). Every guarded loop in the same stretch of JavaScript breaks too,
 * and a cell that ran out of time has every later loop broken until the
 * task ends; the cell whose code was running then fails with
 * {@link LoopStopped}, naming the cell of the loop. The guard is a net for
 * mistakes, not a wall against hostile code, which can simply turn it off.
 */

/** How long one cell's loops may keep the page busy in one task. */
export const LOOP_LIMIT_MS = 2000;

export class LoopStopped extends Error {
  override name = 'RuntimeError';
  /** `cell` is the id of the cell whose loop it was; `label` names it for the reader ("cell H0"). */
  constructor(readonly cell: string, readonly label: string = cell) {
    super(`a loop in ${label} ran for more than ${LOOP_LIMIT_MS / 1000} s without finishing and was stopped, so the page would not freeze`);
  }
}

/** Calls `end` once the current task is over: from a later task, never from a microtask of this one. */
export type AfterTask = (end: () => void) => void;

/**
 * A message to ourselves: it is delivered in a task of its own, after the
 * current one, unthrottled (unlike a zero timeout in a background tab).
 */
export function afterTaskByMessage(): AfterTask {
  let channel: MessageChannel | null = null;
  return (end) => {
    if (!channel) {
      channel = new MessageChannel();
      // Node (the build runs cells headless) would otherwise stay alive for the open port.
      (channel.port1 as { unref?: () => void }).unref?.();
    }
    // One guard asks for one end at a time.
    channel.port1.onmessage = end;
    channel.port2.postMessage(null);
  };
}

/** The page's guard: one clock for all cells, since a task is the page's, each cell charged its share. */
export class LoopGuard {
  /** A task has run a guarded loop and its end has not been seen yet. */
  #inTask = false;
  /** Milliseconds each cell has been charged in this task; a cell is a key once it has checked in it. */
  readonly #charged = new Map<string, number>();
  /** Cells that ran out of time in this task: their loops break at once until it ends. */
  readonly #spent = new Set<string>();
  /** Set by a stop: every guarded loop breaks until the current stretch of JavaScript ends. */
  #breakAll = false;
  /** The cell of the last check, and when the clock was last read. */
  #current: string | null = null;
  /**
   * The cell whose checks may take the fast path (count down, nothing else):
   * the current cell while a task is on and nothing is being broken; null
   * whenever the next check must look closer. A loop checks every iteration,
   * so this path is all most iterations pay.
   */
  #fast: string | null = null;
  #lastCheck = 0;
  /** Iterations until the next look at the clock; fast loops look rarely, slow ones every time. */
  #stride = 1;
  #untilCheck = 1;
  /** Breaks ever, so a cell can tell whether one happened while it ran. */
  #count = 0;
  #lastStop: LoopStopped | null = null;
  #listener: ((stop: LoopStopped) => void) | null = null;
  readonly #now: () => number;
  readonly #limitMs: number;
  readonly #afterTask: AfterTask;

  constructor(now: () => number = () => performance.now(), limitMs = LOOP_LIMIT_MS, afterTask: AfterTask = afterTaskByMessage()) {
    this.#now = now;
    this.#limitMs = limitMs;
    this.#afterTask = afterTask;
  }

  /** The function a cell's loops call: true means "break". `cell` is its id, `label` its name for the reader. */
  forCell(cell: string, label: string = cell): () => boolean {
    return () => this.#check(cell, label);
  }

  /** Breaks so far; compare before and after running a cell with {@link stoppedSince}. */
  get count(): number {
    return this.#count;
  }

  /** The error for a break that happened after `count` was read, or null. */
  stoppedSince(count: number): LoopStopped | null {
    return this.#count !== count ? this.#lastStop : null;
  }

  /**
   * Hears of each cell that runs out of time, once per task, a moment after
   * (from a microtask, not from inside the loop being broken).
   */
  onStop(listener: (stop: LoopStopped) => void): void {
    this.#listener = listener;
  }

  #check(cell: string, label: string): boolean {
    if (cell === this.#fast && --this.#untilCheck > 0) return false;
    return this.#look(cell, label);
  }

  /** A check that reads the clock, or finds the task new, the cell switched, or loops being broken. */
  #look(cell: string, label: string): boolean {
    if (!this.#inTask) this.#beginTask();
    if (this.#breakAll || (this.#spent.size > 0 && this.#spent.has(cell))) return this.#broke(cell, label, false);
    if (cell === this.#current && --this.#untilCheck > 0) {
      this.#fast = cell;
      return false;
    }
    const now = this.#now();
    const since = now - this.#lastCheck;
    const charged = this.#charged.get(cell);
    if (cell === this.#current) {
      // Iterations faster than a tenth of a millisecond are counted, not timed, in growing strides.
      this.#stride = since < 0.1 ? Math.min(this.#stride * 2, 4096) : 1;
    } else {
      this.#current = cell;
      this.#stride = 1;
    }
    this.#untilCheck = this.#stride;
    this.#lastCheck = now;
    // A cell's first check in a task is charged nothing: what ran before it was not its loop.
    const total = charged === undefined ? 0 : charged + since;
    this.#charged.set(cell, total);
    if (total > this.#limitMs) return this.#broke(cell, label, true);
    this.#fast = cell;
    return false;
  }

  /** Breaks a loop of `cell`; a cell that has just run out of time is announced. */
  #broke(cell: string, label: string, ranOut: boolean): true {
    this.#count++;
    if (!ranOut && this.#lastStop) return true;
    const stop = new LoopStopped(cell, label);
    this.#lastStop = stop;
    if (ranOut) {
      this.#spent.add(cell);
      this.#breakAll = true;
      this.#fast = null;
      queueMicrotask(() => {
        this.#breakAll = false;
        this.#listener?.(stop);
      });
    }
    return true;
  }

  #beginTask(): void {
    this.#inTask = true;
    this.#afterTask(() => {
      this.#inTask = false;
      this.#charged.clear();
      this.#spent.clear();
      this.#current = null;
      this.#fast = null;
    });
  }
}
