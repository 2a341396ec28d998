/**
 * The chaotic share of Hénon & Heiles's section against their Fig. 6
 * (Astron. J. 69, 73, 1964): measured here by classifying a grid of launch
 * points by their finite-time Lyapunov exponent, and compared within the
 * sum of the figure's reading error, the grid's sampling error and the
 * share of points whose verdict is unsettled between T/2 and T.
 */
import { describe, expect, it } from 'vitest';
import { henonHeiles } from '../../../../core/analysis/henon-heiles.ts';
import { chaoticArea, HENON_HEILES_FIG6, sectionBox } from '../../../../core/analysis/poincare-area.ts';

describe('sectionBox', () => {
  it('spans the allowed region of plane x = 0: V(0, y) = y²/2 − y³/3 = E at its ends, p_y up to √(2E)', () => {
    const E = 1 / 8;
    const box = sectionBox(henonHeiles, E, 'x');
    const V = (y: number) => y * y / 2 - y ** 3 / 3;
    expect(V(box.uMax)).toBeCloseTo(E, 3);
    expect(V(box.uMin)).toBeCloseTo(E, 3);
    expect(box.puMax).toBe(Math.sqrt(2 * E));
  });
});

describe('chaotic area against Hénon & Heiles (1964), Fig. 6', () => {
  for (const published of HENON_HEILES_FIG6) {
    it(`at E = ${published.energy.toFixed(4)}: the published share ${published.chaotic}`, () => {
      const area = chaoticArea(henonHeiles, published.energy, { plane: 'x', grid: 16, time: 600 });
      expect(area.total).toBeGreaterThan(150);
      const allowed = published.reading + area.samplingError + area.undecided;
      expect(Math.abs(area.fraction - published.chaotic)).toBeLessThanOrEqual(allowed);
    });
  }

  it('rises with the energy, as the figure\'s curve falls', () => {
    const f = [1 / 12, 1 / 8].map((E) => chaoticArea(henonHeiles, E, { plane: 'x', grid: 8, time: 400 }).fraction);
    expect(f[1]).toBeGreaterThan(f[0] + 0.2);
  });
});
