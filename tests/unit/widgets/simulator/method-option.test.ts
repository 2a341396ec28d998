/**
 * The simulator's `method` option: checked with one-line messages, carried
 * into the model it builds, and recorded in the meta of its JSON download
 * (exportMeta), with the adaptive method's tolerances. With a ready `model`
 * the method is applied to it where it can be (the midpoint rule and the
 * adaptive method need only the field) and refused in one line where it
 * cannot, never dropped.
 */
import { describe, expect, it } from 'vitest';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { InputError } from '../../../../core/errors.ts';
import { exportMeta } from '../../../../core/tables/export-meta.ts';
import { modelSummary } from '../../../../core/summary.ts';
import { modelSpec, parseSimulatorOptions } from '../../../../widgets/simulator/options.ts';

/** The one-line InputError parseSimulatorOptions rejects `raw` with. */
async function messageOf(raw: unknown): Promise<string> {
  const error = await parseSimulatorOptions(raw).then(() => null, (e: unknown) => e);
  expect(error).toBeInstanceOf(InputError);
  const { message } = error as Error;
  // One line that fits under a cell, as the e2e tests hold every simulator message to.
  expect(message).not.toContain('\n');
  expect(message.length).toBeLessThan(190);
  return message;
}

describe('simulator option method', () => {
  it('is a known option, and RK 3/8 leaves the spec as it was', async () => {
    const settings = await parseSimulatorOptions({ hamiltonian: 'p^2/2', initial: [0, 1], method: 'adaptive', rtol: 1e-8, atol: 1e-12 });
    expect(settings.model.method).toEqual({ name: 'adaptive', rtol: 1e-8, atol: 1e-12 });
    expect(modelSpec({ hamiltonian: 'p^2/2 + q^2/2', initial: [1, 0] })).not.toHaveProperty('method');
    expect(modelSpec({ hamiltonian: 'p^2/2 + q^2/2', initial: [1, 0], method: 'rk38' })).not.toHaveProperty('method');
  });

  it.each(['verlet', 'yoshida4', 'midpoint'])('%s is recorded in the JSON meta of the simulation it runs', async (method) => {
    const { model, simulation } = await parseSimulatorOptions({ hamiltonian: 'p^2/2 - cos(q)', initial: [1, 0], method, dt: 0.01 });
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
    const { simulation } = await parseSimulatorOptions({ hamiltonian: 'p^2/2 - cos(q)', initial: [1, 0], method: 'adaptive', rtol: 1e-8, dt: 0.01 });
    simulation.run(10);
    const meta = exportMeta(simulation);
    expect(Object.keys(meta).slice(4, 8)).toEqual(['method', 'rtol', 'atol', 'every']);
    expect(meta).toMatchObject({ method: 'adaptive', rtol: 1e-8, atol: 1e-12 });
  });

  it('a bad choice is one line naming the simulator', async () => {
    expect(await messageOf({ hamiltonian: 'p^2/2', initial: [0, 1], method: 'euler' })).toBe(
      'simulator: the method must be one of rk38, verlet, yoshida4, midpoint, adaptive, not "euler"',
    );
    expect(await messageOf({ hamiltonian: 'p^2/2', initial: [0, 1], method: 'verlet', rtol: 1e-6 })).toBe('simulator: rtol and atol are tolerances of the adaptive method, not of verlet');
    // modelSpec, which the build reads a chapter's cells with, says the same.
    expect(() => modelSpec({ hamiltonian: 'p^2/2', initial: [0, 1], method: 'euler' })).toThrow(/^simulator: the method must be one of/);
  });
});

/**
 * The harmonic oscillator H = (q² + p²)/2 from (1, 0), whose steps every
 * method here takes in closed form: it is linear, so one step multiplies the
 * state by a fixed matrix.
 */
