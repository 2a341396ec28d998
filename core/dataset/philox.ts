/**
 * Philox4x32-10, the counter-based random number generator of Salmon,
 * Moraes, Dror & Shaw, "Parallel random numbers: as easy as 1, 2, 3" (SC '11),
 * as in their Random123 library.
 *
 * Counter-based means that the numbers for any counter are computed directly,
 * with no state carried from one call to the next: trajectory 7 of a sampled
 * set gets the same initial state whether it is computed alone, by the third
 * of four workers, or in shard 2 of 5 on another machine. That is what makes
 * a dataset reproducible from its seed however it is split.
 */

const M0 = 0xd2511f53;
const M1 = 0xcd9e8d57;
const W0 = 0x9e3779b9;
const W1 = 0xbb67ae85;
const TWO32 = 4294967296;

/** The high 32 bits of the 64-bit product of two unsigned 32-bit numbers, exactly (doubles hold 53 bits, so in 16-bit halves). */
function mulhi(a: number, b: number): number {
  const low = a * (b & 0xffff); // < 2^48: exact
  const high = a * (b >>> 16); // < 2^48: exact; the product is high·2^16 + low
  const highTop = Math.floor(high / 65536);
  const rest = (high - highTop * 65536) * 65536 + low; // < 2^49: exact
  return (highTop + Math.floor(rest / TWO32)) >>> 0;
}

/**
 * The four 32-bit words of Philox4x32-10 for `counter` (four words) under
 * `key` (two words), written into `out`.
 */
export function philox4x32(counter: ArrayLike<number>, key: ArrayLike<number>, out: Uint32Array | number[]): void {
  let c0 = counter[0] >>> 0;
  let c1 = counter[1] >>> 0;
  let c2 = counter[2] >>> 0;
  let c3 = counter[3] >>> 0;
  let k0 = key[0] >>> 0;
  let k1 = key[1] >>> 0;
  for (let round = 0; round < 10; round++) {
    if (round > 0) {
      k0 = (k0 + W0) >>> 0;
      k1 = (k1 + W1) >>> 0;
    }
    const hi0 = mulhi(M0, c0);
    const lo0 = Math.imul(M0, c0) >>> 0;
    const hi1 = mulhi(M1, c2);
    const lo1 = Math.imul(M1, c2) >>> 0;
    c0 = (hi1 ^ c1 ^ k0) >>> 0;
    c1 = lo1;
    c2 = (hi0 ^ c3 ^ k1) >>> 0;
    c3 = lo0;
  }
  out[0] = c0;
  out[1] = c1;
  out[2] = c2;
  out[3] = c3;
}

/** A double in [0, 1) from 53 bits of two words: 27 of the first, 26 of the second. */
export function unitInterval(a: number, b: number): number {
  return ((a >>> 5) * 67108864 + (b >>> 6)) / 9007199254740992;
}

/** Largest seed: any whole number below 2^53 splits exactly into the two key words. */
export const MAX_SEED = Number.MAX_SAFE_INTEGER;

/**
 * Uniform doubles in [0, 1) addressed by (trajectory, purpose, attempt,
 * index): the same address gives the same number in any process.
 */
export class CounterRandom {
  private readonly key: [number, number];
  private readonly counter = [0, 0, 0, 0];
  private readonly words = new Uint32Array(4);

  constructor(seed: number) {
    if (!Number.isSafeInteger(seed) || seed < 0) throw new RangeError(`the seed must be a whole number from 0 to ${MAX_SEED}, not ${seed}`);
    this.key = [seed % TWO32, Math.floor(seed / TWO32)];
  }

  /**
   * Number `index` of the draws for `trajectory`'s `purpose` (0: the box, 1:
   * the choice among roots, …) at its `attempt`-th try. Two numbers come of
   * one counter, so indices 2i and 2i + 1 share it.
   */
  uniform(trajectory: number, purpose: number, attempt: number, index: number): number {
    const c = this.counter;
    c[0] = trajectory % TWO32;
    c[1] = Math.floor(trajectory / TWO32);
    c[2] = attempt;
    c[3] = purpose * 2 ** 24 + Math.floor(index / 2);
    philox4x32(c, this.key, this.words);
    const w = this.words;
    return index % 2 === 0 ? unitInterval(w[0], w[1]) : unitInterval(w[2], w[3]);
  }
}
