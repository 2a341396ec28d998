/**
 * Orbits of a map as arrays and as a TrajectoryRecord
 * (core/maps/map-iteration.ts): their shape, with the start included and t
 * the iterate; their values against the free rotor's closed form at K = 0
 * (q_n = q_0 + n·p_0 mod 2π) and against the standard map stepped by hand;
 * p reduced into [−π, π) differing from the unreduced p by whole turns; and
 * the record through the CSV export.
 */
import { describe, expect, test } from 'vitest';
import { TWO_PI } from '../../../../core/maps/area-preserving-map.ts';
import { iterateMap, mapRecord } from '../../../../core/maps/map-iteration.ts';
import { standardMap } from '../../../../core/maps/standard-map.ts';
import { toCSV } from '../../../../core/tables/csv.ts';

const angleGap = (a: number, b: number) => {
  const d = Math.abs(a - b) % TWO_PI;
  return Math.min(d, TWO_PI - d);
};

describe('iterateMap', () => {
  test('iterations + 1 points, the start first, each the step of the one before', () => {
    const map = standardMap(1.3);
    const { q, p } = iterateMap(map, [1, 0.5], 50);
    expect(q.length).toBe(51);
    expect(p.length).toBe(51);
    expect([q[0], p[0]]).toEqual([1, 0.5]);
    // by hand: p' = p + K sin q, q' = q + p'
    let [qq, pp] = [1, 0.5];
    for (let n = 1; n <= 50; n++) {
      pp += 1.3 * Math.sin(qq);
      qq += pp;
      expect(angleGap(q[n], qq)).toBeLessThan(1e-9);
      expect(p[n]).toBeCloseTo(pp, 9);
    }
  });

  test('zero iterations give the start alone', () => {
    const { q, p } = iterateMap(standardMap(2), [4, -1], 0);
    expect(Array.from(q)).toEqual([4]);
    expect(Array.from(p)).toEqual([-1]);
  });

  test('at K = 0 the orbit is the free rotor’s, q_n = q_0 + n·p_0 mod 2π', () => {
    const { q, p } = iterateMap(standardMap(0), [0.2, 1.1], 300);
    for (let n = 0; n <= 300; n++) {
      expect(p[n]).toBe(1.1);
      expect(angleGap(q[n], 0.2 + n * 1.1)).toBeLessThan(1e-11);
    }
  });

  test('with reduceP, p lies in [−π, π) and differs from the unreduced p by whole turns; the orbit itself is unchanged', () => {
    const map = standardMap(3);
    const plain = iterateMap(map, [0.4, 0.1], 2000);
    const reduced = iterateMap(map, [0.4, 0.1], 2000, { reduceP: true });
    let left = false;
    for (let n = 0; n <= 2000; n++) {
      expect(reduced.p[n] >= -Math.PI && reduced.p[n] < Math.PI).toBe(true);
      const turns = (plain.p[n] - reduced.p[n]) / TWO_PI;
      expect(Math.abs(turns - Math.round(turns))).toBeLessThan(1e-9);
      expect(reduced.q[n]).toBe(plain.q[n]);
      if (Math.abs(plain.p[n]) > Math.PI) left = true;
    }
    // at K = 3 the orbit wanders in p, so the reduction was exercised
    expect(left).toBe(true);
  });

  test('a number of iterations that is not a whole number from 0 to 10⁷ is refused', () => {
    const map = standardMap(1);
    for (const n of [-1, 1.5, NaN, Infinity, 10_000_001]) expect(() => iterateMap(map, [0, 0], n)).toThrow(RangeError);
    expect(() => mapRecord(map, [0, 0], -2)).toThrow(/whole number from 0 to 10000000/);
  });
});

describe('mapRecord', () => {
  test('columns t, q, p; t is the iterate n; q and p are iterateMap’s', () => {
    const map = standardMap(0.8);
    const record = mapRecord(map, [2, 0.3], 40);
    const { q, p } = iterateMap(map, [2, 0.3], 40);
    expect(record.columns).toEqual(['t', 'q', 'p']);
    expect(record.length).toBe(41);
    expect(record.dropped).toBe(0);
    expect(Array.from(record.column('t'))).toEqual(Array.from({ length: 41 }, (_, n) => n));
    expect(Array.from(record.column('q'))).toEqual(Array.from(q));
    expect(Array.from(record.column('p'))).toEqual(Array.from(p));
  });

  test('goes through the CSV export: a header and one line per iterate', () => {
    const csv = toCSV(mapRecord(standardMap(0), [1, 0.5], 3).table());
    const lines = csv.trim().split('\n');
    expect(lines[0]).toBe('t,q,p');
    expect(lines.length).toBe(5);
    expect(lines[1]).toBe('0,1,0.5');
    expect(lines[2]).toBe('1,1.5,0.5');
  });
});
