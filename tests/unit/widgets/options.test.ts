import { describe, expect, it } from 'vitest';
import { canonicalEquations } from '../../../widgets/core/canonical-equations.ts';
import { Simulation } from '../../../widgets/core/simulation.ts';
import {
  checkOptionNames, defaultCapacity, derivedSeries, flattenInitial, MAX_ROWS, oneLine, RECORD_BYTES, recordWidth, viewNames,
} from '../../../widgets/simulator/options.ts';

describe('simulator/options', () => {
  it('flattenInitial([q, p]) is one trajectory; a list of lists is a batch', () => {
    expect(flattenInitial([2, 0])).toEqual({ values: Float64Array.of(2, 0), count: 1, dim: 2 });
    const beam = flattenInitial(Array.from({ length: 30 }, (_, i) => [-20, (i - 15) * 0.3, 4, 0]), 4);
    expect(beam.count).toBe(30);
    expect(beam.values.length).toBe(120);
    expect(beam.values[4 * 29 + 1]).toBeCloseTo(4.2, 12);
  });

  it('flattenInitial(…) names what is wrong in one line', () => {
    const message = (f: () => unknown): string => {
      try {
        f();
      } catch (e) {
        return (e as Error).message;
      }
      return '';
    };
    expect(message(() => flattenInitial([1, 2, 3], 2))).toBe("simulator: initial has 3 values; it needs 2 (q's then p's for 1 degree(s) of freedom)");
    expect(message(() => flattenInitial([[1, 0], [1, 0, 3]]))).toBe('simulator: initial[1] has 3 values; it needs 2, like initial[0]');
    expect(message(() => flattenInitial([1, NaN]))).toBe('simulator: initial[1] is NaN, not a finite number');
    expect(message(() => flattenInitial([1, 2, 3]))).toMatch(/needs an even number/);
    expect(message(() => flattenInitial([]))).toMatch(/initial must be a list/);
    expect(message(() => flattenInitial('1,0'))).toMatch(/initial must be a list/);
    for (const m of [message(() => flattenInitial([1, 2, 3], 2)), message(() => flattenInitial(null))]) expect(m).not.toContain('\n');
  });

  it('checkOptionNames(options) rejects a misspelt option and suggests the right one', () => {
    expect(() => checkOptionNames({ hamiltonain: 'q', initial: [1, 0] })).toThrow('simulator: unknown option "hamiltonain"; did you mean "hamiltonian"?');
    expect(() => checkOptionNames({ colour: 1 })).toThrow(/unknown option "colour"$/);
    expect(() => checkOptionNames({ hamiltonian: 'q', initial: [1], views: ['time'], timePlot: {} })).not.toThrow();
  });

  it('viewNames(views) defaults to the time plot and rejects unknown views', () => {
    expect(viewNames(undefined)).toEqual(['time']);
    expect(viewNames(['phase', 'time'])).toEqual(['phase', 'time']);
    expect(() => viewNames(['time', 'fft'])).toThrow('simulator: unknown view "fft"; choose from time, trajectory, phase, spectrum');
  });

  it('derivedSeries({I: (t, x, H) => …}, model) hands each trajectory its own state and H', async () => {
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + q^2/2' });
    const derived = derivedSeries({ I: (t: number, x: Float64Array, H: number) => H / 2 + x[0] * 0 + t * 0, Q: (_t: number, [q]: Float64Array) => q }, model);
    const sim = new Simulation(model, { initial: [1, 0, 3, 4], derived });
    expect(sim.record.columns).toEqual(['t', 'q[0]', 'p[0]', 'q[1]', 'p[1]', 'H[0]', 'I[0]', 'Q[0]', 'H[1]', 'I[1]', 'Q[1]']);
    expect(sim.record.get(0, sim.record.columnIndex('I[1]'))).toBeCloseTo(12.5 / 2, 12);
    expect(sim.record.get(0, sim.record.columnIndex('Q[1]'))).toBe(3);
  });

  it('derivedSeries(…) refuses names taken by t, H or the state, and non-functions', async () => {
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + q^2/2' });
    expect(() => derivedSeries({ q: () => 1 }, model)).toThrow('simulator: the derived series "q" has the name of a state component');
    expect(() => derivedSeries({ H: () => 1 }, model)).toThrow(/the name of the energy/);
    expect(() => derivedSeries({ I: 3 }, model)).toThrow('simulator: derived.I must be a function (t, x, H) => number');
    expect(() => derivedSeries(5, model)).toThrow(/derived must be an object/);
  });

  it('defaultCapacity(width) sizes the record from a memory budget, capped at a million rows', async () => {
    expect(defaultCapacity(4)).toBe(MAX_ROWS);
    const model = await canonicalEquations({ dof: 2, hamiltonian: 'px^2 + py^2 + 30/sqrt(x^2+y^2)', coordinates: ['x', 'y'], momenta: ['px', 'py'] });
    const width = recordWidth(model, 1000, 0);
    expect(width).toBe(1 + 1000 * 5);
    expect(defaultCapacity(width) * width * 8).toBeLessThanOrEqual(RECORD_BYTES);
  });

  it('oneLine(error) keeps the first line of a message', () => {
    expect(oneLine(new Error('bad H\n  at line 2'))).toBe('bad H');
    expect(oneLine('plain')).toBe('plain');
  });
});
