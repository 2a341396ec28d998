import { describe, expect, it } from 'vitest';
import { makeMapping } from '../../../../widgets/plots/scale.ts';
import { emptyExtent } from '../../../../widgets/plots/extent.ts';
import { includeRows, liftPens, makePens, traceRows, type Stroke } from '../../../../widgets/plots/trace.ts';
import { recordingSink } from '../../support/fake-canvas.ts';

/** Rows of [t, x, y] laid out as the record stores them. */
function rows(points: [number, number][]): Float64Array {
  const data = new Float64Array(points.length * 3);
  points.forEach(([x, y], i) => data.set([i, x, y], 3 * i));
  return data;
}

const mx = makeMapping('linear', [0, 100], [0, 100]);
const my = makeMapping('linear', [0, 100], [100, 0]);
const stroke: Stroke = { minStep: 0.5, jumpX: 25, jumpY: 25 };

describe('trace', () => {
  it('traceRows(sink, …) starts a lifted pen with a dot and draws a line through the samples', () => {
    const { sink, calls } = recordingSink();
    const pens = makePens(1);
    traceRows(sink, rows([[10, 10], [20, 10], [20, 20]]), 3, 0, 3, 1, 2, mx, my, pens, 0, stroke);
    expect(calls).toEqual([
      ['moveTo', 10, 90],
      ['lineTo', 10, 90],
      ['lineTo', 20, 90],
      ['lineTo', 20, 80],
    ]);
    expect([pens.x[0], pens.y[0], pens.down[0]]).toEqual([20, 80, 1]);
  });

  it('traceRows(sink, …) continues from where the last call ended', () => {
    const { sink, calls } = recordingSink();
    const pens = makePens(1);
    const data = rows([[10, 10], [20, 10], [30, 10]]);
    traceRows(sink, data, 3, 0, 2, 1, 2, mx, my, pens, 0, stroke);
    calls.length = 0;
    traceRows(sink, data, 3, 2, 3, 1, 2, mx, my, pens, 0, stroke);
    expect(calls).toEqual([
      ['moveTo', 20, 90],
      ['lineTo', 30, 90],
    ]);
  });

  it('traceRows(sink, …) skips samples closer than minStep to the last drawn point, without drifting', () => {
    const { sink, calls } = recordingSink();
    const pens = makePens(1);
    const points: [number, number][] = [];
    for (let i = 0; i <= 100; i++) points.push([10 + i * 0.1, 10]);
    traceRows(sink, rows(points), 3, 0, points.length, 1, 2, mx, my, pens, 0, stroke);
    const lines = calls.filter((c) => c[0] === 'lineTo').slice(1);
    expect(lines.length).toBe(20);
    for (let i = 1; i < lines.length; i++) expect(lines[i][1] - lines[i - 1][1]).toBeCloseTo(0.5, 9);
  });

  it('traceRows(sink, …) breaks the line where the state jumps or is not finite', () => {
    const { sink, calls } = recordingSink();
    const pens = makePens(1);
    traceRows(sink, rows([[10, 10], [12, 10], [60, 10], [62, 10], [NaN, 10], [64, 10]]), 3, 0, 6, 1, 2, mx, my, pens, 0, stroke);
    expect(calls.map((c) => c[0])).toEqual(['moveTo', 'lineTo', 'lineTo', 'moveTo', 'lineTo', 'lineTo', 'moveTo', 'lineTo']);
    expect(calls[3]).toEqual(['moveTo', 60, 90]);
    expect(calls[6]).toEqual(['moveTo', 64, 90]);
  });

  it('traceRows(sink, …) tests jumps in data units, so a symlog axis’s stretch near zero is not one', () => {
    const { sink, calls } = recordingSink();
    const pens = makePens(1);
    const sy = makeMapping('symlog', [-1000, 1000], [400, 0]);
    traceRows(sink, rows([[10, -5], [10, 5]]), 3, 0, 2, 1, 2, mx, sy, pens, 0, { minStep: 0.5, jumpX: 500, jumpY: 500 });
    expect(calls.map((c) => c[0])).toEqual(['moveTo', 'lineTo', 'lineTo']);
  });

  it('liftPens(pens) makes the next sample start a new line', () => {
    const { sink, calls } = recordingSink();
    const pens = makePens(2);
    const data = rows([[10, 10], [20, 10]]);
    traceRows(sink, data, 3, 0, 1, 1, 2, mx, my, pens, 1, stroke);
    liftPens(pens);
    calls.length = 0;
    traceRows(sink, data, 3, 1, 2, 1, 2, mx, my, pens, 1, stroke);
    expect(calls[0]).toEqual(['moveTo', 20, 90]);
    expect(pens.down[0]).toBe(0);
  });

  it('includeRows(e, data, width, r0, r1, cx, cy) widens e to the rows’ points', () => {
    const e = emptyExtent();
    includeRows(e, rows([[1, 5], [-2, 7], [NaN, 100], [3, -1]]), 3, 0, 4, 1, 2);
    expect(e).toEqual({ x0: -2, x1: 3, y0: -1, y1: 7 });
  });
});
