import { describe, expect, it } from 'vitest';
import { makeMapping, scaleFor, toPixel, transform, untransform } from '../../../../widgets/plots/scale.ts';

describe('plots/scale: the time plot’s y mapping', () => {
  it('toPixel(makeMapping(kind, domain, range), y) equals the d3 scale of the same kind', () => {
    for (const kind of ['linear', 'symlog'] as const) {
      for (const domain of [[-1, 1], [-250, 3], [0.5, 1e6], [-1e12, -3]] as const) {
        const range = [400, 8] as const;
        const m = makeMapping(kind, domain, range);
        const scale = scaleFor(kind, domain, range);
        for (const y of [domain[0], domain[1], 0, -0.7, 2.5, 1e3, -1e7, (domain[0] + domain[1]) / 2]) {
          expect(toPixel(m, y)).toBeCloseTo(scale(y), 6);
        }
      }
    }
  });

  it('symlog is the paper’s m_y: 20 ln(1 + |y|) sgn y + h/2 for a matching domain', () => {
    const h = 768;
    const u = h / 2 / 20; // the domain edge in transformed units
    const m = makeMapping('symlog', [-untransform('symlog', u), untransform('symlog', u)], [h, 0]);
    for (const y of [-1e6, -3, -0.2, 0, 0.2, 3, 1e6]) {
      // pixels grow downward on a canvas, so the paper's upward η is h − m_y
      expect(h - toPixel(m, y)).toBeCloseTo(20 * Math.log1p(Math.abs(y)) * Math.sign(y) + h / 2, 6);
    }
  });

  it('untransform(symlog) undoes transform(symlog)', () => {
    for (const y of [-1e300, -5, -1e-9, 0, 1e-9, 5, 1e300]) expect(untransform('symlog', transform('symlog', y))).toBeCloseTo(y, 10 - Math.max(0, Math.log10(Math.abs(y) || 1)));
    expect(Object.is(transform('symlog', -0), -0) || transform('symlog', -0) === 0).toBe(true);
  });

  it('makeMapping(kind, [a, a], range) puts every value at the middle instead of dividing by zero', () => {
    const m = makeMapping('linear', [3, 3], [100, 0]);
    expect(toPixel(m, 3)).toBe(50);
    expect(toPixel(m, 1e9)).toBe(50);
  });
});
