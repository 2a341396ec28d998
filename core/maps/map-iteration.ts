/**
 * Orbits of an area-preserving map (core/maps/area-preserving-map.ts), as
 * arrays for a plot or as a TrajectoryRecord for the exports, with the
 * iterate n standing in the record's t column.
 */
import { TrajectoryRecord } from '../record.ts';
import { type AreaPreservingMap, TWO_PI } from './area-preserving-map.ts';

/** The most iterates one call will compute and hold: 10⁷ rows of two doubles is 160 MB, the edge of what a tab can spare. */
export const MAX_ITERATES = 10_000_000;

/** Throws unless `iterations` is a whole number from 0 to MAX_ITERATES. */
function checkIterations(iterations: number): void {
  if (!Number.isInteger(iterations) || iterations < 0 || iterations > MAX_ITERATES) {
    throw new RangeError(`the number of iterations must be a whole number from 0 to ${MAX_ITERATES}, not ${iterations}`);
  }
}

/** The momentum `p` reduced into [−π, π): the torus the standard map is periodic on in p too, for drawing. */
function wrapMomentum(p: number): number {
  const r = (p + Math.PI) % TWO_PI;
  const w = (r < 0 ? r + TWO_PI : r) - Math.PI;
  return w >= Math.PI ? -Math.PI : w;
}

/**
 * The orbit of `start` under `map`: `iterations` + 1 points, the start
 * first. With `reduceP`, p is reduced into [−π, π) as it is stored (the
 * iteration itself goes on with the unreduced value), for maps periodic in
 * p as well as q, such as the standard map, drawn on the torus.
 */
export function iterateMap(map: AreaPreservingMap, start: readonly [number, number], iterations: number, options: { reduceP?: boolean } = {}): { q: Float64Array; p: Float64Array } {
  checkIterations(iterations);
  const reduce = options.reduceP === true;
  const q = new Float64Array(iterations + 1);
  const p = new Float64Array(iterations + 1);
  const state = Float64Array.of(start[0], start[1]);
  for (let n = 0; ; n++) {
    q[n] = state[0];
    p[n] = reduce ? wrapMomentum(state[1]) : state[1];
    if (n === iterations) break;
    map.step(state);
  }
  return { q, p };
}

/**
 * The orbit of `start` as a TrajectoryRecord with the columns t, q, p, t
 * holding the iterate n, so the record goes through the CSV and JSON exports
 * like a flow's. The record holds every row: capacity iterations + 1.
 */
export function mapRecord(map: AreaPreservingMap, start: readonly [number, number], iterations: number): TrajectoryRecord {
  checkIterations(iterations);
  const record = new TrajectoryRecord(['t', ...map.names], iterations + 1);
  const state = Float64Array.of(start[0], start[1]);
  const row = new Float64Array(3);
  for (let n = 0; ; n++) {
    row[0] = n;
    row[1] = state[0];
    row[2] = state[1];
    record.push(row);
    if (n === iterations) break;
    map.step(state);
  }
  return record;
}
