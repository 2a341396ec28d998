/**
 * The standard (Chirikov–Taylor) map, the kicked rotor seen once a period
 * (Chirikov 1979, Phys. Rep. 52, 263; Lichtenberg & Lieberman, Regular and
 * Chaotic Dynamics, §3.1b):
 *
 *   p' = p + K sin q,   q' = q + p'  (mod 2π)
 *
 * The kick uses the old angle and the drift the new momentum, which is what
 * makes it symplectic: it is the composition of two shears, each of
 * determinant 1. Only q is reduced; p is kept on the line so that its
 * diffusion across the cylinder can be measured.
 */
import { type AreaPreservingMap, wrapAngle } from './area-preserving-map.ts';

/** The standard map with kick strength `K`, which must be a finite number. */
export function standardMap(K: number): AreaPreservingMap {
  if (typeof K !== 'number' || !Number.isFinite(K)) throw new RangeError(`the standard map's kick strength K must be a finite number, not ${String(K)}`);
  return {
    name: `standard map, K = ${K}`,
    names: ['q', 'p'],
    step(state: Float64Array): void {
      const p = state[1] + K * Math.sin(state[0]);
      state[1] = p;
      state[0] = wrapAngle(state[0] + p);
    },
    jacobian(q: number): [number, number, number, number] {
      // p' = p + K sin q gives ∂p'/∂q = K cos q, ∂p'/∂p = 1; q' = q + p' adds the row of p' to (1, 0).
      const kick = K * Math.cos(q);
      return [1 + kick, 1, kick, 1];
    },
  };
}
