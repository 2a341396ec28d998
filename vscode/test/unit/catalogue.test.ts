import { describe, expect, test } from 'vitest';
import { optionsAt } from '../../src/analyzer/catalogue.ts';
import { pageContext, createLibrary } from '../../../widgets/index.ts';
import { realCatalogue } from './support.ts';

describe('generateCatalogue(root)', () => {
  test('lists exactly the entries of createLibrary, in its order', () => {
    const names = realCatalogue().builtins.map((b) => b.name);
    expect(names).toEqual(Object.keys(createLibrary(pageContext([]))));
  });

  test("takes simulator's options from SimulatorOptions, with their doc comments and types", () => {
    const simulator = realCatalogue().builtins.find((b) => b.name === 'simulator')!;
    expect(simulator.kind).toBe('function');
    expect(simulator.signature).toBe('simulator(options: SimulatorOptions): Promise<SimulatorElement>');
    expect(simulator.doc).toMatch(/Promise of the widget's element/);
    const initial = simulator.parameters[0].options!.find((o) => o.name === 'initial')!;
    expect(initial).toMatchObject({ optional: false, doc: '[q…, p…], or a list of them for a batch of trajectories' });
    const views = simulator.parameters[0].options!.find((o) => o.name === 'views')!;
    expect(views).toMatchObject({ optional: true, type: 'readonly ("time" | "trajectory" | "phase" | "spectrum")[]' });
  });

  test('follows options-valued options (timePlot) but not values with properties (model)', () => {
    const catalogue = realCatalogue();
    expect(optionsAt(catalogue, 'simulator', 0, ['timePlot']).map((o) => o.name)).toContain('height');
    expect(optionsAt(catalogue, 'simulator', 0, ['model'])).toEqual([]);
  });

  test('a class is constructed, and its options are the argument that takes them', () => {
    const catalogue = realCatalogue();
    const simulation = catalogue.builtins.find((b) => b.name === 'Simulation')!;
    expect(simulation.kind).toBe('class');
    expect(simulation.signature).toMatch(/^new Simulation\(model: Model, options: SimulationOptions\)$/);
    expect(optionsAt(catalogue, 'Simulation', 1, []).map((o) => o.name)).toEqual(['initial', 'dt', 't0', 'every', 'derived', 'energy', 'capacity']);
    expect(optionsAt(catalogue, 'Simulation', 0, [])).toEqual([]);
  });

  test('theoryCheck and tex options', () => {
    const catalogue = realCatalogue();
    expect(optionsAt(catalogue, 'theoryCheck', 0, []).map((o) => o.name)).toEqual(expect.arrayContaining(['label', 'measured', 'predicted', 'relative', 'unit', 'method', 'formula']));
    expect(optionsAt(catalogue, 'tex', 1, []).map((o) => o.name)).toEqual(['display']);
    expect(optionsAt(catalogue, 'nothing', 0, [])).toEqual([]);
  });
});
