import { describe, expect, it } from 'vitest';
import { TrajectoryRecord } from '../../../../../core/record.ts';
import { chooseRows, gatherSamples, MIN_SAMPLES } from '../../../../../widgets/plots/spectrum/spectrum-rows.ts';

/** A record of t, x = 10·i (row number i), sampled every 0.01, holding at most `capacity` rows. */
function record(rows: number, capacity = rows): TrajectoryRecord {
  const r = new TrajectoryRecord(['t', 'x'], capacity);
  for (let i = 0; i < rows; i++) r.push([i * 0.01, 10 * i]);
  return r;
}

describe('spectrum-rows', () => {
  it('chooseRows(rows, undefined, max) takes the whole record with the record’s spacing', () => {
    const c = chooseRows(record(1000), undefined, 1 << 15)!;
    expect(c).toMatchObject({ from: 0, to: 1000, stride: 1, samples: 1000 });
    expect(c.interval).toBeCloseTo(0.01, 12);
    expect(c.duration).toBeCloseTo(10, 9);
  });

  it('chooseRows(rows, span, max) takes the latest span time units', () => {
    const c = chooseRows(record(1000), 2, 1 << 15)!;
    expect(c.to).toBe(1000);
    expect(c.from).toBe(799);
    expect(c.samples).toBe(201);
  });

  it('chooseRows(rows, [t0, t1], max) takes the rows with t0 ≤ t ≤ t1', () => {
    const c = chooseRows(record(1000), [1, 3], 1 << 15)!;
    expect([c.from, c.to]).toEqual([100, 301]);
  });

  it('chooseRows(rows, span, max) thins to at most max samples by whole blocks aligned to the newest row', () => {
    const c = chooseRows(record(1000), undefined, 300)!;
    expect(c.stride).toBe(4);
    expect(c.samples).toBe(250);
    expect(c.to).toBe(1000);
    expect(c.from).toBe(0);
    expect(c.interval).toBeCloseTo(0.04, 12);
    const odd = chooseRows(record(1001), undefined, 300)!;
    expect(odd.from).toBe(1);
  });

  it(`chooseRows(rows, …) is null with fewer than ${MIN_SAMPLES} samples: the 'not enough samples yet' state`, () => {
    expect(chooseRows(record(MIN_SAMPLES - 1), undefined, 1 << 15)).toBeNull();
    expect(chooseRows(record(1000), 0.5, 1 << 15)).toBeNull();
    expect(chooseRows(record(MIN_SAMPLES), undefined, 1 << 15)).not.toBeNull();
  });

  it('gatherSamples(record, column, choice, out) copies the rows, or their block means, across the ring’s wrap', () => {
    const r = record(1500, 1000);
    expect(r.dropped).toBe(500);
    const all = chooseRows(r, undefined, 1 << 15)!;
    const out = new Float64Array(2000);
    const x = gatherSamples(r, 1, all, out);
    expect(x.length).toBe(1000);
    expect(x[0]).toBe(5000);
    expect(x[999]).toBe(14990);
    const thin = chooseRows(r, undefined, 250)!;
    const means = gatherSamples(r, 1, thin, out);
    expect(thin.stride).toBe(4);
    expect(means.length).toBe(250);
    expect(means[0]).toBeCloseTo(10 * (500 + 1.5), 9);
    expect(means[249]).toBeCloseTo(10 * (1496 + 1.5), 9);
  });
});
