import { describe, expect, it } from 'vitest';
import { BEHIND, isBehind, PaceMeter, WARM_UP_MS, WINDOW_MS } from '../../../../widgets/simulator/pace.ts';

const FRAME_MS = 1000 / 60;

/** Frames of 1/60 s from `from` ms for `ms`, each asked 10 steps and taking `share(now)` of them; returns the time after the last. */
function run(meter: PaceMeter, from: number, ms: number, share: (now: number) => number): number {
  let now = from;
  for (; now < from + ms; now += FRAME_MS) meter.frame(now, 10, 10 * share(now));
  return now;
}

describe('PaceMeter', () => {
  it('says nothing until a whole window after the warm-up has been seen, however slow the start', () => {
    const meter = new PaceMeter();
    // A start-up that integrates nothing at all: the JIT, a loading page, a busy machine.
    const end = run(meter, 0, WARM_UP_MS + WINDOW_MS - 3 * FRAME_MS, () => 0);
    expect(meter.pace).toBeNull();
    expect(isBehind(meter.pace)).toBe(false);
    run(meter, end, 4 * FRAME_MS, () => 0);
    expect(meter.pace).toBe(0); // now judged: a model that never moves is behind
    expect(isBehind(meter.pace)).toBe(true);
  });

  it('does not count the warm-up against a run that then keeps up', () => {
    const meter = new PaceMeter();
    const end = run(meter, 0, WARM_UP_MS, () => 0.3);
    run(meter, end, WINDOW_MS + 100, () => 1);
    expect(meter.pace).toBe(1);
    expect(isBehind(meter.pace)).toBe(false);
  });

  it('judges the last window only: a run that slows down is behind once the window holds the slow part', () => {
    const meter = new PaceMeter();
    let now = run(meter, 0, WARM_UP_MS + WINDOW_MS + 100, () => 1);
    expect(meter.pace).toBe(1);
    now = run(meter, now, WINDOW_MS / 2, () => 0.5);
    expect(meter.pace).toBeGreaterThan(0.7);
    expect(meter.pace).toBeLessThan(0.8);
    run(meter, now, WINDOW_MS, () => 0.5);
    expect(meter.pace).toBeCloseTo(0.5, 6);
    expect(isBehind(meter.pace)).toBe(true);
  });

  it('starts afresh after reset (a new speed): the old run’s verdict is dropped and a new warm-up begins', () => {
    const meter = new PaceMeter();
    const end = run(meter, 0, WARM_UP_MS + WINDOW_MS + 100, () => 0.2);
    expect(isBehind(meter.pace)).toBe(true);
    meter.reset();
    run(meter, end, WARM_UP_MS, () => 0.2);
    expect(meter.pace).toBeNull();
  });

  it('takes frames that did more than their share (a carried backlog) as at most keeping up', () => {
    const meter = new PaceMeter();
    run(meter, 0, WARM_UP_MS + WINDOW_MS + 100, (now) => (Math.floor(now / FRAME_MS) % 2 ? 2 : 0.5));
    expect(meter.pace).toBe(1);
  });

  it('ignores a frame with no sensible counts instead of letting it poison the verdict', () => {
    const meter = new PaceMeter();
    const end = run(meter, 0, WARM_UP_MS + WINDOW_MS + 100, () => 1);
    meter.frame(end, NaN, 5);
    meter.frame(end + FRAME_MS, 10, -1);
    expect(meter.pace).toBe(1);
  });

  it('calls a run behind below 90% of real time, and a run not yet judged never', () => {
    expect(BEHIND).toBe(0.9);
    expect([null, 0.95, 0.9, 0.89, 0].map(isBehind)).toEqual([false, false, false, true, true]);
  });
});
