import { scaleLinear as d3Linear, scaleSymlog as d3Symlog } from 'd3-scale';
import { describe, expect, test } from 'vitest';
import { scaleLinear, scaleSymlog } from '../../../../widgets/plots/scale.ts';

// The reference is d3-scale itself: these scales must behave as d3's for what the plots use.
/** Equal to rounding, relative to the size of the values. */
function expectNear(x: number, y: number): void {
  expect(Math.abs(x - y)).toBeLessThanOrEqual(1e-12 * Math.max(1, Math.abs(y)));
}

const DOMAINS: Array<[number, number]> = [[0, 1], [-3.7, 12.2], [1e-9, 3e-9], [-2e12, 5e14], [7, -7], [0.3, 0.3]];

describe('scaleLinear()', () => {
  test.each(DOMAINS)('maps, inverts, ticks, formats and nices like d3 on [%d, %d]', (a, b) => {
    const ours = scaleLinear().domain([a, b]).range([10, 410]);
    const theirs = d3Linear().domain([a, b]).range([10, 410]);
    for (const v of [a, b, (a + b) / 2, a - 1, b * 3]) expectNear(ours(v), theirs(v));
    for (const px of [10, 123, 410]) if (a !== b) expectNear(ours.invert(px), theirs.invert(px));
    for (const count of [2, 5, 10]) {
      expect(ours.ticks(count)).toEqual(theirs.ticks(count));
      const values = theirs.ticks(count);
      expect(values.map(ours.tickFormat(count))).toEqual(values.map(theirs.tickFormat(count)));
    }
    expect(scaleLinear().domain([a, b]).nice(8).domain()).toEqual(d3Linear().domain([a, b]).nice(8).domain());
  });
});

describe('scaleSymlog()', () => {
  test.each([[1], [0.5], [30]])('maps and inverts like d3 with constant %d', (c) => {
    const ours = scaleSymlog().constant(c).domain([-500, 2000]).range([300, 0]);
    const theirs = d3Symlog().constant(c).domain([-500, 2000]).range([300, 0]);
    for (const v of [-500, -3, 0, 0.2, 40, 2000]) expectNear(ours(v), theirs(v));
    for (const px of [0, 77, 300]) expectNear(ours.invert(px), theirs.invert(px));
  });
});
