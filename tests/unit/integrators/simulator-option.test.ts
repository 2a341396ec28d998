/**
 * The simulator's `method` option: checked with one-line messages, carried
 * into the model it builds, and recorded in the meta of its JSON download
 * (exportMeta), with the adaptive method's tolerances.
 */
import { describe, expect, it } from 'vitest';
import { canonicalEquations } from '../../../widgets/core/canonical-equations.ts';
import { exportMeta } from '../../../widgets/core/export-meta.ts';
import { Simulation } from '../../../widgets/core/simulation.ts';
import { modelSummary } from '../../../widgets/core/summary.ts';
import { checkOptionNames, modelSpec } from '../../../widgets/simulator/options.ts';

describe('simulator option method', { timeout: 30_000 }, () => {
  it('is a known option, and RK 3/8 leaves the spec as it was', () => {
    expect(() => checkOptionNames({ hamiltonian: 'p^2/2', initial: [0, 1], method: 'verlet', rtol: 1e-8, atol: 1e-12 })).not.toThrow();
    expect(modelSpec({ hamiltonian: 'p^2/2 + q^2/2', initial: [1, 0] })).not.toHaveProperty('method');
    expect(modelSpec({ hamiltonian: 'p^2/2 + q^2/2', initial: [1, 0], method: 'rk38' })).not.toHaveProperty('method');
  });

  it.each(['verlet', 'yoshida4', 'midpoint'])('%s is recorded in the JSON meta of the simulation it runs', async (method) => {
    const model = await canonicalEquations(modelSpec({ hamiltonian: 'p^2/2 - cos(q)', initial: [1, 0], method }));
    const simulation = new Simulation(model, { initial: [1, 0], dt: 0.01 });
    simulation.run(100);
    const meta = exportMeta(simulation);
    expect(meta.method).toBe(method);
    // The cells' inspector names the method of a model that has one.
    expect(modelSummary(model)).toBe(`Model: 1 DOF, exact derivatives, ${method}, H = p^2/2 - cos(q)`);
    expect(Object.keys(meta).slice(0, 6)).toEqual(['hamiltonian', 'params', 'dof', 'dt', 'method', 'every']);
    // The run is the method's: energy within its bounded error of H₀ = −cos 1 (a check that it ran, not a bound to tune).
    const h = simulation.record.column('H');
    expect(Math.abs(h[h.length - 1] - h[0])).toBeLessThan(1e-3);
  });

  it('adaptive records its tolerances after the method', async () => {
    const model = await canonicalEquations(modelSpec({ hamiltonian: 'p^2/2 - cos(q)', initial: [1, 0], method: 'adaptive', rtol: 1e-8 }));
    const simulation = new Simulation(model, { initial: [1, 0], dt: 0.01 });
    simulation.run(10);
    const meta = exportMeta(simulation);
    expect(Object.keys(meta).slice(4, 8)).toEqual(['method', 'rtol', 'atol', 'every']);
    expect(meta).toMatchObject({ method: 'adaptive', rtol: 1e-8, atol: 1e-12 });
  });

  it('a bad choice is one line naming the simulator', () => {
    expect(() => modelSpec({ hamiltonian: 'p^2/2', initial: [0, 1], method: 'euler' })).toThrow(
      'simulator: the method must be one of rk38, verlet, yoshida4, midpoint, adaptive, not "euler"',
    );
    expect(() => modelSpec({ hamiltonian: 'p^2/2', initial: [0, 1], method: 'verlet', rtol: 1e-6 })).toThrow(/^simulator: rtol and atol are tolerances of the adaptive method, not of verlet$/);
  });
});
