import { describe, expect, it } from 'vitest';
import { TrajectoryRecord, bytesFor, capacityFor } from '../../../core/record.ts';

/** Deterministic PRNG (mulberry32) so failures reproduce. */
function rng(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** The obvious model of a bounded record: a plain array that shifts off the oldest row. */
class ArrayModel {
  rows: number[][] = [];
  dropped = 0;
  constructor(readonly capacity: number) {}
  push(row: number[]): void {
    this.rows.push(row);
    if (this.rows.length > this.capacity) {
      this.rows.shift();
      this.dropped++;
    }
  }
}

const COLS = ['t', 'q', 'p', 'H'] as const;

function expectSameAsModel(rec: TrajectoryRecord, model: ArrayModel): void {
  expect(rec.length).toBe(model.rows.length);
  expect(rec.dropped).toBe(model.dropped);
  const flat = model.rows.flat();
  expect(Array.from(rec.table().data)).toEqual(flat);
  for (let i = 0; i < model.rows.length; i++) {
    expect(rec.time(i)).toBe(model.rows[i][0]);
    for (let j = 0; j < rec.width; j++) expect(rec.get(i, j)).toBe(model.rows[i][j]);
  }
  for (let j = 0; j < rec.width; j++) {
    expect(Array.from(rec.column(j))).toEqual(model.rows.map((r) => r[j]));
  }
}

describe('new TrajectoryRecord(columns, capacity)', () => {
  it('new TrajectoryRecord(columns, capacity) rejects a capacity that is not a positive integer', () => {
    for (const bad of [0, -1, 1.5, NaN, Infinity, -Infinity]) {
      expect(() => new TrajectoryRecord(COLS, bad)).toThrow(/capacity must be a positive integer/);
    }
    expect(() => new TrajectoryRecord(COLS, '3' as unknown as number)).toThrow(/capacity/);
    expect(new TrajectoryRecord(COLS, 1).capacity).toBe(1);
  });

  it('new TrajectoryRecord(columns, capacity) requires column 0 to be "t" and unique, non-empty names', () => {
    expect(() => new TrajectoryRecord(['q', 't'], 4)).toThrow(/column 0 must be "t"/);
    expect(() => new TrajectoryRecord([], 4)).toThrow(/no columns/);
    expect(() => new TrajectoryRecord(['t', 'q', 'q'], 4)).toThrow(/duplicate column name "q"/);
    expect(() => new TrajectoryRecord(['t', ''], 4)).toThrow(/empty column name/);
  });

  it('new TrajectoryRecord(columns, capacity) exposes columns, width and capacity and starts empty', () => {
    const rec = new TrajectoryRecord(COLS, 5);
    expect(rec.columns).toEqual(COLS);
    expect(rec.width).toBe(4);
    expect(rec.capacity).toBe(5);
    expect(rec.length).toBe(0);
    expect(rec.dropped).toBe(0);
    expect(rec.dropped).toBe(0);
    expect(rec.columnIndex('p')).toBe(2);
    expect(rec.columnIndex('I')).toBe(-1);
  });
});

describe('capacityFor(bytes, width) / bytesFor(capacity, width)', () => {
  it('capacityFor(bytes, width) gives the most rows of 8-byte values that fit, at least 1', () => {
    expect(capacityFor(8 * 4 * 1000, 4)).toBe(1000);
    expect(capacityFor(8 * 4 * 1000 + 31, 4)).toBe(1000);
    expect(capacityFor(8 * 4 * 1000 - 1, 4)).toBe(999);
    expect(capacityFor(0, 4)).toBe(1);
    expect(bytesFor(capacityFor(64e6, 7), 7)).toBeLessThanOrEqual(64e6);
    expect(bytesFor(capacityFor(64e6, 7) + 1, 7)).toBeGreaterThan(64e6);
  });

  it('capacityFor(bytes, width) rejects a bad width or budget', () => {
    expect(() => capacityFor(1000, 0)).toThrow(/width/);
    expect(() => capacityFor(1000, 2.5)).toThrow(/width/);
    expect(() => capacityFor(-1, 3)).toThrow(/bytes/);
    expect(() => capacityFor(NaN, 3)).toThrow(/bytes/);
    expect(() => capacityFor(Infinity, 3)).toThrow(/bytes/);
  });
});

describe('record.push(values, offset?)', () => {
  it('record.push(values) drops the oldest row when full', () => {
    const rec = new TrajectoryRecord(['t', 'x'], 3);
    for (let k = 0; k < 3; k++) rec.push([k, 10 * k]);
    expect(rec.dropped).toBe(0);
    rec.push([3, 30]);
    expect(rec.length).toBe(3);
    expect(rec.dropped).toBe(1);
    expect(rec.dropped).toBe(1);
    expect(Array.from(rec.column('t'))).toEqual([1, 2, 3]);
    expect(Array.from(rec.column('x'))).toEqual([10, 20, 30]);
  });

  it('record.push(values) keeps time order across many wrap-arounds, like a plain-array model', () => {
    const random = rng(1);
    for (const capacity of [1, 2, 3, 7, 16]) {
      const rec = new TrajectoryRecord(COLS, capacity);
      const model = new ArrayModel(capacity);
      for (let k = 0; k < 5 * capacity + 3; k++) {
        const row = [k * 0.25, random() - 0.5, random() * 1e6, -random()];
        rec.push(row);
        model.push(row);
        expectSameAsModel(rec, model);
      }
    }
  });

  it('record.push(values, offset) copies width values starting at offset', () => {
    const rec = new TrajectoryRecord(['t', 'a', 'b'], 4);
    const src = new Float64Array([9, 9, 1, 2, 3, 9]);
    rec.push(src, 2);
    expect(Array.from(rec.table().data)).toEqual([1, 2, 3]);
    expect(() => rec.push(src, 4)).toThrow(RangeError);
    expect(() => rec.push([1, 2])).toThrow(/need 3 values/);
    expect(rec.length).toBe(1);
  });

  it('record.push(values) stores values bit-exactly, including -0, NaN and subnormals', () => {
    const rec = new TrajectoryRecord(['t', 'x'], 2);
    rec.push([-0, 5e-324]);
    rec.push([Number.MIN_VALUE * 3, NaN]);
    expect(Object.is(rec.get(0, 0), -0)).toBe(true);
    expect(rec.get(0, 1)).toBe(5e-324);
    expect(Number.isNaN(rec.get(1, 1))).toBe(true);
  });
});

describe('record.time(i) / record.get(i, column) / record.column(column, out?, from?, to?)', () => {
  it('record.get(i, column) rejects rows and columns that are not held', () => {
    const rec = new TrajectoryRecord(['t', 'x'], 3);
    rec.push([0, 1]);
    expect(() => rec.get(1, 0)).toThrow(RangeError);
    expect(() => rec.get(-1, 0)).toThrow(RangeError);
    expect(() => rec.get(0, 2)).toThrow(RangeError);
    expect(() => rec.time(0.5)).toThrow(RangeError);
  });

  it('record.column(column, out, from, to) writes rows [from, to) into out and returns it', () => {
    const rec = new TrajectoryRecord(['t', 'x'], 4);
    for (let k = 0; k < 6; k++) rec.push([k, k * k]); // holds t = 2..5
    const out = new Float64Array(10).fill(-1);
    expect(rec.column('x', out, 1, 3)).toBe(out);
    expect(Array.from(out.subarray(0, 3))).toEqual([9, 16, -1]);
    expect(Array.from(rec.column(0, undefined, 2))).toEqual([4, 5]);
    expect(() => rec.column('y')).toThrow(/no column named "y"/);
    expect(() => rec.column(0, new Float64Array(1))).toThrow(/out holds 1/);
    expect(() => rec.column(0, undefined, 3, 2)).toThrow(RangeError);
  });
});

describe('record.range(t0, t1)', () => {
  function linear(rec: TrajectoryRecord, t0: number, t1: number): [number, number] {
    const inside: number[] = [];
    for (let i = 0; i < rec.length; i++) if (t0 <= rec.time(i) && rec.time(i) <= t1) inside.push(i);
    return inside.length === 0 ? [-1, -1] : [inside[0], inside[inside.length - 1] + 1];
  }

  it('record.range(t0, t1) selects exactly the rows a linear scan finds, across wrap-around', () => {
    const random = rng(7);
    for (const capacity of [1, 2, 5, 13]) {
      const rec = new TrajectoryRecord(['t', 'x'], capacity);
      let t = random();
      for (let n = 0; n < 3 * capacity; n++) {
        // non-decreasing times, with some repeats
        t += random() < 0.2 ? 0 : random();
        rec.push([t, n]);
        const lo = rec.time(0) - 1;
        const hi = rec.time(rec.length - 1) + 1;
        const probes = [lo, hi, rec.time(0), rec.time(rec.length - 1)];
        for (let k = 0; k < 6; k++) probes.push(lo + random() * (hi - lo), rec.time(Math.floor(random() * rec.length)));
        for (const t0 of probes) {
          for (const t1 of probes) {
            const [from, to] = rec.range(t0, t1);
            const [a, b] = linear(rec, t0, t1);
            if (a === -1) expect(to - from).toBe(0);
            else expect([from, to]).toEqual([a, b]);
            expect(0 <= from && from <= to && to <= rec.length).toBe(true);
          }
        }
      }
    }
  });

  it('record.range(t0, t1) of an empty record is [0, 0]', () => {
    expect(new TrajectoryRecord(['t'], 3).range(-Infinity, Infinity)).toEqual([0, 0]);
  });
});

describe('record.table(from?, to?) / record.slices(from?, to?) / record.clear()', () => {
  it('record.table(from, to) is a detached contiguous copy of those rows', () => {
    const rec = new TrajectoryRecord(['t', 'x'], 3);
    for (let k = 0; k < 5; k++) rec.push([k, -k]); // holds t = 2, 3, 4 with the ring wrapped
    const table = rec.table(1, 3);
    expect(table.columns).toEqual(['t', 'x']);
    expect(table.rows).toBe(2);
    expect(Array.from(table.data)).toEqual([3, -3, 4, -4]);
    rec.push([5, -5]);
    expect(Array.from(table.data)).toEqual([3, -3, 4, -4]);
    expect(rec.table(2, 2).rows).toBe(0);
    expect(() => rec.table(2, 4)).toThrow(RangeError);
  });

  it('record.slices(from, to) covers the rows in time order in at most two runs', () => {
    for (let pushes = 0; pushes < 12; pushes++) {
      const rec = new TrajectoryRecord(['t', 'x'], 5);
      for (let k = 0; k < pushes; k++) rec.push([k, k + 0.5]);
      for (let from = 0; from <= rec.length; from++) {
        for (let to = from; to <= rec.length; to++) {
          const runs = rec.slices(from, to);
          expect(runs.length).toBeLessThanOrEqual(2);
          const joined = runs.flatMap((s) => Array.from(s.data.subarray(s.from * 2, s.to * 2)));
          expect(joined).toEqual(Array.from(rec.table(from, to).data));
        }
      }
    }
  });

  it('record.clear() forgets rows and the dropped count, and the record is reusable', () => {
    const rec = new TrajectoryRecord(['t', 'x'], 2);
    for (let k = 0; k < 5; k++) rec.push([k, k]);
    rec.clear();
    expect(rec.length).toBe(0);
    expect(rec.dropped).toBe(0);
    expect(rec.dropped).toBe(0);
    rec.push([10, 11]);
    expect(Array.from(rec.table().data)).toEqual([10, 11]);
  });
});
