/**
 * Whether a running simulation keeps up with real time, judged only once it
 * has had a fair chance. The first second of a run is not its pace: the page
 * is still loading and laying out, the stepper is being compiled by the JIT,
 * a worker may be starting, and a busy machine gives the first frames
 * little time. So a run is judged over a window of frames after a warm-up,
 * and says nothing before: a slow start is not announced as a failure.
 */

/** Real time after a start (play, restart, new speed, back in view) that is not judged, ms. */
export const WARM_UP_MS = 1500;
/** The frames a verdict is taken over: those of the last WINDOW_MS, once the warm-up has passed, ms. */
export const WINDOW_MS = 2000;
/** Below this share of the steps real time asks for, a run is behind. */
export const BEHIND = 0.9;

export class PaceMeter {
  /** When the warm-up of this run ends; NaN until its first frame. */
  #warmUntil = NaN;
  /** When the first frame after the warm-up came; NaN before it. */
  #judgedFrom = NaN;
  /** The judged frames of the last window: when each came, the steps it was asked for and the steps it took. */
  readonly #at: number[] = [];
  readonly #asked: number[] = [];
  readonly #done: number[] = [];

  /** A run starts afresh at its next frame: what it did before says nothing of what it will do. */
  reset(): void {
    this.#warmUntil = NaN;
    this.#judgedFrom = NaN;
    this.#at.length = this.#asked.length = this.#done.length = 0;
  }

  /** One frame of the run at time `now` (ms): real time asked `asked` steps of it, and it took `done`. */
  frame(now: number, asked: number, done: number): void {
    if (Number.isNaN(this.#warmUntil)) this.#warmUntil = now + WARM_UP_MS;
    if (now < this.#warmUntil || !(asked >= 0) || !(done >= 0)) return;
    if (Number.isNaN(this.#judgedFrom)) this.#judgedFrom = now;
    this.#at.push(now);
    this.#asked.push(asked);
    this.#done.push(done);
    while (this.#at.length > 0 && this.#at[0] <= now - WINDOW_MS) {
      this.#at.shift();
      this.#asked.shift();
      this.#done.shift();
    }
  }

  /**
   * The share of the steps asked that the run took over the last window, at
   * most 1; null until a whole window after the warm-up has been seen (no
   * verdict yet).
   */
  get pace(): number | null {
    const last = this.#at[this.#at.length - 1];
    if (last === undefined || last - this.#judgedFrom < WINDOW_MS) return null;
    const asked = this.#asked.reduce((sum, n) => sum + n, 0);
    const done = this.#done.reduce((sum, n) => sum + n, 0);
    return asked > 0 ? Math.min(1, done / asked) : 1;
  }
}

/** Whether a pace (null: not judged yet) is behind real time. */
export function isBehind(pace: number | null): boolean {
  return pace !== null && pace < BEHIND;
}
