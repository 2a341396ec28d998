/**
 * When a cell runs again and calls chart() again, the figure it showed last
 * time is updated in place instead of a new one being built: a cell fed by
 * a generator re-runs on every animation frame, and sixty new figures a
 * second (each with its canvas, listeners and theme watch) would churn the
 * page for nothing. Pure (no DOM), so it is unit-tested in Node.
 *
 * - {@link FigureSlots}: which earlier figure a call takes over. A cell is
 *   known by its owner (the cell machinery's signal for the running cell,
 *   which is new whenever the cell is defined again: an edit builds afresh),
 *   and a call by its place among that run's calls, so a cell that draws two
 *   charts keeps two.
 * - {@link MotionSense}: whether a figure is being animated, i.e. updated on
 *   frame after frame, so that it offers Pause (and, for a reader who asks
 *   for reduced motion, waits for Play) as the simulators do.
 */

/** Which figure each call of a cell's run takes over from the cell's previous run. */
export class FigureSlots<F extends object> {
  /** The figures of each owner's last run, by the place of the call that made them. */
  readonly #figures = new WeakMap<object, F[]>();
  /** Calls so far in the run going on now, per owner; cleared once the run's synchronous code is over. */
  readonly #calls = new Map<object, number>();
  readonly #afterRun: (clear: () => void) => void;

  /** `afterRun` schedules the end of a run: by default a microtask, since a cell calls chart() within its synchronous code. */
  constructor(afterRun: (clear: () => void) => void = (clear) => queueMicrotask(clear)) {
    this.#afterRun = afterRun;
  }

  /**
   * The figure `owner` made at this place in its previous run, if any, and
   * the function that records what this call returns. Without an owner (a
   * call outside a cell's run) there is nothing to take over.
   */
  take(owner: object | undefined): { previous: F | undefined; keep: (figure: F) => void } {
    if (!owner) return { previous: undefined, keep: () => undefined };
    const place = this.#calls.get(owner) ?? 0;
    if (this.#calls.size === 0) this.#afterRun(() => this.#endRuns());
    this.#calls.set(owner, place + 1);
    const figures = this.#figures.get(owner) ?? [];
    this.#figures.set(owner, figures);
    return { previous: figures[place], keep: (figure) => void (figures[place] = figure) };
  }

  /** A run that drew fewer charts than the one before lets go of the rest, so they can be collected. */
  #endRuns(): void {
    for (const [owner, calls] of this.#calls) {
      const figures = this.#figures.get(owner);
      if (figures && figures.length > calls) figures.length = calls;
    }
    this.#calls.clear();
  }
}

/** Updates closer together than this (ms) come from successive animation frames. */
export const FRAME_GAP_MS = 100;

/** Successive frames of updates after which a figure counts as moving and offers Pause. */
export const MOVING_FRAMES = 10;

/** How long (ms) a figure must go without an update to count as still again. */
export const STILL_AFTER_MS = 1000;

/**
 * Whether a figure is animated: updated on `frames` successive animation
 * frames. A reader's edit re-runs a cell once, a generator on every frame.
 * Fed the time of each update; a reader who asks for reduced motion gets
 * `frames` = 1, so that the first frame-on-frame update already holds the
 * picture.
 */
export class MotionSense {
  #last = -Infinity;
  #run = 0;
  constructor(readonly frames = MOVING_FRAMES) {}

  /** Notes an update at `now` (ms); true while the figure is moving. */
  update(now: number): boolean {
    this.#run = now - this.#last <= FRAME_GAP_MS ? this.#run + 1 : 0;
    this.#last = now;
    return this.moving(now);
  }

  /** True when the last `frames` updates came frame on frame and the last was recent. */
  moving(now: number): boolean {
    return this.#run >= this.frames && now - this.#last < STILL_AFTER_MS;
  }
}
