/**
 * The `Simulation` a cell gets: the core's, with a bound on the work it may
 * do in all (core/limits.ts). A theory check runs its own simulations
 * from the cells' parameters; with dt = 1e-9 the introduction's checks
 * would have integrated for hours, showing their old verdict meanwhile. Now
 * such a run fails within seconds, saying why, and a check that an edit has
 * made obsolete stops by the same bound.
 */
import { MAX_CELL_STEPS, Simulation } from '../../../core/index.ts';

export class CellSimulation extends Simulation {
  #taken = 0;

  override run(steps: number): number {
    const wanted = this.#taken + steps * this.count;
    if (wanted > MAX_CELL_STEPS) {
      throw new Error(
        `this Simulation has been asked for ${wanted.toExponential(1)} steps × trajectories, more than the ${MAX_CELL_STEPS.toExponential(0)} `
          + `(about a second of integration) the book lets one cell compute: take a larger dt (now ${this.dt}), a shorter time or fewer trajectories`,
      );
    }
    this.#taken = wanted;
    return super.run(steps);
  }

  /**
   * Runs `steps` steps as `run` does, in slices with a pause between them
   * in which the page draws and answers the reader: a check that integrates
   * for a second keeps the page alive, and the cell holds only its physics
   * (`await run.runAsync(steps)`). Stops early at an error (`run.error`).
   */
  async runAsync(steps: number, slice = 20_000): Promise<number> {
    const end = this.steps + steps;
    while (this.steps < end && !this.error) {
      this.run(Math.min(slice, end - this.steps));
      await new Promise((resolve) => setTimeout(resolve, 0));
    }
    return this.steps;
  }
}
