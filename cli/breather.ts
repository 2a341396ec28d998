/**
 * Returns to the event loop now and then in a long stretch of work that
 * never does on its own. Node runs a signal's listener only from the event
 * loop, and a loop over promises that resolve at once (reading a file with
 * synchronous reads through async generators, as merge and reproduce do)
 * runs in microtasks without ever reaching it: merge once ran 118 s to its
 * end through SIGTERM. A breather costs a clock read per call and a return
 * to the event loop every BREATH_MS, a few microseconds each.
 */

/** Longest stretch without a return to the event loop. */
const BREATH_MS = 20;

/**
 * A function to await between two pieces of work: it returns to the event
 * loop once BREATH_MS have passed since the last time, then throws the
 * reason of `signal` (an Interrupted) if it was aborted meanwhile.
 */
export function breather(signal: AbortSignal | undefined, clock: () => number = () => performance.now()): () => Promise<void> {
  let last = clock();
  return async () => {
    if (clock() - last < BREATH_MS) return;
    await new Promise<void>((resolve) => setImmediate(resolve));
    signal?.throwIfAborted();
    last = clock();
  };
}
