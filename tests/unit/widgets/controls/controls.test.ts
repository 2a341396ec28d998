import { describe, expect, it } from 'vitest';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { Simulation } from '../../../../core/simulation.ts';
import { DriftTracker, energyColumns } from '../../../../widgets/controls/drift.ts';
import { recordLayout, relativeChange } from '../../../../core/index.ts';
import { fixedNumber, formatDrift, formatRate, formatSpeed, formatTime, minusSign, readoutNumber, signedFixed } from '../../../../widgets/controls/format.ts';
import { parseBound, parseDt, parseNumber } from '../../../../widgets/controls/field-values.ts';
import { SPEEDS, speedsWith } from '../../../../widgets/controls/transport.ts';

describe('controls/parse', () => {
  it('parseDt(text) accepts positive numbers as typed', () => {
    expect(parseDt('5e-4')).toEqual({ value: 5e-4 });
    expect(parseDt(' 0.001 ')).toEqual({ value: 0.001 });
    expect(parseDt('.25')).toEqual({ value: 0.25 });
  });

  it('parseDt(text) says why a bad dt is refused', () => {
    expect(parseDt('')).toEqual({ error: 'dt is empty; type a number such as 5e-4' });
    expect(parseDt('abc')).toEqual({ error: 'dt: “abc” is not a number' });
    expect(parseDt('0')).toEqual({ error: 'dt must be positive, not 0' });
    expect(parseDt('−1e-3')).toEqual({ error: 'dt must be positive, not -0.001' });
    expect(parseDt('5')).toEqual({ error: 'dt = 5 is too large; use at most 1' });
    expect(parseDt('1e999')).toEqual({ error: 'dt: 1e999 is too large' });
    expect(parseDt('1/2000').error).toMatch(/not a number/);
  });

  it('parseBound(text, name) reads an empty bound as null', () => {
    expect(parseBound('', 't0')).toEqual({ value: null });
    expect(parseBound('−3', 't0')).toEqual({ value: -3 });
    expect(parseNumber('x1', 't1').error).toBe('t1: “x1” is not a number');
  });
});

describe('controls/format', () => {
  it('readoutNumber(x, digits) keeps a fixed number of significant digits', () => {
    expect(readoutNumber(200)).toBe('200.000');
    expect(readoutNumber(-0.5, 3)).toBe('−0.500');
    expect(readoutNumber(4.9631741e14, 8)).toBe('4.9631741 × 10¹⁴');
    expect(readoutNumber(-2e-7, 2)).toBe('−2.0 × 10⁻⁷');
    expect([NaN, Infinity, -Infinity, 0].map((x) => readoutNumber(x))).toEqual(['NaN', '∞', '−∞', '0']);
  });

  it('formatTime(t, dt) shows as many decimals as dt has', () => {
    expect(formatTime(12.3456789, 5e-4)).toBe('12.3457');
    expect(formatTime(3, 0.01)).toBe('3.00');
    expect(formatTime(3, 1)).toBe('3');
    expect(formatTime(-1.25, 0.01)).toBe('−1.25');
    expect(formatTime(-1e-9, 5e-4)).toBe('0.0000'); // t0 a hair below zero
  });

  it('minusSign(text) writes a true minus, and none on a number that reads as zero', () => {
    expect(minusSign('-2.5')).toBe('−2.5');
    expect(minusSign('2.5e-7')).toBe('2.5e-7'); // an exponent's sign is not the number's
    expect(minusSign('-1.5e-7')).toBe('−1.5e-7');
    expect(['-0', '-0.00', '-0.', '-.000', '-0e+0', '-0.0E-3'].map(minusSign)).toEqual(['0', '0.00', '0.', '.000', '0e+0', '0.0E-3']);
    expect(minusSign('-0.01')).toBe('−0.01');
    expect(minusSign('-10')).toBe('−10');
    expect(minusSign('0.00')).toBe('0.00');
  });

  it('fixedNumber(x, d) and signedFixed(x, d) never print −0, however small the negative rounded away', () => {
    for (const x of [-0, -1e-300, -4e-5, -0.004999]) {
      expect(fixedNumber(x, 2)).toBe('0.00');
      expect(signedFixed(x, 2)).toBe('0.00');
      expect(readoutNumber(x, 3)).not.toMatch(/^−0(\.0*)?$/);
    }
    expect(fixedNumber(-0.005001, 2)).toBe('−0.01');
    expect(signedFixed(-0.005001, 2)).toBe('−0.01');
    expect(signedFixed(27.3812, 2)).toBe('+27.38');
    expect(signedFixed(4e-5, 2)).toBe('0.00'); // no "+0.00" either: zero has no sign
    expect([NaN, Infinity, -Infinity].map((x) => fixedNumber(x, 2))).toEqual(['NaN', '∞', '−∞']);
  });

  it('formatDrift(d), formatSpeed(s), formatRate(r) read compactly', () => {
    expect(formatDrift(3.14e-12)).toBe('3.1 × 10⁻¹²');
    expect(formatDrift(0)).toBe('0');
    expect(formatSpeed(0.05)).toBe('0.05');
    expect(formatSpeed(200)).toBe('200');
    expect(formatRate(2000)).toBe('2000');
    expect(formatRate(100000)).toBe('100 k');
    expect(formatRate(2.5e6)).toBe('2.5 M');
  });

  it('speedsWith(speed) offers the usual speeds plus the given one, sorted', () => {
    expect(speedsWith(1)).toEqual(SPEEDS);
    expect(speedsWith(3)).toContain(3);
    expect(speedsWith(3).indexOf(3)).toBe(speedsWith(3).indexOf(2) + 1);
  });
});

describe('controls/drift', () => {
  it('energyColumns(layout) finds H, in each trajectory of a batch', () => {
    expect(energyColumns(recordLayout(['q', 'p'], ['H', 'I']))).toEqual([3]);
    // t, q[0], p[0], q[1], p[1], H[0], H[1]
    expect(energyColumns(recordLayout(['q', 'p'], ['H'], 2))).toEqual([5, 6]);
    expect(energyColumns(recordLayout(['q', 'p'], []))).toEqual([]);
  });

  it('relativeChange(h, h0) is |h − h0| / |h0|, absolute when h0 = 0', () => {
    expect(relativeChange(1.1, 1)).toBeCloseTo(0.1, 12);
    expect(relativeChange(-2.2, -2)).toBeCloseTo(0.1, 12);
    expect(relativeChange(0.3, 0)).toBeCloseTo(0.3, 12);
  });

  it('DriftTracker reports the worst drift of a batch and keeps H₀ when old rows are dropped', async () => {
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + q^2/2' });
    const sim = new Simulation(model, { initial: [1, 0, 2, 0], dt: 0.5, capacity: 4 }); // a large dt drifts
    const tracker = new DriftTracker(sim.record);
    tracker.start(sim.record);
    sim.run(40);
    expect(sim.record.dropped).toBeGreaterThan(0);
    const h = (j: number) => sim.record.get(sim.record.length - 1, sim.record.columnIndex(`H[${j}]`));
    const latest = tracker.latest(sim.record)!;
    expect(latest.drift).toBeCloseTo(Math.abs(h(0) - 0.5) / 0.5, 12);
    expect(latest.worst).toBeCloseTo(Math.max(Math.abs(h(0) - 0.5) / 0.5, Math.abs(h(1) - 2) / 2), 12);
    expect(new DriftTracker(recordLayout(['q', 'p'], [])).latest(sim.record)).toBeNull();
  });
});
