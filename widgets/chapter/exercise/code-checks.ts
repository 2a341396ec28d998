/**
 * The hidden checks of a write-code exercise: properties of the model the
 * reader's H defines, compared with a reference H, never with a stored copy
 * of the reference's output. Each check gives a verdict with a sentence.
 *
 * - `equations`: Hamilton's equations of the reader's H equal the
 *   reference's at random states drawn in a box (so H may differ by a
 *   constant, or be written any way at all);
 * - `returns`: released from a state, the reader's system comes back to it
 *   after the period the physics demands (the motion, not its formula);
 * - `equationsInTime`: as `equations`, at random times in a range as well,
 *   for an H that depends on t (a ramp, a modulation), which the equations
 *   at t = 0 alone cannot tell from its frozen value.
 */
import type { Model } from '../../../core/index.ts';
import type { CodeCheck } from './exercise-spec.ts';
import type { Verdict } from './grade.ts';

/** A seeded generator (mulberry32), so a page checks the same states each time and a failure can be reproduced. */
function uniform(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const short = (x: number) => Number(x.toPrecision(4)).toString();
const state = (names: readonly string[], x: ArrayLike<number>) => `(${names.join(', ')}) = (${Array.from(x, short).join(', ')})`;

/** How many random states the equations are compared at. */
export const STATES = 8;

/**
 * Relative agreement asked of the equations. Symbolic derivatives agree to
 * rounding; an opaque JS function is differentiated by 5-point central
 * differences (core/js-function), good to about 10⁻⁹ of the scale, so 10⁻⁶
 * passes every correct H by either route and fails any wrong coefficient
 * larger than one part in a million.
 */
export const EQUATIONS_TOLERANCE = 1e-6;

export function equationsCheck(reader: Model, reference: Model, box: readonly (readonly [number, number])[], seed = 1, time: readonly [number, number] = [0, 0]): Verdict {
  const draw = uniform(seed);
  const [early, late] = time;
  // A time is drawn only for a range, so a check at t = 0 meets the same states as ever.
  const when = () => (late > early ? early + (late - early) * draw() : early);
  const x = new Float64Array(reference.dim);
  const mine = new Float64Array(reference.dim);
  const theirs = new Float64Array(reference.dim);
  const rate = reference.names.map((n) => `${n}̇`);
  let worst = 0;
  for (let k = 0; k < STATES; k++) {
    const t = when();
    box.forEach(([low, high], i) => (x[i] = low + (high - low) * draw()));
    reader.field(t, x, mine);
    reference.field(t, x, theirs);
    const scale = Math.max(1, ...Array.from(theirs, Math.abs));
    for (let i = 0; i < reference.dim; i++) {
      const gap = Math.abs(mine[i] - theirs[i]) / scale;
      if (!(gap <= EQUATIONS_TOLERANCE)) {
        const wrong = rate[i];
        return {
          passed: false,
          message: `Hamilton’s equations differ at ${late > early ? `t = ${short(t)}, ` : ''}${state(reference.names, x)}: your H gives ${wrong} = ${short(mine[i])}, where the right one is ${short(theirs[i])}.`,
        };
      }
      worst = Math.max(worst, gap);
    }
  }
  const times = late > early ? ` and times ${short(early)} ≤ t ≤ ${short(late)}` : '';
  return { passed: true, message: `Hamilton’s equations of your H equal the reference’s at ${STATES} random states${times} (largest relative difference ${worst.toExponential(1)}).` };
}

/**
 * Integrates the reader's model for one `period` from `initial` (RK 3/8 at
 * step `dt`, whose error over one period of ω ≈ 2π/period is about
 * 2π(ωΔt)⁴/120, far below the default tolerance 10⁻⁴ of the state's size) and
 * says how far from its start it ends.
 */
export function returnsCheck(reader: Model, initial: readonly number[], period: number, dt = 1e-3, tolerance = 1e-4): Verdict {
  const x = Float64Array.from(initial);
  const steps = Math.max(1, Math.round(period / dt));
  const done = reader.stepper.advance(x, 1, reader.params, 0, 0, period / steps, steps);
  const start = state(reader.names, initial);
  if (done < steps) return { passed: false, message: `Released from ${start}, your system blows up before one period ${short(period)} has passed.` };
  const size = Math.max(1, ...initial.map(Math.abs));
  const distance = Math.hypot(...Array.from(x, (v, i) => v - initial[i])) / size;
  return distance <= tolerance
    ? { passed: true, message: `Released from ${start}, your system returns to it after the period ${short(period)}, to ${distance.toExponential(1)} of its size.` }
    : { passed: false, message: `Released from ${start}, your system is at ${state(reader.names, x)} after ${short(period)}, not back where it began: its period is not the one asked for.` };
}

/** Runs one declared check. */
export function runCheck(check: CodeCheck, reader: Model, reference: Model, seed = 1): Verdict {
  if (reader.dim !== reference.dim) return { passed: false, message: `Your H has ${reader.dof} degree${reader.dof > 1 ? 's' : ''} of freedom; the exercise asks for ${reference.dof}.` };
  if (check.check === 'equationsInTime') return equationsCheck(reader, reference, check.box, seed, check.time);
  return check.check === 'equations' ? equationsCheck(reader, reference, check.box, seed) : returnsCheck(reader, check.initial, check.period, check.dt, check.tolerance);
}
