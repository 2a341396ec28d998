/**
 * What a simulator shows on paper. A page is printed in one synchronous
 * pass after `beforeprint`, with no animation frame in between, and a
 * simulator far from the view may not have run at all: so before printing,
 * each one integrates on the spot up to a fixed span of simulated time and
 * draws, and the printout shows the motion rather than an empty plot. A
 * simulator that has already run further keeps what it has.
 */

/** Simulated time a printed simulator shows at least: several periods of the book's oscillators (ω ≈ 1…10). */
export const PRINT_SPAN = 10;

/**
 * Trajectory-steps integrated for one printout at most: the span of one
 * trajectory at dt = 5e-4 is 2·10⁴, a few milliseconds; a batch of many
 * trajectories, or a tiny dt, shows less time rather than holding up the print.
 */
export const PRINT_WORK = 2_000_000;

/** What printSteps reads of a simulation. */
export interface PrintedRun {
  readonly t: number;
  readonly t0: number;
  readonly dt: number;
  readonly count: number;
}

/** Steps to integrate before printing: up to t0 + span, within `work` trajectory-steps; 0 when already there. */
export function printSteps(run: PrintedRun, span = PRINT_SPAN, work = PRINT_WORK): number {
  const owed = Math.ceil((run.t0 + span - run.t) / run.dt - 1e-9);
  if (!(owed > 0)) return 0;
  return Math.min(owed, Math.floor(work / Math.max(1, run.count)));
}
