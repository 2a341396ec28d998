import { describe, expect, it } from 'vitest';
import type { Theme } from '../../../../../widgets/plots/theme.ts';
import { drawTimeFrame, plotBox } from '../../../../../widgets/plots/time/time-stage.ts';
import { formatPower } from '../../../../../widgets/plots/ticks.ts';
import { scaleFor } from '../../../../../widgets/plots/scale.ts';
import { FakeContext } from '../../../support/fake-canvas.ts';

const THEME: Theme = { fg: '#000', bg: '#fff', muted: '#000', accent: '#00f', axis: '#111', grid: '#ccc', series: ['red'], font: 'sans-serif', dark: false };

/** The y labels a time plot's frame draws, with their heights, for a domain on a plot `height` px tall. */
function yLabels(kind: 'linear' | 'symlog', domain: [number, number], height = 244) {
  const ctx = new FakeContext();
  const box = plotBox(640, height);
  const state = { box, kind, domain, inset: 0.02, t0: 0, t1: 10 };
  const labels = drawTimeFrame(ctx as never, state, THEME, 640, height);
  const drawn = ctx.calls.filter((c) => c[0] === 'fillText' && c[2] === box.left - 6).map((c) => ({ text: c[1] as string, y: c[3] as number }));
  return { labels, drawn, box };
}

describe('plots/ticks and the time plot’s y axis', () => {
  it('formatPower(v) writes 10ⁿ from 10⁴ on, with a true minus', () => {
    expect([0, 1, -10, 1000, 1e4, -1e20].map(formatPower)).toEqual(['0', '1', '−10', '1000', '10⁴', '−10²⁰']);
  });

  it('the time plot’s y axis labels every decade of a symlog range its height has room for', () => {
    const { drawn } = yLabels('symlog', [-1e6, 1e6], 400);
    const texts = drawn.map((d) => d.text);
    for (const k of [1, 2, 3, 4, 5, 6]) {
      expect(texts).toContain(formatPower(10 ** k));
      expect(texts).toContain(formatPower(-(10 ** k)));
    }
    expect(texts).toContain('0');
  });

  it('its labels are a line of text apart and fit left of the plot, at every magnitude', () => {
    for (let e = -12; e <= 15; e++) {
      for (const kind of ['linear', 'symlog'] as const) {
        const domain: [number, number] = [-3 * 10 ** e, 7 * 10 ** e];
        const { drawn, box } = yLabels(kind, domain);
        expect(drawn.length, `${kind} 10^${e}`).toBeGreaterThanOrEqual(2);
        const ys = drawn.map((d) => d.y).sort((a, b) => a - b);
        for (let i = 1; i < ys.length; i++) expect(ys[i] - ys[i - 1]).toBeGreaterThanOrEqual(11);
        // the fake context measures 6 px a character: every label within the room left of the plot
        for (const d of drawn) expect(d.text.length * 6).toBeLessThanOrEqual(box.left - 8);
        const y = scaleFor(kind, domain, [box.top + box.height * 0.98, box.top + box.height * 0.02]);
        for (const d of drawn) expect(d.y).toBeGreaterThanOrEqual(y(domain[1]) - 1);
      }
    }
  });

  it('a tiny span far from zero gets short labels and its offset written once, under them', () => {
    const { labels, drawn } = yLabels('linear', [1e9, 1e9 + 1e-3]);
    expect(labels.offsetText).toBe('1×10⁹');
    expect(drawn.map((d) => d.text)).toContain('+1×10⁹');
  });
});
