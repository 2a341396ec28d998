/**
 * The area of a disc of initial conditions after the flow has carried it
 * for a time: the measurement the Liouville chapter's checks make, run to
 * the end in one call where the ensemble widget shows it frame by frame.
 */
import { InputError } from '../errors.ts';
import type { Model, Stepper } from '../types.ts';
import { discArea, discBoundary, semiAxes } from './boundary-curve.ts';
import { TrackedBoundary } from './tracked-boundary.ts';

export interface FlowAreaOptions {
  center: readonly [number, number];
  /** a radius, or the semi-axes along q and p */
  radius: number | readonly [number, number];
  dt: number;
  /** how long the flow carries the disc */
  span: number;
  /** the longest side of the boundary, in units of the radius along each axis */
  maxSegment?: number;
  /** vertices at the start */
  vertices?: number;
  maxVertices?: number;
}

export interface FlowArea {
  /** the time reached */
  t: number;
  /** the boundary polygon's shoelace area */
  area: number;
  /** a bound on the polygon's own error against the curve through its vertices (polygonAreaError) */
  polygonError: number;
  /** the disc's area at the start, πab */
  initialArea: number;
  vertices: number;
  /** the boundary outgrew maxVertices, or stretched faster than refinement could follow: its area is not measured */
  saturated: boolean;
  unresolved: boolean;
  /** a vertex left the finite numbers */
  failed: boolean;
}

/** What a disc's tracked boundary is made from: its place, its step, and how finely it is followed. */
export type DiscSetup = Pick<FlowAreaOptions, 'center' | 'radius' | 'dt' | 'maxSegment' | 'vertices' | 'maxVertices'> & { t0?: number };

/** The boundary of the disc in the phase plane, to be carried by `stepper`, its sides measured in units of the radius along each axis. */
export function trackedDisc(stepper: Stepper, params: Float64Array, setup: DiscSetup): TrackedBoundary {
  const { center, radius, dt, t0 = 0, maxSegment = 0.05, vertices = 512, maxVertices } = setup;
  return new TrackedBoundary({
    stepper,
    params,
    curve: discBoundary(center, radius),
    dim: 2,
    t0,
    dt,
    initialVertices: vertices,
    maxSegment,
    maxVertices,
    scale: semiAxes(radius),
  });
}

/** Carries the disc's boundary `span` time units by `model`'s own stepper, in steps of dt, and measures the area it encloses. */
export function flowArea(model: Model, options: FlowAreaOptions): FlowArea {
  const { radius, dt, span, maxVertices = 100_000 } = options;
  if (model.dim !== 2) throw new InputError(`flowArea measures an area in the phase plane of one degree of freedom, not ${model.dof}`);
  if (!(span >= 0 && Number.isFinite(span))) throw new InputError(`flowArea: span must be a time ≥ 0, not ${span}`);
  const boundary = trackedDisc(model.stepper, model.params, { ...options, maxVertices });
  const steps = Math.round(span / dt);
  // In stretches, so the polygon is refined as it stretches rather than once at the end, when neighbours would have parted far.
  const stretch = Math.max(1, Math.round(0.1 / dt));
  for (let done = 0; done < steps && !boundary.failed && !boundary.saturated; ) {
    const now = Math.min(stretch, steps - done);
    boundary.advance(now);
    done += now;
  }
  return {
    t: boundary.t,
    area: boundary.area(),
    polygonError: boundary.areaError(),
    initialArea: discArea(radius),
    vertices: boundary.count,
    saturated: boundary.saturated,
    unresolved: boundary.unresolved,
    failed: boundary.failed,
  };
}
