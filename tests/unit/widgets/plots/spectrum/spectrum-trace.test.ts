import { describe, expect, it } from 'vitest';
import { makeMapping } from '../../../../../widgets/plots/scale.ts';
import { traceSeries } from '../../../../../widgets/plots/spectrum/spectrum-plot.ts';
import { recordingSink } from '../../../support/fake-canvas.ts';

describe('spectrum-plot: traceSeries', () => {
  it('traceSeries(sink, x, y, end, mx, my) connects points a pixel or more apart one by one', () => {
    const { sink, calls } = recordingSink();
    const x = Float64Array.from([0, 1, 2, 3]);
    const y = Float64Array.from([0, 1, 0, 1]);
    const n = traceSeries(sink, x, y, 2, makeMapping('linear', [0, 3], [0, 300]), makeMapping('linear', [0, 1], [100, 0]));
    expect(calls).toEqual([
      ['moveTo', 0, 100],
      ['lineTo', 100, 0],
      ['lineTo', 200, 100],
    ]);
    expect(n).toBe(2);
  });

  it('traceSeries(sink, …) draws many points in one pixel column as first, range and last', () => {
    const { sink, calls } = recordingSink();
    const count = 10000;
    const x = Float64Array.from({ length: count }, (_, i) => i);
    const y = Float64Array.from({ length: count }, (_, i) => (i % 7 === 0 ? 1 : 0));
    const mx = makeMapping('linear', [0, count], [0, 100]);
    const my = makeMapping('linear', [0, 1], [100, 0]);
    traceSeries(sink, x, y, count - 1, mx, my);
    expect(calls.length).toBeLessThanOrEqual(4 * 100);
    const ys = new Set(calls.map((c) => c[2]));
    expect(ys).toEqual(new Set([0, 100]));
  });
});
