/**
 * What the page lets a simulator, or a cell's own Simulation, ask for. Each
 * bound is far beyond what the book's chapters use and well short of what
 * would stall the page or exhaust its memory; each refusal names the bound.
 */

/** Simulated time per real second. Beyond this the clock only skips: the integration cannot follow. */
export const MAX_SPEED = 1e5;
/** The smallest time step: smaller steps leave the simulated clock nearly still and the rounding larger than the step's error. */
export const MIN_DT = 1e-9;
/** The largest time step: beyond it a fixed-step RK 3/8 is rarely meaningful. */
export const MAX_DT = 1;
/** Degrees of freedom of one model. */
export const MAX_DOF = 200;
/** Trajectories in one simulator's batch. */
export const MAX_BATCH = 100_000;
/**
 * Steps × trajectories one Simulation in a cell may take, in all: about a
 * second of integration, ten times what the largest check in the chapters
 * uses (the scattered beam's paths, 30 particles × 3·10⁴ steps). A theory
 * check that would need more (dt = 1e-9, say) fails with this bound's
 * message instead of computing for hours, and one left running by an edit
 * ends within seconds.
 */
export const MAX_CELL_STEPS = 1e7;

/** One line naming a bound a value broke, or null when it is within. */
export function outside(name: string, value: number, min: number, max: number, unit = ''): string | null {
  if (!Number.isFinite(value)) return `${name} must be a finite number, not ${value}`;
  if (value < min) return `${name} = ${value} is below the smallest the book allows, ${min}${unit}`;
  if (value > max) return `${name} = ${value} is above the largest the book allows, ${max}${unit}`;
  return null;
}
