/**
 * Ctrl-C (SIGINT) and SIGTERM while the CLI holds something to clean up.
 *
 * Node stops at once on these signals when nobody listens, which is right
 * for a run that writes to stdout but would leave a partial file behind. So
 * a guard listens only while it is held: a signal then aborts its
 * AbortSignal, the integration notices at its next return to the event loop
 * (see paced-run.ts), the partial is removed, and the CLI exits with the
 * shell's status for that signal, 128 + its number.
 */
import { constants } from 'node:os';

const SIGNALS = ['SIGINT', 'SIGTERM'] as const;
export type StopSignal = (typeof SIGNALS)[number];

/** The run was stopped by a signal; `status` is the exit status a shell reports for it. */
export class Interrupted extends Error {
  override name = 'Interrupted';
  readonly status: number;
  constructor(
    readonly signal: StopSignal,
    detail = '',
  ) {
    super(`stopped by ${signal}${detail}`);
    this.status = 128 + constants.signals[signal];
  }
}

export class InterruptGuard {
  private readonly controller = new AbortController();
  private readonly listeners = SIGNALS.map((name) => [name, () => this.controller.abort(new Interrupted(name))] as const);
  private held = false;

  /** Aborted, with an Interrupted as its reason, when a signal arrives while the guard is held. */
  get signal(): AbortSignal {
    return this.controller.signal;
  }

  /** Starts catching the signals (instead of dying of them). */
  hold(): void {
    if (this.held) return;
    this.held = true;
    for (const [name, listener] of this.listeners) process.on(name, listener);
  }

  /** Gives the signals back their default effect. */
  release(): void {
    if (!this.held) return;
    this.held = false;
    for (const [name, listener] of this.listeners) process.off(name, listener);
  }
}
