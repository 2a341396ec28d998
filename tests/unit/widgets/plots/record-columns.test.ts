import { describe, expect, it } from 'vitest';
import { recordLayout } from '../../../../core/index.ts';
import { axisTitle, columnsOf, defaultBodies, phasePairs, toExtent, tracksOf } from '../../../../widgets/plots/record-columns.ts';

// Columns t, q0 … q3, p0 … p3, H
const single = recordLayout(['q0', 'q1', 'q2', 'q3', 'p0', 'p1', 'p2', 'p3'], ['H']);
// Columns t, q0[0], q1[0], p0[0], p1[0], q0[1], q1[1], p0[1], p1[1], H[0], H[1]
const batch = recordLayout(['q0', 'q1', 'p0', 'p1'], ['H'], 2);

describe('plane-columns', () => {
  it('columnsOf(layout, name) is the column of that series in one trajectory', () => {
    expect(columnsOf(single, 'q2')).toEqual([3]);
    expect(columnsOf(single, 'H')).toEqual([9]);
  });

  it('columnsOf(layout, name) is the series\' column in every trajectory j, or the one column its header names', () => {
    expect(columnsOf(batch, 'q1')).toEqual([2, 6]);
    expect(columnsOf(batch, 'p0[1]')).toEqual([7]);
  });

  it('columnsOf(layout, name) names the series it has when the name is unknown', () => {
    expect(() => columnsOf(single, 'x')).toThrow(/no series named “x”; the record has q0, q1/);
    expect(() => columnsOf(single, 't')).toThrow(/no series/);
  });

  it('tracksOf(layout, pair, group) pairs x and y trajectory by trajectory', () => {
    expect(tracksOf(batch, ['q0', 'q1'], (j) => 10 + j)).toEqual([
      { x: 1, y: 2, group: 10 },
      { x: 5, y: 6, group: 11 },
    ]);
    expect(() => tracksOf(batch, ['q0', 'p0[1]'], () => 0)).toThrow(/as many of each/);
  });

  it('defaultBodies(names, dof) pairs consecutive coordinates and refuses one coordinate', () => {
    expect(defaultBodies(['q0', 'q1', 'q2', 'q3', 'p0', 'p1', 'p2', 'p3'], 4)).toEqual([
      ['q0', 'q1'],
      ['q2', 'q3'],
    ]);
    expect(defaultBodies(['a', 'b', 'c', 'pa', 'pb', 'pc'], 3)).toEqual([['a', 'b']]);
    expect(() => defaultBodies(['q', 'p'], 1)).toThrow(/one coordinate/);
  });

  it('phasePairs(names, dof, chosen) is (q_i, p_i) for all or the chosen i, or explicit pairs', () => {
    const names = ['q0', 'q1', 'p0', 'p1'];
    expect(phasePairs(names, 2)).toEqual([
      ['q0', 'p0'],
      ['q1', 'p1'],
    ]);
    expect(phasePairs(names, 2, [1, ['q0', 'H']])).toEqual([
      ['q1', 'p1'],
      ['q0', 'H'],
    ]);
    expect(() => phasePairs(names, 2, [2])).toThrow(/0 … 1/);
  });

  it('axisTitle(names, generic) is the one name, or the generic name with the list', () => {
    expect(axisTitle(['q0', 'q0'], 'x')).toBe('q0');
    expect(axisTitle(['q0', 'q2'], 'x')).toBe('x (q0, q2)');
    expect(axisTitle(['q0', 'q1', 'q2', 'q3'], 'q')).toBe('q (q0, q1, …)');
  });

  it('toExtent(option, what) checks the bounds', () => {
    expect(toExtent({ x: [-1, 1], y: [0, 2] }, 'extent')).toEqual({ x0: -1, x1: 1, y0: 0, y1: 2 });
    expect(toExtent(undefined, 'extent')).toBeUndefined();
    expect(() => toExtent({ x: [1, 1], y: [0, 2] }, 'limit')).toThrow(/limit must be/);
  });
});

describe('a large batch: a plane view draws a stated, even sample of its trajectories', () => {
  it('tracksOf picks MAX_PLANE_TRACKS evenly spread trajectories, first and last included, with their own groups', async () => {
    const { tracksOf, MAX_PLANE_TRACKS, batchTitle } = await import('../../../../widgets/plots/record-columns.ts');
    const count = 100_000;
    // Every trajectory's q, then every trajectory's p.
    const block = (name: string, first: number, n: number) => ({ name, columns: Array.from({ length: n }, (_, j) => first + j) });
    const layout = (n: number) => ({
      columns: ['t', ...Array.from({ length: n }, (_, j) => `q[${j}]`), ...Array.from({ length: n }, (_, j) => `p[${j}]`)],
      series: [block('q', 1, n), block('p', 1 + n, n)],
      trajectories: n,
    });
    const tracks = tracksOf(layout(count), ['q', 'p'], (j) => j);
    expect(tracks).toHaveLength(MAX_PLANE_TRACKS);
    expect(tracks[0]).toEqual({ x: 1, y: 1 + count, group: 0 });
    expect(tracks.at(-1)).toEqual({ x: count, y: 2 * count, group: count - 1 });
    // Evenly spread: no two neighbours farther apart than ⌈count / (MAX − 1)⌉.
    const gaps = tracks.slice(1).map((t, k) => t.group - tracks[k].group);
    expect(Math.max(...gaps)).toBeLessThanOrEqual(Math.ceil(count / (MAX_PLANE_TRACKS - 1)));
    expect(batchTitle(count)).toBe('2,000 of 100,000 trajectories shown');
    expect(batchTitle(30)).toBe('30 trajectories');
    expect(batchTitle(1)).toBeUndefined();
    // A batch within the bound is drawn whole.
    expect(tracksOf(layout(10), ['q', 'p'], (j) => j)).toHaveLength(10);
  });
});
