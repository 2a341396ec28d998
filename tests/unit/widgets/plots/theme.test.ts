import { describe, expect, it } from 'vitest';
import { PALETTE, seriesColor } from '../../../../widgets/plots/theme.ts';

/** WCAG relative luminance of #rrggbb. */
function luminance(hex: string): number {
  const [r, g, b] = [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16) / 255);
  const f = (c: number) => (c <= 0.03928 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);
  return 0.2126 * f(r) + 0.7152 * f(g) + 0.0722 * f(b);
}
const contrast = (a: string, b: string) => {
  const [x, y] = [luminance(a), luminance(b)].sort((m, n) => n - m);
  return (x + 0.05) / (y + 0.05);
};

describe('plots/theme', () => {
  it('every palette colour reads on a light and on a dark background (contrast ≥ 3.2)', () => {
    for (const c of PALETTE) {
      expect(contrast(c, '#ffffff')).toBeGreaterThanOrEqual(3.2);
      expect(contrast(c, '#111111')).toBeGreaterThanOrEqual(3.2);
    }
  });

  it('seriesColor(theme, i) cycles through the palette', () => {
    const theme = { series: PALETTE };
    expect(seriesColor(theme, 0)).toBe(PALETTE[0]);
    expect(seriesColor(theme, PALETTE.length + 2)).toBe(PALETTE[2]);
    expect(seriesColor(theme, -1)).toBe(PALETTE[PALETTE.length - 1]);
  });
});
