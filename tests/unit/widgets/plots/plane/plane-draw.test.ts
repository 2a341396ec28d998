import { describe, expect, it } from 'vitest';
import { TrajectoryRecord } from '../../../../../core/record.ts';
import { toPixel } from '../../../../../widgets/plots/scale.ts';
import { defaultLook, drawDots, fadeLayer, rescaleImage, strokeRows, type LineStyle } from '../../../../../widgets/plots/plane/plane-draw.ts';
import { makePanel, placePanel, type Panel } from '../../../../../widgets/plots/plane/plane-panels.ts';
import { fakeContext } from '../../../support/fake-canvas.ts';

/** Two bodies circling the origin, sampled 100 times. */
function circling(): TrajectoryRecord {
  const record = new TrajectoryRecord(['t', 'x0', 'y0', 'x1', 'y1'], 1000);
  for (let i = 0; i < 100; i++) {
    const a = (2 * Math.PI * i) / 100;
    record.push([i * 0.01, Math.cos(a), Math.sin(a), -2 * Math.cos(a), -2 * Math.sin(a)]);
  }
  return record;
}

function panel(): Panel {
  const p = makePanel({
    tracks: [
      { x: 1, y: 2, group: 0 },
      { x: 3, y: 4, group: 1 },
    ],
    xLabel: 'x',
    yLabel: 'y',
    legend: [],
    xKind: 'linear',
    yKind: 'linear',
    constant: 1,
    equal: true,
    extent: { x0: -2.5, x1: 2.5, y0: -2.5, y1: 2.5 },
  });
  placePanel(p, { left: 50, top: 20, width: 300, height: 300 });
  return p;
}

const style: LineStyle = { lineWidth: 1.5, lineOpacity: 1, jump: 0.25, color: (g) => ['red', 'blue'][g] };

describe('plane-draw', () => {
  it('strokeRows(g, record, panels, from, to, opacity, style) strokes one path per colour group, clipped to the panel', () => {
    const { context, calls } = fakeContext();
    const p = panel();
    strokeRows(context, circling(), [p], 0, 100, 0.5, style);
    expect(calls.filter((c) => c.name === 'stroke').length).toBe(2);
    expect(calls.filter((c) => c.name === 'clip').length).toBe(1);
    expect(calls.find((c) => c.name === 'rect')!.args).toEqual([50, 20, 300, 300]);
    const colours = calls.filter((c) => c.name === 'set strokeStyle').map((c) => c.args[0]);
    expect(colours).toEqual(['red', 'blue']);
    expect(calls.find((c) => c.name === 'set globalAlpha')!.args[0]).toBe(0.5);
    const lines = calls.filter((c) => c.name === 'lineTo').length;
    expect(lines).toBeGreaterThan(150);
    expect(lines).toBeLessThanOrEqual(202);
    expect(p.pens.down[0]).toBe(1);
  });

  it('strokeRows(…) in two calls draws the same line as in one, joined where the first ended', () => {
    const whole = fakeContext();
    const split = fakeContext();
    strokeRows(whole.context, circling(), [panel()], 0, 100, 1, style);
    const p = panel();
    strokeRows(split.context, circling(), [p], 0, 50, 1, style);
    strokeRows(split.context, circling(), [p], 50, 100, 1, style);
    const ends = (calls: typeof whole.calls) => calls.filter((c) => c.name === 'lineTo').map((c) => c.args.map((v) => Math.round(Number(v) * 1e6)).join());
    expect(new Set(ends(split.calls))).toEqual(new Set(ends(whole.calls)));
  });

  it('fadeLayer(g, alpha, w, h) fills the layer with destination-out at that alpha', () => {
    const { context, calls } = fakeContext();
    fadeLayer(context, 0.25, 700, 400);
    expect(calls.map((c) => c.name)).toEqual(['save', 'set globalCompositeOperation', 'set fillStyle', 'fillRect', 'restore']);
    expect(calls[1].args[0]).toBe('destination-out');
    expect(calls[2].args[0]).toBe('rgba(0,0,0,0.25)');
  });

  it('rescaleImage(g, image, panels, before, w, h, dpr) maps each panel’s own old picture and the pens onto the new mapping', () => {
    const p = panel();
    const before = [{ mx: p.mx, my: p.my }];
    p.pens.x[0] = toPixel(p.mx, 1);
    p.pens.y[0] = toPixel(p.my, 0.5);
    p.fitted = { x0: -5, x1: 5, y0: -5, y1: 5 };
    // a fixed extent is what placePanel shows; widen it as growth would
    (p.spec as { extent?: object }).extent = p.fitted;
    placePanel(p, p.rect);
    const { context, calls } = fakeContext();
    rescaleImage(context, {} as CanvasImageSource, [p], before, 400, 340, 2);
    const t = calls.find((c) => c.name === 'transform')!.args as number[];
    expect(calls.find((c) => c.name === 'drawImage')!.args.slice(1)).toEqual([100, 40, 600, 600, 50, 20, 300, 300]);
    expect(t[0]).toBeCloseTo(0.5, 12);
    expect(t[3]).toBeCloseTo(0.5, 12);
    expect(p.pens.x[0]).toBeCloseTo(toPixel(p.mx, 1), 9);
    expect(p.pens.y[0]).toBeCloseTo(toPixel(p.my, 0.5), 9);
  });

  it('drawDots(g, record, row, panels, r, color, ring) puts one dot per track at its state in that row', () => {
    const { context, calls } = fakeContext();
    const p = panel();
    drawDots(context, circling(), 25, [p], 4, style.color, 'white');
    const arcs = calls.filter((c) => c.name === 'arc').map((c) => c.args.slice(0, 2) as number[]);
    expect(arcs.length).toBe(2);
    expect(arcs[0][0]).toBeCloseTo(toPixel(p.mx, Math.cos(Math.PI / 2)), 9);
    expect(arcs[0][1]).toBeCloseTo(toPixel(p.my, 1), 9);
    expect(arcs[1][1]).toBeCloseTo(toPixel(p.my, -2), 9);
    expect(calls.filter((c) => c.name === 'set strokeStyle').map((c) => c.args[0])).toEqual(['white', 'white']);
  });

  it('defaultLook(tracks) thins lines and dots for large batches', () => {
    expect(defaultLook(2)).toEqual({ radius: 4, lineWidth: 1.5, lineOpacity: 1 });
    expect(defaultLook(1000).radius).toBeLessThan(2);
    expect(defaultLook(1000).lineOpacity).toBeLessThan(1);
  });
});
