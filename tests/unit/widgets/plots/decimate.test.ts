import { describe, expect, it } from 'vitest';
import { ColumnDecimator, strokeColumns } from '../../../../widgets/plots/decimate.ts';
import { FakeContext } from '../../support/fake-canvas.ts';

/** A decimator whose sink strokes every series into `ctx` at offset 0. */
function setup(series: number, capacity = 64): { d: ColumnDecimator; ctx: FakeContext; flushes: number[] } {
  const ctx = new FakeContext();
  const flushes: number[] = [];
  const d = new ColumnDecimator(series, capacity, (dec) => {
    flushes.push(dec.count);
    for (let s = 0; s < dec.series; s++) strokeColumns(ctx.ctx, dec, s, 0);
  });
  return { d, ctx, flushes };
}

describe('plots/decimate', () => {
  it('ColumnDecimator: many samples in one column become one vertical stroke from min to max', () => {
    const { d, ctx } = setup(1);
    d.column(0);
    d.value(0, 10);
    d.column(1);
    for (const y of [5, 9, 1, 7, 3]) {
      d.column(1);
      d.value(0, y);
    }
    d.end();
    const path = ctx.calls.filter((c) => c[0] === 'moveTo' || c[0] === 'lineTo').map((c) => `${c[0]} ${c[1]} ${c[2]}`);
    // column 0 alone, then column 1: join to first (5), down to min (1), up to max (9), to last (3)
    expect(path).toEqual(['moveTo 0.5 10', 'lineTo 1.5 5', 'lineTo 1.5 1', 'lineTo 1.5 9', 'lineTo 1.5 3']);
  });

  it('ColumnDecimator: drawing calls grow with columns, not with samples', () => {
    const count = (samplesPerColumn: number): number => {
      const { d, ctx } = setup(2);
      for (let i = 0; i < 100 * samplesPerColumn; i++) {
        d.column(Math.floor(i / samplesPerColumn));
        d.value(0, Math.sin(i));
        d.value(1, Math.cos(i));
      }
      d.end();
      return ctx.named('lineTo').length;
    };
    expect(count(1000)).toBeLessThanOrEqual(2 * 100 * 4);
    expect(count(100000)).toBeLessThanOrEqual(2 * 100 * 4);
    expect(count(10)).toBeGreaterThan(2 * 100); // at least one segment per column and series
  });

  it('ColumnDecimator: a full queue flushes early and the next batch joins onto the last point', () => {
    const { d, ctx, flushes } = setup(1, 4);
    for (let c = 0; c < 10; c++) {
      d.column(c);
      d.value(0, c * 2);
    }
    d.end();
    expect(flushes).toEqual([4, 4, 2]);
    const moves = ctx.named('moveTo');
    expect(moves[1]).toEqual(['moveTo', 3.5, 6]); // the second stroke starts at the first one's last point
    expect(ctx.named('stroke')).toHaveLength(3);
  });

  it('ColumnDecimator: non-finite values leave a gap, and penUp() stops the join', () => {
    const { d, ctx } = setup(1);
    const ys = [1, 2, NaN, Infinity, 5, 6];
    ys.forEach((y, c) => {
      d.column(c);
      d.value(0, y);
    });
    d.end();
    const path = ctx.calls.filter((c) => c[0] === 'moveTo' || c[0] === 'lineTo').map((c) => c[0]);
    expect(path).toEqual(['moveTo', 'lineTo', 'moveTo', 'lineTo']);
    d.penUp();
    d.column(6);
    d.value(0, 7);
    d.end();
    // a lone point after the pen was lifted: moveTo and a 1-pixel dash
    expect(ctx.calls.slice(-3).map((c) => c.slice(0, 3))).toEqual([['moveTo', 6.5, 7], ['lineTo', 7.5, 7], ['stroke', '#000', 1]]);
  });

  it('ColumnDecimator: values beyond ±limit are clamped so the canvas never sees huge coordinates', () => {
    const { d, ctx } = setup(1);
    d.column(0);
    d.value(0, 1e300);
    d.column(1);
    d.value(0, -1e300);
    d.end();
    for (const [, , y] of ctx.calls.filter((c) => c[0] === 'lineTo' || c[0] === 'moveTo')) expect(Math.abs(y as number)).toBeLessThanOrEqual(1e5);
  });

  it('strokeColumns(ctx, d, s, offset) shifts x by the offset, at pixel centres', () => {
    const { d, ctx } = setup(1);
    const strokes: number[] = [];
    const d2 = new ColumnDecimator(1, 8, (dec) => {
      strokeColumns(ctx.ctx, dec, 0, 1000);
      strokes.push(dec.count);
    });
    d2.column(1003);
    d2.value(0, 4);
    d2.column(1004);
    d2.value(0, 5);
    d2.end();
    expect(ctx.named('moveTo')[0]).toEqual(['moveTo', 3.5, 4]);
    expect(ctx.named('lineTo')[0]).toEqual(['lineTo', 4.5, 5]);
    void d;
  });
});
