/**
 * Cancellation and progress of a model build. A page or a worker that
 * compiles H as the reader types starts a new build on every edit; the one
 * it supersedes should stop at once rather than finish for nothing, and a
 * long one should say how far it has got.
 */

export interface BuildControl {
  /** Aborting it stops the build with an error named AbortError, at the next unit of work. */
  signal?: AbortSignal;
  /**
   * Called after each unit of work of a symbolic build: each of the 2·dof
   * derivatives, then the code generation, so `done` reaches `total`. A
   * model found compiled, or one left to finite differences, has no such
   * work and reports none.
   */
  progress?: (done: number, total: number) => void;
}

/**
 * Work done between two looks at the event loop. An abort (a message to a
 * worker, the next keystroke on a page) only arrives when the build lets the
 * event loop run, and a progress bar only repaints then. A slice this short
 * keeps a page responsive; each costs a long build one turn of the event
 * loop (a zero timeout: 1 ms in Node, up to 4 ms in a browser without
 * `scheduler.yield`). A build shorter than a slice never yields at all.
 */
const SLICE_MS = 12;

/** The error an aborted build throws: the signal's reason when that is an AbortError, else a new one. */
export function abortError(signal: AbortSignal): Error {
  const reason: unknown = signal.reason;
  if (reason instanceof Error && reason.name === 'AbortError') return reason;
  return new DOMException('the model build was cancelled', 'AbortError');
}

export function throwIfAborted(signal: AbortSignal | undefined): void {
  if (signal?.aborted) throw abortError(signal);
}

/**
 * Counts a build's units of work, reports each, and checks for an abort
 * between them. Without a signal or a progress callback it never yields to
 * the event loop, so a build nobody watches runs in one go, as before.
 */
export class BuildTracker {
  private done = 0;
  private sliceStart = performance.now();
  private readonly watched: boolean;

  constructor(
    private readonly control: BuildControl,
    readonly total: number,
  ) {
    this.watched = control.signal !== undefined || control.progress !== undefined;
    throwIfAborted(control.signal);
  }

  /** One unit done: report it, let the event loop run if the slice is used up, then stop if aborted. */
  async step(): Promise<void> {
    this.done++;
    this.control.progress?.(this.done, this.total);
    if (this.watched && performance.now() - this.sliceStart > SLICE_MS) {
      await nextTask();
      this.sliceStart = performance.now();
    }
    throwIfAborted(this.control.signal);
  }
}

/** Resolves in a later task: `scheduler.yield` where there is one, a zero timeout elsewhere (Node, Firefox, Safari). */
function nextTask(): Promise<void> {
  const scheduler = (globalThis as { scheduler?: { yield?: () => Promise<void> } }).scheduler;
  if (typeof scheduler?.yield === 'function') return scheduler.yield();
  return new Promise((resolve) => setTimeout(resolve, 0));
}
