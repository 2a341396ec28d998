import { describe, expect, it } from 'vitest';
import { spectrum } from '../../../../../core/spectrum/spectrum.ts';
import { drawAxes } from '../../../../../widgets/plots/axes.ts';
import { makeMapping } from '../../../../../widgets/plots/scale.ts';
import { drawSpectrum, lastBin, spectrumMappings, type SpectrumPicture } from '../../../../../widgets/plots/spectrum/spectrum-plot.ts';
import type { Theme } from '../../../../../widgets/plots/theme.ts';
import { fakeContext } from '../../../support/fake-canvas.ts';

const theme: Theme = {
  fg: '#111',
  bg: '#fff',
  muted: '#777',
  accent: '#2563eb',
  axis: '#777',
  grid: '#ddd',
  series: ['#2563eb', '#d9480f'],
  font: 'sans-serif',
  dark: false,
};

function picture(overrides: Partial<SpectrumPicture> = {}): SpectrumPicture {
  const samples = Float64Array.from({ length: 1024 }, (_, j) => Math.cos(2 * Math.PI * 1.5 * j * 0.01));
  return {
    spectrum: spectrum(samples, 0.01),
    peaks: [{ frequency: 1.5, amplitude: 1 }],
    show: 'magnitude',
    maxFrequency: 5,
    yMax: 1.2,
    series: 'q',
    ...overrides,
  };
}

const texts = (calls: { name: string; args: unknown[] }[]) => calls.filter((c) => c.name === 'fillText').map((c) => c.args[0]);

describe('spectrum-plot', () => {
  it('spectrumMappings(w, h, p) puts 0 … maxFrequency across and 0 … yMax (or ±yMax with Re, Im) up', () => {
    const { rect, mx, my } = spectrumMappings(700, 300, { maxFrequency: 5, yMax: 2, show: 'magnitude' });
    expect(mx.scale(0)).toBe(rect.left);
    expect(mx.scale(5)).toBe(rect.left + rect.width);
    expect(my.scale(0)).toBe(rect.top + rect.height);
    const both = spectrumMappings(700, 300, { maxFrequency: 5, yMax: 2, show: 'both' });
    expect(both.my.scale(0)).toBeCloseTo(both.rect.top + both.rect.height / 2, 9);
  });

  it('lastBin(s, f) is the first bin past f, within the spectrum', () => {
    const s = picture().spectrum;
    expect(s.frequency[lastBin(s, 5)]).toBeGreaterThan(5);
    expect(lastBin(s, 1e9)).toBe(s.frequency.length - 1);
  });

  it('drawSpectrum(g, w, h, p, theme, dpr) draws the theory marker dashed at its frequency, with its label', () => {
    const { context, calls } = fakeContext();
    const p = picture({ theory: { frequency: 1.518, label: 'theory 1.518' } });
    drawSpectrum(context, 700, 300, p, theme, 1);
    const { mx } = spectrumMappings(700, 300, p);
    const dash = calls.findIndex((c) => c.name === 'setLineDash' && (c.args[0] as number[]).length > 0);
    expect(dash).toBeGreaterThan(-1);
    const move = calls.slice(dash).find((c) => c.name === 'moveTo')!;
    expect(Math.abs((move.args[0] as number) - mx.scale(1.518))).toBeLessThanOrEqual(1);
    expect(texts(calls)).toContain('theory 1.518');
  });

  it('drawSpectrum(g, …) numbers the peaks on the plot and labels the lines shown', () => {
    const magnitude = fakeContext();
    drawSpectrum(magnitude.context, 700, 300, picture(), theme, 2);
    expect(texts(magnitude.calls)).toEqual(expect.arrayContaining(['1', '|X|', 'spectrum of q', 'frequency f (cycles per time unit)']));
    expect(texts(magnitude.calls)).not.toContain('Re');
    const both = fakeContext();
    drawSpectrum(both.context, 700, 300, picture({ show: 'both' }), theme, 2);
    expect(texts(both.calls)).toEqual(expect.arrayContaining(['|X|', 'Re', 'Im']));
    const strokes = both.calls.filter((c) => c.name === 'set strokeStyle').map((c) => c.args[0]);
    expect(strokes).toEqual(expect.arrayContaining([theme.muted, theme.series[1], theme.accent]));
  });

  it('drawAxes(g, rect, mx, my, theme, style, dpr) labels d3’s ticks and both axes', () => {
    const { context, calls } = fakeContext();
    const rect = { left: 50, top: 20, width: 400, height: 200 };
    drawAxes(context, rect, makeMapping('linear', [0, 10], [50, 450]), makeMapping('symlog', [-100, 100], [220, 20]), theme, { xLabel: 'q0', yLabel: 'p0' }, 1);
    const labels = texts(calls);
    expect(labels).toEqual(expect.arrayContaining(['0', '2', '10', 'q0', 'p0', '−100', '100']));
  });
});
