/**
 * Which sides of a boundary polygon are split (core/ensemble/side-splits.ts),
 * against polygons whose side lengths and turning angles are known exactly:
 * the regular n-gon of circumradius 1 (sides 2 sin(π/n), a turn of 2π/n at
 * every vertex) and a rectangle (right-angle turns).
 */
import { describe, expect, test } from 'vitest';
import { markSplits } from '../../../../core/ensemble/side-splits.ts';

const regular = (n: number) => ({
  q: Float64Array.from({ length: n }, (_, i) => Math.cos((2 * Math.PI * i) / n)),
  p: Float64Array.from({ length: n }, (_, i) => Math.sin((2 * Math.PI * i) / n)),
});

describe('markSplits', () => {
  const n = 100;
  const side = 2 * Math.sin(Math.PI / n);
  const turn = (2 * Math.PI) / n;
  const { q, p } = regular(n);
  const split = new Uint8Array(n);

  test('the regular 100-gon: every side, or none, as its side 2 sin(π/n) and turn 2π/n compare with the limits', () => {
    expect(markSplits(q, p, n, { maxSegment: side * 1.01, maxTurn: turn * 1.01, scale: [1, 1] }, split)).toBe(0);
    expect(markSplits(q, p, n, { maxSegment: side * 0.99, maxTurn: turn * 1.01, scale: [1, 1] }, split)).toBe(n);
    expect(markSplits(q, p, n, { maxSegment: side * 1.01, maxTurn: turn * 0.99, scale: [1, 1] }, split)).toBe(n);
    expect([...split].every((v) => v === 1)).toBe(true);
  });

  test('lengths count in units of scale', () => {
    // In units of 2 along q and p, every side is half as long.
    expect(markSplits(q, p, n, { maxSegment: side * 0.51, maxTurn: 1, scale: [2, 2] }, split)).toBe(0);
    expect(markSplits(q, p, n, { maxSegment: side * 0.49, maxTurn: 1, scale: [2, 2] }, split)).toBe(n);
  });

  test('a rectangle 4 × 1: the long sides by length, all four by the right-angle turns', () => {
    const rq = [0, 4, 4, 0];
    const rp = [0, 0, 1, 1];
    const four = new Uint8Array(4);
    expect(markSplits(rq, rp, 4, { maxSegment: 2, maxTurn: 1.6, scale: [1, 1] }, four)).toBe(2);
    expect([...four]).toEqual([1, 0, 1, 0]);
    expect(markSplits(rq, rp, 4, { maxSegment: 5, maxTurn: 1.5, scale: [1, 1] }, four)).toBe(4);
  });

  test('a triangle with each side cut in ten: its three corners mark the two sides about each, the wrap included', () => {
    // Collinear cuts turn by 0; the corners (0, 0), (1, 0), (0, 1) by 3π/4, 3π/4 and π/2.
    const corners = [
      [0, 0],
      [1, 0],
      [0, 1],
    ];
    const tq: number[] = [];
    const tp: number[] = [];
    for (let c = 0; c < 3; c++) {
      const [a, b] = [corners[c], corners[(c + 1) % 3]];
      for (let j = 0; j < 10; j++) {
        tq.push(a[0] + ((b[0] - a[0]) * j) / 10);
        tp.push(a[1] + ((b[1] - a[1]) * j) / 10);
      }
    }
    const marks = new Uint8Array(30);
    expect(markSplits(tq, tp, 30, { maxSegment: 1, maxTurn: 0.5, scale: [1, 1] }, marks)).toBe(6);
    expect([...marks].flatMap((v, i) => (v ? [i] : []))).toEqual([0, 9, 10, 19, 20, 29]);
    // Above the sharpest turn, 3π/4, none counts.
    expect(markSplits(tq, tp, 30, { maxSegment: 1, maxTurn: 2.4, scale: [1, 1] }, marks)).toBe(0);
  });
});