describe('simulator option method with a ready model', () => {
  const oscillator = () => canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + q^2/2' });
  const h = 0.1;
  const steps = 1000;
  const ends = (simulation: { record: { column(name: string): Float64Array } }) => {
    const [q, p, H] = ['q', 'p', 'H'].map((c) => simulation.record.column(c));
    return { q: q[q.length - 1], p: p[p.length - 1], drift: H[H.length - 1] / H[0] - 1 };
  };

  it('without a method the model runs as built: RK 3/8, whose energy shrinks by |R(ih)|² per step', async () => {
    const model = await oscillator();
    const settings = await parseSimulatorOptions({ model, initial: [1, 0], dt: h });
    expect(settings.model).toBe(model);
    settings.simulation.run(steps);
    // Every 4-stage 4th-order Runge–Kutta method has R(z) = 1 + z + z²/2 + z³/6 + z⁴/24, so on this
    // rotation |R(ih)|² = 1 − h⁶/72 + h⁸/576 exactly (Hairer, Nørsett & Wanner, Solving ODEs I, §IV.2);
    // only rounding separates the drift from the N-th power, well under 1e-12 in 1000 steps.
    const predicted = (1 - h ** 6 / 72 + h ** 8 / 576) ** steps - 1;
    expect(Math.abs(ends(settings.simulation).drift - predicted)).toBeLessThan(1e-12);
    expect(predicted).toBeLessThan(-1e-5);
  });

  it('method: midpoint is applied to it: a rotation by 2·atan(h/2) per step, H kept to rounding', async () => {
    const model = await oscillator();
    const settings = await parseSimulatorOptions({ model, initial: [1, 0], dt: h, method: 'midpoint' });
    expect(settings.model.method).toEqual({ name: 'midpoint' });
    expect(settings.model.accuracy).toContain('its Newton Jacobian by central differences');
    expect(model.method).toBeUndefined();
    settings.simulation.run(steps);
    // The implicit midpoint rule is the Cayley transform of the rotation generator: each step is an exact
    // rotation by θ = 2·atan(h/2), so it keeps the quadratic H (Hairer, Lubich & Wanner, Geometric
    // Numerical Integration, §IV.2). Newton solves the linear step to rounding, so only 1000 steps'
    // rounding, well under 1e-11, remains, where RK 3/8 (above) drifts by 1.4e-5.
    const angle = steps * 2 * Math.atan(h / 2);
    const end = ends(settings.simulation);
    expect(Math.abs(end.q - Math.cos(angle))).toBeLessThan(1e-11);
    expect(Math.abs(end.p + Math.sin(angle))).toBeLessThan(1e-11);
    expect(Math.abs(end.drift)).toBeLessThan(1e-12);
    expect(exportMeta(settings.simulation).method).toBe('midpoint');
  });

  it('method: adaptive is applied to it, with its tolerances: q(10) = cos 10 where RK 3/8 at this dt is off by 1e-3', async () => {
    const model = await oscillator();
    const run = async (method?: string) => {
      const settings = await parseSimulatorOptions({ model, initial: [1, 0], dt: 0.5, method, ...(method ? { rtol: 1e-10 } : {}) });
      settings.simulation.run(20);
      return { settings, error: Math.abs(ends(settings.simulation).q - Math.cos(10)) };
    };
    const adaptive = await run('adaptive');
    expect(adaptive.settings.model.method).toEqual({ name: 'adaptive', rtol: 1e-10, atol: 1e-12 });
    // Dormand–Prince holds each step's local error below atol + rtol·|x| ≈ 1e-10; fewer than a hundred
    // such steps in t ≤ 10 leave the global error under 1e-8.
    expect(adaptive.error).toBeLessThan(1e-8);
    // The model as built (RK 3/8 with dt = 0.5): a phase error of about h⁵/120 per step, 20 steps.
    expect((await run()).error).toBeGreaterThan(1e-4);
  });

  it('left out, the method is the model’s own, with its tolerances unless rtol or atol are given', async () => {
    const adaptive = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + q^2/2', method: { name: 'adaptive', rtol: 1e-6, atol: 1e-9 } });
    expect((await parseSimulatorOptions({ model: adaptive, initial: [1, 0] })).model).toBe(adaptive);
    expect((await parseSimulatorOptions({ model: adaptive, initial: [1, 0], method: 'adaptive', rtol: 1e-6, atol: 1e-9 })).model).toBe(adaptive);
    expect((await parseSimulatorOptions({ model: adaptive, initial: [1, 0], rtol: 1e-8 })).model.method).toEqual({ name: 'adaptive', rtol: 1e-8, atol: 1e-9 });
    expect(await messageOf({ model: await oscillator(), initial: [1, 0], rtol: 1e-8 })).toBe('simulator: rtol and atol are tolerances of the adaptive method, not of rk38');
  });

  it('RK 3/8 and the splittings run code generated with the model: for a model built otherwise, one line says where to ask', async () => {
    const model = await oscillator();
    expect(await messageOf({ model, initial: [1, 0], method: 'verlet' })).toBe(
      "simulator: the model was built for rk38, and verlet needs code generated with the model; pass method: 'verlet' to canonicalEquations({…}), or hamiltonian instead of model",
    );
    const verlet = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + q^2/2', method: { name: 'verlet' } });
    expect((await parseSimulatorOptions({ model: verlet, initial: [1, 0], method: 'verlet' })).model).toBe(verlet);
    expect(await messageOf({ model: verlet, initial: [1, 0], method: 'rk38' })).toMatch(/^simulator: the model was built for verlet, and rk38 needs code generated with the model; /);
    expect(await messageOf({ model: verlet, initial: [1, 0], method: 'yoshida4' })).toMatch(/^simulator: the model was built for verlet, and yoshida4 needs code generated with the model; /);
    // H that cannot be shown separable: the reason comes first, since no model of it takes a splitting.
    const opaque = await canonicalEquations({ dof: 1, hamiltonian: (_t: number, x: Float64Array) => Math.hypot(x[0], x[1]) ** 2 / 2, differentiation: 'stencil' });
    expect(await messageOf({ model: opaque, initial: [1, 0], method: 'verlet' })).toBe(
      'simulator: the method verlet needs H = T(p) + V(q, t), and H is an opaque JavaScript function, whose separation into T(p) + V(q, t) cannot be shown; use rk38, midpoint or adaptive',
    );
    expect((await parseSimulatorOptions({ model: opaque, initial: [1, 0], method: 'midpoint' })).model.method).toEqual({ name: 'midpoint' });
  });

  it('options that build a model are refused beside a ready one, and a model that is not one is named', async () => {
    const model = await oscillator();
    expect(await messageOf({ model, initial: [1, 0], hamiltonian: 'p^2/2' })).toBe(
      'simulator: hamiltonian goes into building a model, and a model is given; give hamiltonian to canonicalEquations({…}), or leave out model',
    );
    expect(await messageOf({ model, initial: [1, 0], params: { k: 2 } })).toMatch(/^simulator: params goes into building a model, and a model is given/);
    expect(await messageOf({ model, initial: [1, 0], dof: 2 })).toBe("simulator: dof 2 does not match the model's 1");
    expect(await messageOf({ model: Promise.resolve(model), initial: [1, 0] })).toBe(
      'simulator: model must be a model from canonicalEquations({…}), not a promise; give the model a cell of its own, model = canonicalEquations({…}), and pass that',
    );
    expect(await messageOf({ model: 'p^2/2', initial: [1, 0] })).toBe('simulator: model must be a model from canonicalEquations({…}), not p^2/2');
  });
});
