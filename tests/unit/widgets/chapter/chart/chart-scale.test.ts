import { describe, expect, it } from 'vitest';
import { resolveChart } from '../../../../../widgets/chapter/chart/chart-options.ts';
import { axisMapping, fitDomain, layoutChart, samplePoints, settleChart, tickCount } from '../../../../../widgets/chapter/chart/chart-scale.ts';

describe('fitDomain', () => {
  it('hugs the data, rounded out to ticks', () => {
    expect(fitDomain([-3.2, 7.9], 'linear')).toEqual([-4, 8]);
  });
  it('keeps zero as the floor of values that are never negative, when zero is near', () => {
    expect(fitDomain([0.5, 9.7], 'linear')).toEqual([0, 10]);
    expect(fitDomain([-9.7, -0.5], 'linear')).toEqual([-10, 0]);
    // a positive quantity far from zero is not squashed against it
    expect(fitDomain([99, 101], 'linear')[0]).toBeGreaterThan(90);
  });
  it('gives a log axis whole decades around its positive values, ignoring the rest', () => {
    expect(fitDomain([3e-9, 0, -1, 0.2], 'log')).toEqual([1e-9, 1]);
    expect(fitDomain([5, 5], 'log')).toEqual([1, 10]);
    expect(fitDomain([10, 10], 'log')).toEqual([10, 100]);
  });
  it('has an interval to show when there is nothing or one value', () => {
    expect(fitDomain([], 'linear')).toEqual([0, 1]);
    expect(fitDomain([NaN], 'log')).toEqual([1, 10]);
    const [a, b] = fitDomain([-5, -5], 'linear');
    expect(a).toBeLessThan(-5);
    expect(b).toBeGreaterThan(-5);
  });
});

describe('formula curves', () => {
  it('are sampled across the x axis, evenly or evenly in log, at the formula\'s own values', () => {
    const c = settleChart(resolveChart({ label: 'L', x: { domain: [0.01, 100], scale: 'log' }, series: [{ formula: (x: number) => 1 / x, samples: 5 }] }));
    const curve = c.series[0].curves[0];
    expect(Array.from(curve.x).map((v) => Number(v.toPrecision(12)))).toEqual([0.01, 0.1, 1, 10, 100]);
    curve.x.forEach((x, i) => expect(curve.y[i]).toBe(1 / x));
  });
  it('take their range from the data when the axis has none, and from/to when given', () => {
    const c = settleChart(resolveChart({ label: 'L', series: [{ points: [[2, 0], [6, 1]] }, { formula: (x: number) => x * x, from: 3, samples: 3 }] }));
    expect(Array.from(c.series[1].curves[0].x)).toEqual([3, 4.5, 6]);
    expect(Array.from(c.series[1].curves[0].y)).toEqual([9, 20.25, 36]);
  });
  it('break where the formula throws or is not finite, without failing the chart', () => {
    const c = settleChart(resolveChart({ label: 'L', x: { domain: [-1, 1] }, series: [{ formula: (x: number) => { if (x > 0.5) throw new Error('no'); return 1 / x; }, samples: 5 }] }));
    expect(Array.from(c.series[0].curves[0].y)).toEqual([-1, -2, NaN, 2, NaN]);
  });
  it('need somewhere to be drawn', () => {
    expect(() => settleChart(resolveChart({ label: 'L', series: [{ formula: Math.sin }] }))).toThrow(/needs the x axis's domain/);
  });
  it('fill a band whose edges are functions', () => {
    const c = settleChart(resolveChart({ label: 'L', x: { domain: [0, 2] }, series: [{ lower: (x: number) => x, upper: (x: number) => 2 * x, samples: 3 }] }));
    expect(c.series[0].curves.map((k) => Array.from(k.y))).toEqual([
      [0, 1, 2],
      [0, 2, 4],
    ]);
  });
  it('samplePoints ends exactly at its end', () => {
    expect(samplePoints(1e-11, 3, 7, true)[6]).toBe(3);
  });
});

describe('axes', () => {
  it('a log axis labels every decade when they fit, with the foundation\'s labels', () => {
    const axis = { label: 'y', scale: 'log' as const, domain: null, ticks: null };
    const count = tickCount(axis, [1e-11, 3], 266, 20);
    expect(count).toBe(11);
    const m = axisMapping(axis, [1e-11, 3], [278, 12]);
    const labels = m.scale.ticks(count).map(m.scale.tickFormat(count)).filter(Boolean);
    expect(labels).toEqual(['10⁻¹¹', '10⁻¹⁰', '10⁻⁹', '10⁻⁸', '10⁻⁷', '10⁻⁶', '10⁻⁵', '10⁻⁴', '0.001', '0.01', '0.1', '1']);
    // and maps a decade to equal lengths
    expect(m.scale(1e-11) - m.scale(1e-10)).toBeCloseTo(m.scale(0.1) - m.scale(1), 9);
    expect(m.scale(3)).toBeCloseTo(12, 9);
  });
  it('fewer decades labelled when there is no room for all', () => {
    const axis = { label: 'y', scale: 'log' as const, domain: null, ticks: null };
    expect(tickCount(axis, [1e-11, 3], 120, 20)).toBe(6);
  });
  it('given ticks replace d3\'s, inside the domain, with short labels', () => {
    const m = axisMapping({ label: 'θ', scale: 'linear', domain: null, ticks: [-30, 0, 30, 60, 90, 200] }, [0, 180], [300, 0]);
    expect(m.scale.ticks(5)).toEqual([0, 30, 60, 90]);
    expect(m.scale.ticks(5).map(m.scale.tickFormat(5))).toEqual(['0', '30', '60', '90']);
    expect(m.scale(90)).toBe(150);
  });
  it('an equal aspect makes a unit as long up as across', () => {
    const c = settleChart(resolveChart({ label: 'L', aspect: 'equal', x: { domain: [-20, 20] }, y: { domain: [-12, 12] }, series: [] }));
    const { rect } = layoutChart(c, 640);
    expect(rect.height / 24).toBeCloseTo(rect.width / 40, 9);
  });
  it('an equal aspect with a given height keeps to it: the plot narrows instead', () => {
    const c = settleChart(resolveChart({ label: 'L', aspect: 'equal', height: 280, x: { domain: [-1.3, 1.3] }, y: { domain: [-1.3, 1.3] }, series: [] }));
    const { rect, height } = layoutChart(c, 700);
    expect(height).toBe(280);
    expect(rect.width).toBeCloseTo(rect.height, 9);
    expect(rect.width).toBeLessThan(700 / 2);
    // At a phone's width the column decides, and the units stay equal.
    const narrow = layoutChart(c, 200).rect;
    expect(narrow.height).toBeCloseTo(narrow.width, 9);
  });
});
