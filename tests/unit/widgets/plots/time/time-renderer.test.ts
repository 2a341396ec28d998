import { describe, expect, it } from 'vitest';
import { TrajectoryRecord } from '../../../../../core/record.ts';
import { TimeRenderer } from '../../../../../widgets/plots/time/time-renderer.ts';
import { fakeFactory, FakeContext, type FakeSurface } from '../../../support/fake-canvas.ts';

/** A record of q = sin t, p = cos t sampled every dt, from t0 to t1. */
function push(record: TrajectoryRecord, t0: number, t1: number, dt: number, amplitude = 1): void {
  for (let k = Math.round(t0 / dt); k * dt <= t1 + 1e-12; k++) {
    const t = k * dt;
    record.push([t, amplitude * Math.sin(t), amplitude * Math.cos(t)]);
  }
}

function setup(window = 10, width = 200): { renderer: TimeRenderer; record: TrajectoryRecord; tiles: FakeSurface[] } {
  const { create, made } = fakeFactory();
  const renderer = new TimeRenderer(create, window);
  renderer.resize(width, 100, 1.5);
  renderer.setSeries([1, 2], ['red', 'blue']);
  const record = new TrajectoryRecord(['t', 'q', 'p'], 100_000);
  renderer.reset(0);
  return { renderer, record, tiles: made.slice(-3) };
}

const segments = (tiles: FakeSurface[]): number => tiles.reduce((n, s) => n + s.context.named('lineTo').length, 0);
const reset = (tiles: FakeSurface[]): void => tiles.forEach((s) => (s.context.calls = []));

describe('plots/time-renderer', () => {
  it('TimeRenderer.update(record) fits the y range to the first samples', () => {
    const { renderer, record } = setup();
    push(record, 0, 0.5, 0.01);
    expect(renderer.update(record)).toBe('rescaled');
    expect(renderer.domain[0]).toBeLessThanOrEqual(0);
    expect(renderer.domain[1]).toBeGreaterThanOrEqual(1);
    expect(renderer.update(record)).toBe('none');
  });

  it('TimeRenderer.update(record) draws only what is new: work per frame follows the new samples', () => {
    const { renderer, record, tiles } = setup(10, 200); // 20 px per time unit
    push(record, 0, 7, 0.001, 1); // a full period, so the range already fits
    renderer.update(record);
    for (let frame = 1; frame <= 20; frame++) {
      reset(tiles);
      push(record, 7 + (frame - 1) * 0.05 + 0.001, 7 + frame * 0.05, 0.001); // 50 samples, 1 column
      expect(renderer.update(record)).toBe('drawn');
      // two series, a column or two each: a handful of segments, not 50 per series
      expect(segments(tiles)).toBeLessThanOrEqual(2 * 2 * 4 + 4);
      expect(segments(tiles)).toBeGreaterThan(0);
    }
  });

  it('TimeRenderer.update(record) grows the range and redraws everything when a value leaves it', () => {
    const { renderer, record, tiles } = setup();
    push(record, 0, 3, 0.01, 1);
    renderer.update(record);
    const before = renderer.domain;
    reset(tiles);
    record.push([3.01, 50, 0]);
    expect(renderer.update(record)).toBe('rescaled');
    expect(renderer.domain[1]).toBeGreaterThanOrEqual(50);
    expect(renderer.domain).not.toEqual(before);
    expect(tiles.some((s) => s.context.named('clearRect').length > 0)).toBe(true);
  });

  it('TimeRenderer.update(record) skips samples that scrolled out of view before they were drawn', () => {
    const { renderer, record, tiles } = setup(10, 200);
    push(record, 0, 0.1, 0.01);
    renderer.update(record);
    reset(tiles);
    push(record, 0.11, 1000, 0.01); // 100 000 samples at once: 100 views' worth
    renderer.update(record);
    // only about one view width of columns is drawn, per series (at most 4 segments per column)
    expect(segments(tiles)).toBeLessThan(2 * (200 + 20) * 4);
    expect(segments(tiles)).toBeGreaterThan(2 * 200);
    expect(renderer.end).toBe(renderer.columnOf(1000) + 1);
  });

  it('TimeRenderer: a stroke near a tile boundary is drawn into both tiles', () => {
    const { renderer, record, tiles } = setup(10, 200);
    push(record, 0, 9.9, 0.01); // up to column 198 of tile 0
    renderer.update(record);
    reset(tiles);
    push(record, 9.91, 10.05, 0.01); // across column 200
    renderer.update(record);
    expect(tiles.filter((s) => s.context.named('stroke').length > 0)).toHaveLength(2);
  });

  it('TimeRenderer.renderWindow(target, record, end) draws the window’s rows from the record', () => {
    const { renderer, record } = setup(10, 200);
    push(record, 0, 100, 0.01, 1);
    renderer.update(record);
    const target = new FakeContext();
    const end = renderer.columnOf(30);
    renderer.renderWindow(target.ctx, record, end);
    const xs = target.calls.filter((c) => c[0] === 'lineTo').map((c) => c[1] as number);
    expect(Math.min(...xs)).toBeGreaterThan(-10);
    expect(Math.max(...xs)).toBeLessThan(210);
    expect(xs.length).toBeGreaterThan(200);
  });

  it('TimeRenderer.fitWindow(record, t0, t1) fits the range to the rows in [t0, t1] only', () => {
    const { renderer, record } = setup();
    push(record, 0, 5, 0.01, 100);
    push(record, 5.01, 10, 0.01, 1);
    renderer.update(record);
    renderer.fitWindow(record, 6, 10);
    expect(renderer.domain[1]).toBeLessThan(2);
    expect(renderer.domain[0]).toBeGreaterThan(-2);
  });

  it('TimeRenderer hugs the data again once a whole window has passed without growth', () => {
    const { renderer, record } = setup(10, 200);
    record.push([0, 1, 0]);
    renderer.update(record); // the first sample alone: a narrow range around q = 1
    // a cosine of amplitude 1, fed a frame at a time: the range grows, with headroom, as q swings down
    let t = 0;
    const frame = (): string => {
      for (let k = 0; k < 10; k++) {
        t += 0.005;
        record.push([t, Math.cos(t), -Math.sin(t)]);
      }
      return renderer.update(record);
    };
    while (t < 4) frame();
    const grown = renderer.domain;
    expect(grown[1] - grown[0]).toBeGreaterThan(2.5);
    // nothing new leaves the range: after a window (10 time units) it is fitted to what is in view
    while (t < 16) frame();
    const [a, b] = renderer.domain;
    expect(a).toBeLessThanOrEqual(-1);
    expect(b).toBeGreaterThanOrEqual(1);
    expect(b - a).toBeLessThanOrEqual(2.4);
    // and then left alone
    while (t < 30) expect(frame()).not.toBe('rescaled');
  });

  it('TimeRenderer never shrinks a range that keeps growing (exponential growth)', () => {
    const { renderer, record } = setup(10, 200);
    let span = 0;
    for (let t = 0; t < 40; t += 0.05) {
      record.push([t, Math.exp(0.3 * t) * Math.cos(3 * t), 0]);
      renderer.update(record);
      const now = renderer.domain[1] - renderer.domain[0];
      expect(now).toBeGreaterThanOrEqual(span);
      span = now;
    }
  });
});
