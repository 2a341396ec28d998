import { describe, expect, it } from 'vitest';
import { recordLayout } from '../../../../core/index.ts';
import { planSeries, spread } from '../../../../widgets/plots/series.ts';

describe('plots/series', () => {
  it('planSeries(layout) makes one legend entry per series for one trajectory', () => {
    const plan = planSeries(recordLayout(['q', 'p'], ['H', 'I']));
    expect(plan.groups).toEqual([
      { name: 'q', columns: [1] },
      { name: 'p', columns: [2] },
      { name: 'H', columns: [3] },
      { name: 'I', columns: [4] },
    ]);
    expect(plan.count).toBe(1);
  });

  it('planSeries(batch layout, maxLines) groups each series over the batch and draws at most maxLines of them', () => {
    const m = 1000;
    // t, x[0], y[0], x[1], y[1] … then H[0] … H[999]
    const plan = planSeries(recordLayout(['x', 'y'], ['H'], m), 50);
    expect(plan.groups.map((g) => g.name)).toEqual(['x', 'y', 'H']);
    expect(plan.drawn).toBe(50);
    expect(plan.count).toBe(m);
    for (const g of plan.groups) expect(g.columns).toHaveLength(50);
    expect(plan.groups[0].columns[0]).toBe(1); // x[0]
    expect(plan.groups[0].columns.at(-1)).toBe(1 + 2 * (m - 1)); // x[999]
  });

  it('planSeries(layout, n, only) keeps the named entries and names an unknown one in its error', () => {
    expect(planSeries(recordLayout(['q', 'p'], ['H']), 10, ['H']).groups.map((g) => g.name)).toEqual(['H']);
    expect(() => planSeries(recordLayout(['q', 'p'], []), 10, ['E'])).toThrow(/no series named "E"; the record has q, p/);
  });

  it('spread(count, n) picks n evenly spaced indices including both ends', () => {
    expect([...spread(5, 10)]).toEqual([0, 1, 2, 3, 4]);
    expect([...spread(101, 5)]).toEqual([0, 25, 50, 75, 100]);
    expect([...spread(1000, 1)]).toEqual([0]);
  });
});
