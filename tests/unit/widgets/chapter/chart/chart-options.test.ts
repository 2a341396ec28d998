import { describe, expect, it } from 'vitest';
import { fileName, resolveChart, toCurve } from '../../../../../widgets/chapter/chart/chart-options.ts';

const points: [number, number][] = [
  [0, 1],
  [1, 2],
];

describe('resolveChart: what a cell writes, checked', () => {
  it('gives points the next palette colour and dots, formulas and lines a line', () => {
    const c = resolveChart({ label: 'L', series: [{ points }, { formula: (x: number) => x }, { lines: [points, { x: [0, 1], y: [3, 4] }] }, { points, color: 'teal' }] });
    expect(c.series.map((s) => [s.kind, s.source, s.color])).toEqual([
      ['dots', 'points', 0],
      ['line', 'formula', 1],
      ['line', 'lines', 2],
      ['dots', 'points', 2],
    ]);
    expect(c.series[2].curves.map((k) => Array.from(k.y))).toEqual([
      [1, 2],
      [3, 4],
    ]);
  });

  it('reads columns {x, y} (typed arrays) as well as [x, y] pairs', () => {
    const c = resolveChart({ label: 'L', series: [{ x: new Float64Array([1, 2, 3]), y: [4, 5, 6], mark: 'line' }] });
    expect(Array.from(c.series[0].curves[0].x)).toEqual([1, 2, 3]);
    expect(c.series[0].kind).toBe('line');
  });

  it('samples a parametric curve over its parameter: an orbit over one period closes on itself', () => {
    const omega = 10;
    const c = resolveChart({ label: 'L', series: [{ curve: (t: number) => [Math.cos(omega * t), -Math.sin(omega * t)], from: 0, to: (2 * Math.PI) / omega, samples: 101 }] });
    const [s] = c.series;
    expect([s.source, s.kind, s.curves[0].x.length]).toEqual(['curve', 'line', 101]);
    const { x, y } = s.curves[0];
    // every point on the unit circle (q² + (p/mω)² = 1 for the oscillator at unit amplitude), the last the first
    for (let i = 0; i < x.length; i++) expect(Math.hypot(x[i], y[i])).toBeCloseTo(1, 14);
    expect(x[100]).toBeCloseTo(x[0], 14);
    expect(y[100]).toBeCloseTo(y[0], 14);
    // a quarter period on: (cos π/2, −sin π/2) = (0, −1)
    expect(x[25]).toBeCloseTo(0, 14);
    expect(y[25]).toBeCloseTo(-1, 14);
  });

  it('breaks a curve where it gives no finite point, and asks for its parameter range', () => {
    const c = resolveChart({ label: 'L', series: [{ curve: (s: number) => (s === 1 ? [NaN, 0] : s === 2 ? ({} as [number, number]) : [s, s * s]), from: 0, to: 3, samples: 4 }] });
    expect(Array.from(c.series[0].curves[0].x)).toEqual([0, NaN, NaN, 3]);
    expect(() => resolveChart({ label: 'L', series: [{ curve: (s: number) => [s, s] }] })).toThrow(/a curve needs from and to/);
    expect(() => resolveChart({ label: 'L', series: [{ curve: [[0, 1]], from: 0, to: 1 }] })).toThrow(/curve must be a function/);
  });

  it('skips false rules, so a rule can depend on a condition', () => {
    const c = resolveChart({ label: 'L', series: [], rules: [{ y: 1, label: 'c' }, false, null, { x: 2, faint: true }] });
    expect(c.rules).toEqual([
      { y: 1, label: 'c', faint: false },
      { x: 2, label: '', faint: true },
    ]);
  });

  it('says what is wrong, naming the option, rather than drawing nonsense', () => {
    expect(() => resolveChart({ series: [] })).toThrow(/label must say what the figure shows/);
    expect(() => resolveChart({ label: 'L', series: [{ points, formula: Math.sin }] })).toThrow(/series\[0\] needs exactly one of .* it has points and formula/);
    expect(() => resolveChart({ label: 'L', series: [{ label: 'beam', points, colour: 'red' }] })).toThrow(/series\[0\] has no option 'colour'/);
    expect(() => resolveChart({ label: 'L', series: [{ points, color: 'red' }] })).toThrow(/color must be one of blue, orange/);
    expect(() => resolveChart({ label: 'L', series: [{ lower: points }] })).toThrow(/a band needs both lower and upper/);
    expect(() => resolveChart({ label: 'L', series: [], x: { domain: [1, 1] } })).toThrow(/x.domain must be two different finite numbers/);
    expect(() => resolveChart({ label: 'L', series: [], y: { domain: [0, 1], scale: 'log' } })).toThrow(/log axis must be positive/);
    expect(() => resolveChart({ label: 'L', series: [], rules: [{ x: 1, y: 2 }] })).toThrow(/rules\[0\] needs exactly one of x or y/);
    expect(() => resolveChart({ label: 'L', series: [], aspect: 'equal', x: { scale: 'log' } })).toThrow(/needs linear axes/);
    expect(() => toCurve('series[0]', [[1, 2], [3]])).toThrow(/point 1 is not an \[x, y\] pair/);
    expect(() => toCurve('series[0]', { x: [1, 2], y: [1] })).toThrow(/x has 2 values but y has 1/);
  });

  it('names downloads after the label', () => {
    expect(fileName('Deflection angle against impact parameter')).toBe('deflection-angle-against-impact-parameter');
    expect(fileName('θ − θ_R (°)')).toBe('r');
    expect(fileName('—')).toBe('chart');
  });
});
