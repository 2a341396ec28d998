import { describe, expect, it } from 'vitest';
import { canonicalEquations } from '../../../../../core/model/canonical-equations.ts';
import { Simulation } from '../../../../../core/simulation.ts';
import { compareWithTheory } from '../../../../../widgets/plots/spectrum/spectrum-readout.ts';
import { hamming } from '../../../../../core/spectrum/window.ts';
import { analyse, displaySpectrum, largestShown, theoryOf } from '../../../../../widgets/plots/spectrum/spectrum-analysis.ts';
import { lastBin } from '../../../../../widgets/plots/spectrum/spectrum-plot.ts';
import { chooseRows, gatherSamples } from '../../../../../widgets/plots/spectrum/spectrum-rows.ts';

describe('spectrum-analysis', () => {
  it('analyse(samples, Δ, window, n) finds a tone’s frequency and amplitude, strongest first', () => {
    const dt = 0.01;
    const samples = Float64Array.from({ length: 4000 }, (_, j) => 2 * Math.cos(2 * Math.PI * 1.37 * j * dt) + 0.5 * Math.sin(2 * Math.PI * 4.1 * j * dt) + 3);
    const { peaks, spectrum } = analyse(samples, dt, 'hamming', 3);
    expect(peaks.length).toBe(2);
    expect(peaks[0].frequency).toBeCloseTo(1.37, 4);
    expect(peaks[0].amplitude).toBeCloseTo(2, 3);
    expect(peaks[1].frequency).toBeCloseTo(4.1, 4);
    expect(peaks[1].amplitude).toBeCloseTo(0.5, 3);
    expect(spectrum.window).toBe('hamming');
  });

  it('analyse(samples, Δ, window, n) of a constant series has no peaks', () => {
    expect(analyse(new Float64Array(256).fill(4), 0.1, 'hamming', 3).peaks).toEqual([]);
    expect(analyse(Float64Array.from({ length: 256 }, (_, j) => Math.sin(j)), 0.1, 'none', 0).peaks).toEqual([]);
  });

  it('the nonlinear oscillator of the paper’s §6.7 reads ω/2π ≈ 1.518 through chooseRows, gatherSamples and analyse', async () => {
    const model = await canonicalEquations({
      dof: 1,
      hamiltonian: 'p^2/2 + omega0^2*q^2/2 + alpha*q^3 + beta*q^4',
      params: { omega0: 10, alpha: -2, beta: -3 },
    });
    const simulation = new Simulation(model, { initial: [1, 0] });
    simulation.run(60_000); // 30 time units at the paper's dt = 5e-4
    const choice = chooseRows(simulation.record, undefined, 1 << 14)!;
    expect(choice.stride).toBe(4);
    expect(choice.interval).toBeCloseTo(4 * 5e-4, 12);
    const samples = gatherSamples(simulation.record, simulation.record.columnIndex('q'), choice, new Float64Array(choice.samples));
    const { peaks } = analyse(samples, choice.interval, 'hamming', 3);
    expect(Math.abs(peaks[0].frequency - 1.518)).toBeLessThan(1e-3);
    expect(peaks[0].amplitude).toBeGreaterThan(0.9);
    expect(compareWithTheory(peaks[0], { frequency: 1.518, label: 'theory 1.518' }, choice.duration)).toMatch(/^strongest peak 1\.518 vs theory 1\.518: ([+−]0\.0[1-9]|0\.00)%$/); // signed unless it rounds to zero
  });

  it('theoryOf(option, format) takes a number or {frequency, label}, and ignores nonsense', () => {
    const format = (f: number) => f.toFixed(2);
    expect(theoryOf(1.518, format)).toEqual({ frequency: 1.518, label: 'theory 1.52' });
    expect(theoryOf({ frequency: 2, label: 'ω₀/2π' }, format)).toEqual({ frequency: 2, label: 'ω₀/2π' });
    expect(theoryOf(-1, format)).toBeUndefined();
    expect(theoryOf(undefined, format)).toBeUndefined();
  });

  it('largestShown(s, reim, end) is the largest |X| (and |Re|, |Im|) past DC up to bin end', () => {
    const s = { amplitude: Float64Array.from([9, 1, 2, 7]), re: Float64Array.from([0, -3, 1, 0]), im: Float64Array.from([0, 0, -2.5, 0]) };
    expect(largestShown(s, false, 2)).toBe(2);
    expect(largestShown(s, true, 2)).toBe(3);
    expect(largestShown(s, false, 99)).toBe(7);
  });
});

describe('displaySpectrum', () => {
  /** The windowed DTFT of y at f, normalised as the core's spectrum, referred to the first sample. */
  function dtft(y: Float64Array, dt: number, f: number): [number, number] {
    const n = y.length;
    let mean = 0;
    for (const v of y) mean += v / n;
    let re = 0;
    let im = 0;
    let sum = 0;
    for (let j = 0; j < n; j++) {
      const w = hamming(j / n);
      sum += w;
      re += w * (y[j] - mean) * Math.cos(2 * Math.PI * f * j * dt);
      im -= w * (y[j] - mean) * Math.sin(2 * Math.PI * f * j * dt);
    }
    return [(2 * re) / sum, (2 * im) / sum];
  }

  it('displaySpectrum(samples, Δ, window, fmax) thins the samples but keeps |X|, Re and Im where it is drawn', () => {
    const dt = 1e-3;
    const y = Float64Array.from({ length: 8192 }, (_, j) => 2 * Math.cos(2 * Math.PI * 1.5 * j * dt + 0.7) + 0.3 * Math.cos(2 * Math.PI * 40 * j * dt));
    const s = displaySpectrum(y, dt, 'hamming', 4);
    expect(s.interval).toBeGreaterThan(5 * dt);
    expect(s.frequency[lastBin(s, 4)]).toBeGreaterThan(4);
    expect(lastBin(s, 4)).toBeGreaterThan(300);
    for (const f of [1.3, 1.5, 1.62, 3]) {
      const k = Math.round(f / s.binWidth);
      const [re, im] = dtft(y, dt, s.frequency[k]);
      expect(s.re[k]).toBeCloseTo(re, 2);
      expect(s.im[k]).toBeCloseTo(im, 2);
      expect(s.amplitude[k]).toBeCloseTo(Math.hypot(re, im), 2);
    }
  });
});
