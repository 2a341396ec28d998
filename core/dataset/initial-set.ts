/**
 * The initial states of a dataset's trajectories: given one by one (on the
 * command line or in a file), drawn uniformly in a box from a seed (and
 * optionally moved onto an energy surface), or laid on a grid.
 *
 * Any trajectory's initial state is computed from the set's description and
 * its index alone, so a worker, or a shard on another machine, makes exactly
 * the states the whole run would have given those trajectories.
 */
import { InputError } from '../errors.ts';
import type { HamiltonianFunction } from '../types.ts';
import { pointIn, type Axis, type Range } from './box.ts';
import { momentumRoots, type EnergyTarget } from './energy-surface.ts';
import { gridPoint, gridSize } from './grid.ts';
import { CounterRandom } from './philox.ts';

export type InitialSet =
  | { kind: 'given'; dim: number; values: ArrayLike<number> }
  | { kind: 'sample'; count: number; seed: number; box: readonly Range[]; energy?: { value: number; component: number } }
  | { kind: 'grid'; axes: readonly Axis[] };

/** Draws for one trajectory before a point with a solution counts as not to be found: a 1 % acceptance still fails less than once in 1e40. */
export const ENERGY_ATTEMPTS = 10_000;

/** Random streams of a trajectory: the point in the box, and the choice among roots. */
const BOX = 0;
const ROOT = 1;

export function trajectoryCount(set: InitialSet): number {
  switch (set.kind) {
    case 'given':
      return set.values.length / set.dim;
    case 'sample':
      return set.count;
    case 'grid':
      return gridSize(set.axes);
  }
}

export interface FillContext {
  dim: number;
  /** H, to project onto an energy surface */
  hamiltonian?: HamiltonianFunction;
  /** the time at which H is evaluated: t0 */
  t0: number;
  /** the state names, for messages */
  names: readonly string[];
}

/** The initial states of trajectories [first, first + count), one after another in `out`. */
export function fillInitial(set: InitialSet, first: number, count: number, out: Float64Array, context: FillContext): void {
  const { dim } = context;
  if (set.kind === 'given') {
    for (let i = 0; i < count * dim; i++) out[i] = set.values[first * dim + i];
    return;
  }
  if (set.kind === 'grid') {
    for (let j = 0; j < count; j++) gridPoint(set.axes, first + j, out, j * dim);
    return;
  }
  const random = new CounterRandom(set.seed);
  const x = new Float64Array(dim);
  for (let j = 0; j < count; j++) {
    const trajectory = first + j;
    if (set.energy) projectOntoEnergy(set, random, trajectory, x, context);
    else for (let c = 0; c < dim; c++) x[c] = pointIn(set.box[c], random.uniform(trajectory, BOX, 0, c));
    out.set(x, j * dim);
  }
}

function projectOntoEnergy(
  set: Extract<InitialSet, { kind: 'sample' }>,
  random: CounterRandom,
  trajectory: number,
  x: Float64Array,
  context: FillContext,
): void {
  const energy = set.energy!;
  const h = context.hamiltonian;
  if (!h) throw new InputError('--energy needs H: a vector field alone has no energy to fix');
  const target: EnergyTarget = { value: energy.value, component: energy.component, range: set.box[energy.component] };
  let low = Infinity;
  let high = -Infinity;
  for (let attempt = 0; attempt < ENERGY_ATTEMPTS; attempt++) {
    for (let c = 0; c < x.length; c++) x[c] = pointIn(set.box[c], random.uniform(trajectory, BOX, attempt, c));
    const found = momentumRoots(h, context.t0, x, target);
    if (found.roots.length > 0) {
      const pick = Math.floor(random.uniform(trajectory, ROOT, attempt, 0) * found.roots.length);
      x[energy.component] = found.roots[pick];
      return;
    }
    low = Math.min(low, found.low);
    high = Math.max(high, found.high);
  }
  const name = context.names[energy.component];
  const { lo, hi } = target.range;
  const seen = low <= high ? `; H − E ranged over [${low.toPrecision(4)}, ${high.toPrecision(4)}] at the points tried` : '';
  throw new InputError(
    `no point of the box reaches H = ${energy.value} with ${name} in [${lo}, ${hi}] (trajectory ${trajectory}, ${ENERGY_ATTEMPTS} points tried${seen})`,
  );
}
