import { describe, expect, it } from 'vitest';
import { chartCsv, chartSummary, tableRows } from '../../../../../widgets/chapter/chart/chart-data.ts';
import { resolveChart } from '../../../../../widgets/chapter/chart/chart-options.ts';
import { settleChart } from '../../../../../widgets/chapter/chart/chart-scale.ts';

const chart = settleChart(
  resolveChart({
    label: 'Deflection against b',
    x: { label: 'impact parameter, |b|', domain: [0, 2] },
    y: { label: 'θ' },
    series: [
      { label: 'beam', points: [[0.1, 1 / 3], [0.2, -2e-17]] },
      { label: 'trajectories', lines: [[[0, 0], [1, 1]], [[0, 1], [1, 0]]] },
      { formula: (x: number) => x / 3, samples: 2 },
    ],
    rules: [{ x: 1.5, label: 'escape at b = 1.5' }],
  }),
);

describe('chartCsv', () => {
  it('has a row a point, headed by the axes, each number reading back to the same double', () => {
    const csv = chartCsv(chart);
    const rows = csv.trim().split('\n');
    expect(rows[0]).toBe('series,"impact parameter, |b|",θ');
    expect(rows.length).toBe(1 + 2 + 4 + 2);
    expect(rows[1]).toBe('beam,0.1,0.3333333333333333');
    expect(Number(rows[1].split(',')[2])).toBe(1 / 3);
    expect(Number(rows[2].split(',')[2])).toBe(-2e-17);
    expect(rows.slice(3, 7).map((r) => r.split(',')[0])).toEqual(['trajectories 1', 'trajectories 1', 'trajectories 2', 'trajectories 2']);
    expect(rows[8]).toBe(`series 3,2,${String(2 / 3)}`);
  });
});

describe('chartSummary', () => {
  it('says what is drawn, on which axes, and what is marked', () => {
    const text = chartSummary(chart);
    expect(text).toContain('Deflection against b.');
    expect(text).toContain('Horizontal axis: impact parameter, |b|, from 0 to 2.');
    expect(text).toContain('beam: 2 points, x from 0.1 to 0.2, y from −2e−17 to 0.3333.');
    expect(text).toContain('trajectories: 2 lines');
    expect(text).toContain('series 3: a formula curve, x from 0 to 2');
    expect(text).toContain('Marked: escape at b = 1.5 (x = 1.5).');
    expect(text).not.toMatch(/NaN|Infinity/);
  });
  it('names a parametric curve, and reads −0 as 0', () => {
    const orbit = settleChart(resolveChart({ label: 'Orbit', series: [{ label: 'orbit', curve: (t: number) => [Math.cos(t), -Math.sin(t)], from: 0, to: Math.PI, samples: 3 }] }));
    // (1, −0), (0, −1), (−1, −0): y runs from −1 to 0
    expect(chartSummary(orbit)).toContain('orbit: a parametric curve of 3 points, x from −1 to 1, y from −1 to 0.');
  });
});

describe('tableRows', () => {
  it('shows every row of a short curve, and evenly spaced ones of a long curve, first and last included', () => {
    const x = Float64Array.from({ length: 1001 }, (_, i) => i);
    const { rows, omitted } = tableRows({ x, y: x }, 11);
    expect(rows.map(([a]) => a)).toEqual([0, 100, 200, 300, 400, 500, 600, 700, 800, 900, 1000]);
    expect(omitted).toBe(990);
    expect(tableRows({ x: x.subarray(0, 3), y: x.subarray(0, 3) }, 11)).toEqual({ rows: [[0, 0], [1, 1], [2, 2]], omitted: 0 });
  });
});
