/**
 * Builtins whose value changes over time are generators: the runtime pulls
 * one value per animation frame, and a yielded promise makes it wait.
 */

/**
 * A generator that yields whatever `subscribe` reports, waiting (yielding a
 * promise) while nothing has changed. `subscribe` returns its clean-up, which
 * runs when the runtime stops the generator (the cell was redefined or the
 * page disposed the runtime).
 */
export function* observe<T>(subscribe: (change: (value: T) => void) => () => void): Generator<T | Promise<T>, void, unknown> {
  let latest: T | undefined;
  let fresh = false;
  let wake: ((value: T) => void) | null = null;
  const unsubscribe = subscribe((value) => {
    latest = value;
    if (wake) {
      wake(value);
      wake = null;
    } else {
      fresh = true;
    }
  });
  try {
    while (true) {
      if (fresh) {
        fresh = false;
        yield latest as T;
      } else {
        yield new Promise<T>((resolve) => (wake = resolve));
      }
    }
  } finally {
    unsubscribe();
  }
}

/**
 * The width in CSS pixels of `element`'s content box, updated on resize.
 * ResizeObserver reports once as soon as it observes, which gives the first value.
 */
export function observeWidth(element: Element): Generator<number | Promise<number>, void, unknown> {
  return observe<number>((change) => {
    let last = -1;
    const report = (width: number) => {
      if (width !== last) change((last = width));
    };
    const observer = new ResizeObserver(([entry]) => {
      if (entry) report(Math.floor(entry.contentRect.width));
    });
    observer.observe(element);
    return () => observer.disconnect();
  });
}

/** The current `performance.now()`, once per animation frame. */
export function* observeNow(): Generator<number, never, unknown> {
  while (true) yield performance.now();
}
