/**
 * The initial boundary of a blob of initial conditions, as a closed curve
 * parametrised by s ∈ [0, 1). The boundary is tracked by its points, not its
 * interior: a Hamiltonian flow is a continuous, invertible map, so the image
 * of the blob is the region bounded by the image of its boundary, and the
 * parameter s names the same point of that boundary at every time. A vertex
 * added later, where the image has stretched, is the image of the point of
 * the initial curve at its s.
 */
import { InputError } from '../errors.ts';

export interface BoundaryCurve {
  /**
   * Writes the full state (2·dof numbers, q's then p's) of the curve's point
   * at parameter s ∈ [0, 1) into `out`. The curve must close (s → 1 meets
   * s = 0) and be traversed counter-clockwise in the (q, p) plane of the first
   * degree of freedom, so that its shoelace area is positive.
   */
  point(s: number, out: Float64Array): void;
}

/** Semi-axes [r_q, r_p] of an ellipse, from one radius or two. */
export function semiAxes(radius: number | readonly [number, number]): [number, number] {
  const [rq, rp] = typeof radius === 'number' ? [radius, radius] : radius;
  if (!(rq > 0 && rp > 0 && Number.isFinite(rq) && Number.isFinite(rp))) {
    throw new InputError(`a disc's radius must be finite and > 0, not ${typeof radius === 'number' ? radius : `[${radius.join(', ')}]`}`);
  }
  return [rq, rp];
}

/**
 * The circle (or ellipse of semi-axes [r_q, r_p]) about `center` in the
 * plane of the first coordinate q and its momentum p:
 * q = c_q + r_q cos 2πs, p = c_p + r_p sin 2πs, counter-clockwise. `center`
 * is a full state of 2·dof numbers; for dof > 1 the other components stay at
 * the centre's values, so the curve is a loop in one conjugate plane.
 */
export function discBoundary(center: readonly number[], radius: number | readonly [number, number]): BoundaryCurve {
  const dim = center.length;
  if (dim < 2 || dim % 2 !== 0 || !center.every(Number.isFinite)) {
    throw new InputError(`a disc's centre must be a full state of 2·dof finite numbers, not [${center.join(', ')}]`);
  }
  const [rq, rp] = semiAxes(radius);
  const dof = dim / 2;
  const c = Float64Array.from(center);
  return {
    point(s, out) {
      for (let i = 0; i < dim; i++) out[i] = c[i];
      const angle = 2 * Math.PI * s;
      out[0] += rq * Math.cos(angle);
      out[dof] += rp * Math.sin(angle);
    },
  };
}

/** The area π r_q r_p that discBoundary encloses, the truth the tracked area is held to under a Hamiltonian flow. */
export function discArea(radius: number | readonly [number, number]): number {
  const [rq, rp] = semiAxes(radius);
  return Math.PI * rq * rp;
}
