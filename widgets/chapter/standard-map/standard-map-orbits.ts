/**
 * The standard map's phase portrait as pixels: many orbits iterated from a
 * lattice of starts on the torus and each iterate marked in its orbit's
 * colour straight into the canvas's image. Hundreds of thousands of points
 * are drawn by writing words into one buffer, where as many fillRect calls
 * would take longer than a frame.
 */
import { type AreaPreservingMap, TWO_PI, wrapAngle } from '../../../core/index.ts';
import type { PixelMapping } from '../../plots/pixel-image.ts';

/** The torus as drawn: q in [0, 2π), p reduced into [−π, π) so that the main island about (π, 0) sits in the middle. */
export const Q_DOMAIN: [number, number] = [0, TWO_PI];
export const P_DOMAIN: [number, number] = [-Math.PI, Math.PI];

/** p reduced into [−π, π): the map is periodic in p with period 2π, so the torus holds every orbit. */
export function torusP(p: number): number {
  return wrapAngle(p + Math.PI) - Math.PI;
}

/**
 * About `count` starts on a square lattice over the torus, offset by half a
 * cell so that none sits on a fixed point or on the lines q = 0, π where the
 * symmetric orbits lie (those would draw as single dots): the pairs q, p one
 * after the other, the state each orbit is iterated from.
 */
export function startGrid(count: number): Float64Array {
  const side = Math.max(1, Math.round(Math.sqrt(count)));
  const starts = new Float64Array(2 * side * side);
  for (let i = 0; i < side; i++) {
    for (let j = 0; j < side; j++) {
      starts[2 * (i * side + j)] = ((i + 0.5) / side) * TWO_PI;
      starts[2 * (i * side + j) + 1] = P_DOMAIN[0] + ((j + 0.37) / side) * TWO_PI;
    }
  }
  return starts;
}

/**
 * Iterates each orbit `iterations` times further under `map`, from its state
 * in `states` (the pairs q, p, updated in place), and marks every iterate in
 * `pixels` (RGBA words of an image `to.width` × `to.height`) with its
 * orbit's colour, `colours[k mod colours.length]`. Returns the points marked.
 * Called again on the same states, it carries the orbits on: a portrait can
 * be drawn a part per frame.
 */
export function markOrbits(pixels: Uint32Array, to: PixelMapping, map: AreaPreservingMap, states: Float64Array, iterations: number, colours: Uint32Array): number {
  const state = new Float64Array(2);
  const { width, height, qScale, qOffset, pScale, pOffset } = to;
  let marked = 0;
  for (let k = 0; 2 * k < states.length; k++) {
    const colour = colours[k % colours.length];
    state[0] = states[2 * k];
    state[1] = states[2 * k + 1];
    for (let n = 0; n < iterations; n++) {
      map.step(state);
      // Kept on the torus as it goes: the map is 2π-periodic in p, and a bounded p keeps sin and the sum exact.
      if (state[1] >= Math.PI || state[1] < -Math.PI) state[1] = torusP(state[1]);
      const x = Math.floor(qScale * state[0] + qOffset);
      const y = Math.floor(pScale * state[1] + pOffset);
      if (x >= 0 && x < width && y >= 0 && y < height) {
        pixels[y * width + x] = colour;
        marked++;
      }
    }
    states[2 * k] = state[0];
    states[2 * k + 1] = state[1];
  }
  return marked;
}
