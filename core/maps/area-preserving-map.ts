/**
 * Area-preserving maps of the cylinder: the core's small extension from
 * flows to maps. Where the rest of the core integrates the canonical
 * equations of a Hamiltonian in time t, a map is iterated, and the iterate
 * number n plays the part of t. A map of this kind is what a Poincaré
 * section of a two-degree-of-freedom flow reduces to (or what a periodically
 * kicked system is, exactly): symplectic in two dimensions means area- and
 * orientation-preserving, so the Jacobian's determinant is 1.
 *
 * The state is [q, p], q an angle on [0, 2π) and p its conjugate momentum,
 * left on the line unless a map says otherwise, so that its drift can be
 * measured.
 */

/** 2π, the period of the angle q. */
export const TWO_PI = 2 * Math.PI;

/**
 * The angle `q` reduced into [0, 2π). The remainder of a negative q is
 * negative, hence the second reduction; and a q just below 0 can round up
 * to exactly 2π, which is put back to 0 so the interval stays half-open.
 * A q within one turn above the interval, the usual case of an iterated
 * map, takes one subtraction instead of the remainder, which is several
 * times slower: it is exact there (Sterbenz), so the result is the same.
 */
export function wrapAngle(q: number): number {
  if (q >= 0 && q < TWO_PI) return q;
  if (q >= TWO_PI && q < 2 * TWO_PI) return q - TWO_PI;
  const r = q % TWO_PI;
  const w = r < 0 ? r + TWO_PI : r;
  return w === TWO_PI ? 0 : w;
}

/** An area-preserving map of the cylinder (q mod 2π, p), stepped in place. */
export interface AreaPreservingMap {
  /** the map's name, as a reader would say it: "standard map, K = 0.97" */
  readonly name: string;
  /** the names of the two coordinates, angle first */
  readonly names: readonly [string, string];
  /** one iterate, in place: `state` is [q, p] before, [q', p'] after */
  step(state: Float64Array): void;
  /** the Jacobian ∂(q', p')/∂(q, p) at (q, p), row-major: [∂q'/∂q, ∂q'/∂p, ∂p'/∂q, ∂p'/∂p] */
  jacobian(q: number, p: number): [number, number, number, number];
}
