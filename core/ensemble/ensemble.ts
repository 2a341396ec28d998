/**
 * An ensemble of a one-degree-of-freedom model: a disc of initial
 * conditions in the phase plane, carried by the flow as a cloud of points
 * and, separately, as its boundary, a polygon refined where it stretches
 * (tracked-boundary.ts). The cloud shows where the blob goes; the boundary
 * measures its area, which Liouville's theorem keeps (and a
 * non-Hamiltonian term does not). Pure: the page runs it in a worker, the
 * chapter's checks on the page, the tests in Node, with the same numbers.
 */
import { InputError } from '../errors.ts';
import type { Stepper } from '../types.ts';
import { discArea } from './boundary-curve.ts';
import { trackedDisc } from './flow-area.ts';
import type { TrackedBoundary } from './tracked-boundary.ts';

export interface EnsembleSetup {
  /** the disc's centre (q, p) */
  center: readonly [number, number];
  /** its radius, or its semi-axes along q and p */
  radius: number | readonly [number, number];
  /** points in the cloud */
  points: number;
  dt: number;
  t0?: number;
  /** the boundary's polygon at the start, refined from there */
  vertices?: number;
  /** the longest segment of the boundary, in units of the disc's radius along each axis */
  maxSegment?: number;
}

/** The most points a cloud may hold: beyond, a frame's steps take longer than a frame. */
export const MOST_POINTS = 200_000;

/** What an ensemble is at one time. */
export interface EnsembleState {
  t: number;
  /** steps taken from the start */
  k: number;
  /** the cloud: q, p pairs */
  cloud: Float64Array;
  area: number;
  areaError: number;
  /** the disc's area at the start, πab */
  initialArea: number;
  vertices: number;
  /** the boundary needed more vertices than it may hold: its area is no longer measured */
  saturated: boolean;
  /** a point left the finite numbers: the step at which it did */
  failed: boolean;
}

/** The golden angle: successive points of a Vogel spiral, each turned by it, fill a disc evenly. */
const GOLDEN_ANGLE = Math.PI * (3 - Math.sqrt(5));

/**
 * `points` starts spread evenly over the disc (a Vogel spiral, r ∝ √((i + ½)/n)
 * at the angle i times the golden angle): every point carries the same share
 * of the area, with no clumps a random draw would leave.
 */
export function discCloud(center: readonly [number, number], radius: readonly [number, number], points: number): Float64Array {
  const cloud = new Float64Array(2 * points);
  for (let i = 0; i < points; i++) {
    const r = Math.sqrt((i + 0.5) / points);
    const angle = i * GOLDEN_ANGLE;
    cloud[2 * i] = center[0] + radius[0] * r * Math.cos(angle);
    cloud[2 * i + 1] = center[1] + radius[1] * r * Math.sin(angle);
  }
  return cloud;
}

export class Ensemble {
  readonly cloud: Float64Array;
  readonly boundary: TrackedBoundary;
  readonly initialArea: number;
  #k = 0;
  #failed = false;

  private readonly params: Float64Array;

  constructor(
    private readonly stepper: Stepper,
    params: Float64Array,
    private readonly setup: EnsembleSetup,
  ) {
    // The values at the start, as the boundary keeps them: cloud and boundary move under one flow.
    this.params = Float64Array.from(params);
    if (stepper.dim !== 2) throw new InputError(`an ensemble in the phase plane needs a model of one degree of freedom, not ${stepper.dim / 2}`);
    const { center, points, dt, t0 = 0, vertices = 256, maxSegment = 0.1 } = setup;
    const radius: [number, number] = typeof setup.radius === 'number' ? [setup.radius, setup.radius] : [setup.radius[0], setup.radius[1]];
    if (!(center.length === 2 && center.every(Number.isFinite))) throw new InputError('the ensemble’s center must be two finite numbers, [q, p]');
    if (!(radius[0] > 0 && radius[1] > 0 && Number.isFinite(radius[0] + radius[1]))) throw new InputError('the ensemble’s radius must be positive: a number, or [along q, along p]');
    if (!(Number.isInteger(points) && points >= 1 && points <= MOST_POINTS)) throw new InputError(`the ensemble’s points must be a whole number from 1 to ${MOST_POINTS}, not ${points}`);
    if (!(dt > 0 && Number.isFinite(dt))) throw new InputError(`the ensemble’s dt must be a positive number, not ${dt}`);
    this.cloud = discCloud(center, radius, points);
    this.initialArea = discArea(radius);
    this.boundary = trackedDisc(stepper, params, { center, radius, dt, t0, vertices, maxSegment });
  }

  get t(): number {
    return (this.setup.t0 ?? 0) + this.#k * this.setup.dt;
  }

  /** Carries the cloud and the boundary `steps` steps further; once a point has blown up, nothing more moves. */
  advance(steps: number): void {
    if (this.#failed || steps <= 0) return;
    const { points, dt, t0 = 0 } = this.setup;
    const done = this.stepper.advance(this.cloud, points, this.params, t0, this.#k, dt, steps);
    if (done < steps) {
      this.#failed = true;
      this.#k += done;
      return;
    }
    this.boundary.advance(steps);
    if (this.boundary.failed) this.#failed = true;
    this.#k += steps;
  }

  /** The ensemble now: the cloud is the live array, copied by whoever keeps it. */
  state(): EnsembleState {
    const b = this.boundary;
    return {
      t: this.t,
      k: this.#k,
      cloud: this.cloud,
      area: b.area(),
      areaError: b.areaError(),
      initialArea: this.initialArea,
      vertices: b.count,
      saturated: b.saturated,
      failed: this.#failed,
    };
  }
}
