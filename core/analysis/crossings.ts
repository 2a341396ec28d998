/**
 * Times at which a sampled series crosses a level, linearly interpolated
 * between samples: the independent, FFT-free way to measure a period.
 * `direction` +1 keeps upward crossings, −1 downward, 0 both.
 */
export function crossings(
  t: ArrayLike<number>,
  y: ArrayLike<number>,
  level = 0,
  direction: -1 | 0 | 1 = 1,
): number[] {
  const out: number[] = [];
  for (let i = 1; i < y.length; i++) {
    const a = y[i - 1] - level;
    const b = y[i] - level;
    const up = a < 0 && b >= 0;
    const down = a > 0 && b <= 0;
    if ((up && direction >= 0) || (down && direction <= 0)) {
      out.push(t[i - 1] + (a / (a - b)) * (t[i] - t[i - 1]));
    }
  }
  return out;
}

/** Mean spacing of successive events (NaN with fewer than two): the period of a periodic series. */
export function meanPeriod(events: readonly number[]): number {
  if (events.length < 2) return NaN;
  return (events[events.length - 1] - events[0]) / (events.length - 1);
}
