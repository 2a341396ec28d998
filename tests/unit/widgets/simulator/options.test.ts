/**
 * simulator()'s options, through the one step that checks them
 * (parseSimulatorOptions): what each becomes in the settings, and the one
 * line each mistake is reported in. No DOM: the settings are plain data, a
 * model and a Simulation.
 */
import { describe, expect, it } from 'vitest';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { InputError } from '../../../../core/errors.ts';
import { defaultCapacity, MAX_ROWS, oneLine, parseSimulatorOptions, RECORD_BYTES, recordWidth } from '../../../../widgets/simulator/options.ts';

const oscillator = { hamiltonian: 'p^2/2 + q^2/2' };

/** The message parseSimulatorOptions rejects `raw` with, checked to be one line of an InputError naming the simulator; '' if it resolves. */
async function messageOf(raw: unknown): Promise<string> {
  try {
    await parseSimulatorOptions(raw);
  } catch (error) {
    expect(error).toBeInstanceOf(InputError);
    const { message } = error as Error;
    expect(message).toMatch(/^simulator: /);
    expect(message).not.toContain('\n');
    expect(message.length).toBeLessThan(190);
    return message;
  }
  return '';
}

describe('simulator/options', () => {
  it('initial [q, p] is one trajectory; a list of lists is a batch, sampled every 20 steps', async () => {
    const one = await parseSimulatorOptions({ ...oscillator, initial: [2, 0] });
    expect(one.simulation.initial).toEqual(Float64Array.of(2, 0));
    expect(one.simulation.count).toBe(1);
    expect(one.simulation.every).toBe(1);
    const beam = await parseSimulatorOptions({ hamiltonian: 'p0^2/2 + p1^2/2', initial: Array.from({ length: 30 }, (_, i) => [-20, (i - 15) * 0.3, 4, 0]) });
    expect(beam.model.dof).toBe(2);
    expect(beam.simulation.count).toBe(30);
    expect(beam.simulation.initial.length).toBe(120);
    expect(beam.simulation.initial[4 * 29 + 1]).toBeCloseTo(4.2, 12);
    expect(beam.simulation.every).toBe(20);
  });

  it('a wrong initial state is named in one line', async () => {
    expect(await messageOf({ ...oscillator, dof: 1, initial: [1, 2, 3] })).toBe("simulator: initial has 3 values; it needs 2 (q's then p's for 1 degree(s) of freedom)");
    expect(await messageOf({ ...oscillator, initial: [[1, 0], [1, 0, 3]] })).toBe('simulator: initial[1] has 3 values; it needs 2, like initial[0]');
    expect(await messageOf({ ...oscillator, initial: [1, NaN] })).toBe('simulator: initial[1] is NaN, not a finite number');
    expect(await messageOf({ ...oscillator, initial: [1, 2, 3] })).toMatch(/needs an even number/);
    expect(await messageOf({ ...oscillator, initial: [] })).toMatch(/initial must be a list/);
    expect(await messageOf({ ...oscillator, initial: '1,0' })).toMatch(/initial must be a list/);
    expect(await messageOf({ ...oscillator, initial: null })).toMatch(/initial must be a list/);
  });

  it('a misspelt option is refused with the right one suggested', async () => {
    expect(await messageOf({ hamiltonain: 'q', initial: [1, 0] })).toBe('simulator: unknown option "hamiltonain"; did you mean "hamiltonian"?');
    expect(await messageOf({ colour: 1 })).toMatch(/unknown option "colour"$/);
    expect(await messageOf({ ...oscillator, initial: [1, 0], views: ['time'], timePlot: {} })).toBe('');
    expect(await messageOf(7)).toBe('simulator: pass an options object, e.g. simulator({hamiltonian, initial})');
  });

  it('views default to the time plot, are heard before the model is built, and unknown ones are refused', async () => {
    expect((await parseSimulatorOptions({ ...oscillator, initial: [1, 0] })).views).toEqual(['time']);
    const heard: unknown[] = [];
    const phase = { layout: 'multiples' as const };
    const settings = await parseSimulatorOptions({ ...oscillator, initial: [1, 0], views: ['phase', 'time'], phase }, {}, (views, options) => heard.push(views, options.phase));
    expect(settings.views).toEqual(['phase', 'time']);
    expect(settings.viewOptions.phase).toBe(phase);
    expect(heard).toEqual([['phase', 'time'], phase]);
    // A model that cannot be built fails after the views were heard, so their modules load while it builds.
    const early: unknown[] = [];
    await expect(parseSimulatorOptions({ hamiltonian: 'p^2/2 +* q', initial: [1, 0] }, {}, (views) => early.push(views))).rejects.toThrow(/^simulator: /);
    expect(early).toEqual([['time']]);
    expect(await messageOf({ ...oscillator, initial: [1, 0], views: ['time', 'fft'] })).toBe('simulator: unknown view "fft"; choose from time, trajectory, phase, spectrum');
  });

  it('speed, dt, dof and capacity are refused beyond their bounds, naming the option', async () => {
    const base = { ...oscillator, initial: [1, 0] };
    expect(await messageOf({ ...base, speed: 1e308 })).toBe('simulator: speed = 1e+308 is above the largest the book allows, 100000 time units per second');
    expect(await messageOf({ ...base, speed: -1 })).toBe('simulator: speed must be a positive number of time units per second, not -1');
    expect(await messageOf({ ...base, dt: 1e-12 })).toBe('simulator: dt = 1e-12 is below the smallest the book allows, 1e-9');
    expect(await messageOf({ ...base, dof: 201 })).toMatch(/^simulator: dof = 201 is above the largest the book allows/);
    expect(await messageOf({ ...base, capacity: 1.5 })).toBe('simulator: capacity must be a whole number of rows, at least 2, not 1.5');
    expect(await messageOf({ ...base, every: 0 })).toBe('simulator: the sampling interval must be a whole number of steps ≥ 1, not 0');
    expect(await messageOf({ ...base, invalidation: true })).toBe("simulator: invalidation must be the cell's invalidation promise, not true");
    const settings = await parseSimulatorOptions({ ...base, dt: 0.01, speed: 3, capacity: 500, autoplay: false, label: 'L' });
    expect(settings).toMatchObject({ speed: 3, autoplay: false, label: 'L' });
    expect(settings.simulation.dt).toBe(0.01);
    expect(settings.simulation.record.capacity).toBe(500);
    // The widget's dt field makes the same simulation with another step; a bad one is one line too.
    expect(settings.withDt(0.02).dt).toBe(0.02);
    expect(() => settings.withDt(-1)).toThrow(new InputError('simulator: dt must be a positive number, not -1'));
  });

  it('derived {I: (t, x, H) => …} hands each trajectory its own state and H', async () => {
    const derived = { I: (t: number, x: Float64Array, H: number) => H / 2 + x[0] * 0 + t * 0, Q: (_t: number, [q]: Float64Array) => q };
    const { simulation } = await parseSimulatorOptions({ ...oscillator, initial: [[1, 0], [3, 4]], derived });
    expect(simulation.record.columns).toEqual(['t', 'q[0]', 'p[0]', 'q[1]', 'p[1]', 'H[0]', 'I[0]', 'Q[0]', 'H[1]', 'I[1]', 'Q[1]']);
    // H = (q² + p²)/2 = 12.5 at (3, 4).
    expect(simulation.record.get(0, simulation.record.columnIndex('I[1]'))).toBeCloseTo(12.5 / 2, 12);
    expect(simulation.record.get(0, simulation.record.columnIndex('Q[1]'))).toBe(3);
  });

  it('derived series may not take the names of t, H or the state, and must be functions that evaluate', async () => {
    const base = { ...oscillator, initial: [1, 0] };
    expect(await messageOf({ ...base, derived: { q: () => 1 } })).toBe('simulator: the derived series "q" has the name of a state component');
    expect(await messageOf({ ...base, derived: { H: () => 1 } })).toMatch(/the name of the energy/);
    expect(await messageOf({ ...base, derived: { I: 3 } })).toBe('simulator: derived.I must be a function (t, x, H) => number');
    expect(await messageOf({ ...base, derived: 5 })).toMatch(/derived must be an object/);
    expect(await messageOf({ ...base, derived: { I: () => NaN } })).toBe('simulator: the derived series I fails at the initial state: it is NaN');
    // log(−1) is NaN in H; the field, ṗ = −1/q, is finite there.
    expect(await messageOf({ hamiltonian: 'p^2/2 + log(q)', initial: [-1, 0] })).toBe('simulator: H fails at the initial state: it is NaN');
  });

  it('the default capacity is what a memory budget holds, capped at a million rows', async () => {
    expect(defaultCapacity(4)).toBe(MAX_ROWS);
    const model = await canonicalEquations({ dof: 2, hamiltonian: 'px^2 + py^2 + 30/sqrt(x^2+y^2)', coordinates: ['x', 'y'], momenta: ['px', 'py'] });
    const width = recordWidth(model, 1000, 0);
    expect(width).toBe(1 + 1000 * 5);
    expect(defaultCapacity(width) * width * 8).toBeLessThanOrEqual(RECORD_BYTES);
    const initial = Array.from({ length: 1000 }, (_, j) => [10, j * 1e-3, 0, 1]);
    expect((await parseSimulatorOptions({ model, initial })).simulation.record.capacity).toBe(defaultCapacity(width));
  });

  it('oneLine(error) keeps the first line of a message', () => {
    expect(oneLine(new Error('bad H\n  at line 2'))).toBe('bad H');
    expect(oneLine('plain')).toBe('plain');
  });
});
