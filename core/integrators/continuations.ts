/**
 * The adaptive method's continuations between calls, found again by the
 * sample the last call left. A run is cut into calls (frames on the page,
 * paced stretches in the CLI), and a trajectory whose internal step were
 * restarted at each cut would get other numbers; so each call keeps where
 * every trajectory's integration stands, under its sample grid (t0, dt), the
 * sample number reached and the state written there, and the next call that
 * brings that very state continues it.
 */

/** What a continuation is found by: the samples t0 + k·dt, the next k, and the state written at the last. */
export interface Resumable {
  t0: number;
  dt: number;
  k: number;
  sample: Float64Array;
}

export interface Continuations<C extends Resumable> {
  /** Takes out the continuation that left x[o…o+dim) as sample k of t0 + k·dt, if one is kept. */
  take(x: Float64Array, o: number, t0: number, dt: number, k: number): C | undefined;
  /** Keeps c, which has just written x[o…o+dim) as its sample c.k; beyond `capacity`, the oldest go. */
  keep(c: C, x: Float64Array, o: number): void;
}

/** A store of at least `capacity` continuations of states of `dim` components (enough for a worker's batch). */
export function continuations<C extends Resumable>(dim: number, capacity: number): Continuations<C> {
  const kept = new Map<string, C[]>();
  let count = 0;
  // The sample grid, the sample number and the state's first and last components: few states share one.
  const keyOf = (t0: number, dt: number, k: number, x: Float64Array, o: number) => `${t0}|${dt}|${k}|${x[o]}|${x[o + dim - 1]}`;

  function take(x: Float64Array, o: number, t0: number, dt: number, k: number): C | undefined {
    const key = keyOf(t0, dt, k, x, o);
    const list = kept.get(key);
    if (!list) return undefined;
    const at = list.findIndex((c) => c.sample.every((v, i) => v === x[o + i]));
    if (at < 0) return undefined;
    const [c] = list.splice(at, 1);
    if (list.length === 0) kept.delete(key);
    count--;
    return c;
  }

  function keep(c: C, x: Float64Array, o: number): void {
    c.sample.set(x.subarray(o, o + dim));
    const key = keyOf(c.t0, c.dt, c.k, x, o);
    const list = kept.get(key);
    if (list) list.push(c);
    else kept.set(key, [c]);
    count++;
    // The oldest go first: a trajectory not continued for this long has been restarted or dropped.
    while (count > capacity) {
      const [oldest, entries] = kept.entries().next().value as [string, C[]];
      entries.shift();
      if (entries.length === 0) kept.delete(oldest);
      count--;
    }
  }

  return { take, keep };
}
