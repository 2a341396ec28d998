/**
 * Non-Hamiltonian terms (core/model/non-hamiltonian.ts): rates added to
 * Hamilton's equations, ẋ_i = (Ω∇H)_i + term_i, compiled into the fused
 * stepper, and kept out of the canonical checks. Against truth:
 *
 * - the damped oscillator H = (p² + q²)/2 with ṗ += −γp is q̈ + γq̇ + q = 0,
 *   whose underdamped solution from (1, 0) is q = e^{−γt/2}(cos Ωt +
 *   (γ/2Ω) sin Ωt), p = q̇ = −e^{−γt/2} sin(Ωt)/Ω, Ω = √(1 − γ²/4) (Landau &
 *   Lifshitz, *Mechanics*, §25);
 * - its flow is linear with a Jacobian of trace −γ, so det M = e^{−γT}
 *   (Liouville's formula), and MᵀΩM − Ω = (det M − 1)Ω for one degree of
 *   freedom: the symplectic defect is |e^{−γT} − 1|;
 * - the field of a model, written here by hand from H and the terms.
 */
import { describe, expect, it } from 'vitest';
import { symplecticCheck } from '../../../../core/analysis/flow-map.ts';
import { driftCheck, energyDrift } from '../../../../core/analysis/energy-drift.ts';
import { InputError } from '../../../../core/errors.ts';
import { methodChoice } from '../../../../core/integrators/methods.ts';
import { rk38 } from '../../../../core/integrators/rk38.ts';
import { canonicalEquations, type HamiltonianSpec } from '../../../../core/model/canonical-equations.ts';
import { compileModel } from '../../../../core/model/compile-model.ts';
import { isCompiledModel, modelKey, type CompiledModel, type CompiledModelStore } from '../../../../core/model/compiled-model.ts';
import type { Model } from '../../../../core/types.ts';
import { judge } from '../../../../widgets/chapter/theory-check/check-verdict.ts';
import { modelFromPortable, portableModel } from '../../../../widgets/simulator/portable-model.ts';

const OSCILLATOR = '(p^2 + q^2)/2';
const DAMPED = { dof: 1, hamiltonian: OSCILLATOR, params: { gamma: 0.1 }, nonHamiltonian: { p: '-gamma*p' } } satisfies HamiltonianSpec;

/** The underdamped solution of q̈ + γq̇ + q = 0 from q = 1, q̇ = 0, as (q, p = q̇). */
function dampedExact(gamma: number, t: number): [number, number] {
  const omega = Math.sqrt(1 - gamma ** 2 / 4);
  const decay = Math.exp((-gamma * t) / 2);
  return [decay * (Math.cos(omega * t) + (gamma / (2 * omega)) * Math.sin(omega * t)), (-decay * Math.sin(omega * t)) / omega];
}

/** The state after `steps` steps of dt of the model's own stepper, from `x0`. */
function run(model: Model, x0: readonly number[], dt: number, steps: number): Float64Array {
  const x = Float64Array.from(x0);
  expect(model.stepper.advance(x, 1, model.params, 0, 0, dt, steps)).toBe(steps);
  return x;
}

/** The rejection of a build, which must be an InputError of one line. */
async function refusal(spec: HamiltonianSpec | Promise<unknown>): Promise<string> {
  const error = await (spec instanceof Promise ? spec : canonicalEquations(spec)).then(
    () => undefined,
    (e: unknown) => e,
  );
  expect(error).toBeInstanceOf(InputError);
  const message = (error as Error).message;
  expect(message).not.toContain('\n');
  return message;
}

describe('a model with a non-Hamiltonian term', () => {
  it('integrates the damped oscillator to its closed form at t = 10, within RK 3/8’s error estimated from a run at dt/2', async () => {
    const model = await canonicalEquations(DAMPED);
    const exact = dampedExact(0.1, 10);
    const full = run(model, [1, 0], 0.01, 1000);
    const half = run(model, [1, 0], 0.005, 2000);
    for (let i = 0; i < 2; i++) {
      // RK 3/8 is of fourth order: the error at dt is 16/15 of the change to dt/2, allowed twice, plus rounding over 1000 steps.
      const richardson = (16 / 15) * Math.abs(full[i] - half[i]);
      expect(Math.abs(full[i] - exact[i])).toBeLessThan(2 * richardson + 1e-13);
      // and that estimate is the size of a fourth-order error at dt = 0.01, not of a mistake in the equations
      expect(richardson).toBeLessThan(1e-9);
    }
    // The amplitude has decayed by e^{−γt/2}: the term is in the motion.
    expect(Math.hypot(full[0], full[1])).toBeLessThan(Math.exp(-0.5) * 1.06);
  });

  it('runs by the adaptive method too, through the field, to its tolerance', async () => {
    const model = await canonicalEquations({ ...DAMPED, method: methodChoice('adaptive') });
    const x = run(model, [1, 0], 1, 10);
    const exact = dampedExact(0.1, 10);
    // rtol 1e-9 of the local error per step, summed over the steps it takes (observed: 6e-10)
    for (let i = 0; i < 2; i++) expect(Math.abs(x[i] - exact[i])).toBeLessThan(1e-8);
  });

  it('has the field ω∇H + term, by hand, with terms on coordinates, momenta and in time', async () => {
    const model = await canonicalEquations({
      dof: 2,
      hamiltonian: '(px^2 + py^2)/2 + (x^2 + 4*y^2)/2',
      coordinates: ['x', 'y'],
      momenta: ['px', 'py'],
      params: { gamma: 0.1, f: 0.5 },
      // written out of the state's order, which must not matter
      nonHamiltonian: { py: '-gamma*py + f*sin(t)', px: '-gamma*px', x: 'gamma*(1 - x)' },
    });
    const [gamma, f] = [0.1, 0.5];
    const byHand = (t: number, s: Float64Array, out: Float64Array) => {
      const [x, y, px, py] = s;
      out[0] = px + gamma * (1 - x);
      out[1] = py;
      out[2] = -x - gamma * px;
      out[3] = -4 * y - gamma * py + f * Math.sin(t);
    };
    const state = Float64Array.of(0.3, -1.2, 0.8, 0.25);
    const [rate, expected] = [new Float64Array(4), new Float64Array(4)];
    model.field(0.7, state, rate);
    byHand(0.7, state, expected);
    for (let i = 0; i < 4; i++) expect(rate[i]).toBeCloseTo(expected[i], 15);
    expect(model.nonHamiltonian?.terms).toEqual({ x: 'gamma*(1 - x)', px: '-gamma*px', py: '-gamma*py + f*sin(t)' });
    // The fused stepper integrates that field, its time terms included: the generic RK 3/8 of the hand-written field agrees to rounding.
    const fused = Float64Array.from(state);
    const generic = Float64Array.from(state);
    model.stepper.advance(fused, 1, model.params, 0.2, 3, 0.01, 500);
    rk38(byHand, 4).advance(generic, 1, model.params, 0.2, 3, 0.01, 500);
    for (let i = 0; i < 4; i++) expect(Math.abs(fused[i] - generic[i])).toBeLessThan(1e-13);
  });

  it('reads its parameter live: writing model.params changes the damping without recompiling', async () => {
    const model = await canonicalEquations(DAMPED);
    const { stepper } = model;
    model.params[0] = 0.4;
    const rate = new Float64Array(2);
    model.field(0, Float64Array.of(0, 1), rate);
    expect(Array.from(rate)).toEqual([1, -0.4]);
    expect(model.stepper).toBe(stepper);
    const x = run(model, [1, 0], 0.01, 1000);
    const exact = dampedExact(0.4, 10);
    for (let i = 0; i < 2; i++) expect(Math.abs(x[i] - exact[i])).toBeLessThan(1e-8);
  });

  it('writes the term into Hamilton’s equations, and H without it', async () => {
    const model = await canonicalEquations(DAMPED);
    expect(model.latex!.hamiltonian).toBe('H = \\frac{{ p}^{2}+{ q}^{2}}{2}');
    expect(model.latex!.equations).toEqual([
      '\\dot{q} = \\frac{\\partial H}{\\partial p} =  p',
      '\\dot{p} = -\\frac{\\partial H}{\\partial q} - \\gamma\\cdot p = - q- \\gamma\\cdot p',
    ]);
    expect(model.nonHamiltonian).toEqual({ terms: { p: '-gamma*p' }, latex: { p: '- \\gamma\\cdot p' } });
    // H is H: the term is a rate, not energy
    expect(model.hamiltonian!(0, Float64Array.of(1, 2))).toBe(2.5);
    const undamped = await canonicalEquations({ dof: 1, hamiltonian: OSCILLATOR });
    expect(undamped.nonHamiltonian).toBeUndefined();
  });
});

describe('the compiled model’s key', () => {
  const undamped = { dof: 1, hamiltonian: OSCILLATOR, params: { gamma: 0.1 } };

  it('differs with and without the term, is the same for the same spec, and does not depend on the order the terms were written in', () => {
    expect(modelKey(DAMPED)).not.toBe(modelKey(undamped));
    expect(modelKey({ ...DAMPED, nonHamiltonian: { p: '-gamma*p' } })).toBe(modelKey(DAMPED));
    expect(modelKey({ ...undamped, nonHamiltonian: {} })).toBe(modelKey(undamped));
    expect(modelKey({ ...DAMPED, nonHamiltonian: { p: '-2*gamma*p' } })).not.toBe(modelKey(DAMPED));
    const two = { dof: 2, hamiltonian: '(px^2 + py^2)/2', coordinates: ['x', 'y'], momenta: ['px', 'py'] };
    expect(modelKey({ ...two, nonHamiltonian: { px: '-px', py: '-py' } })).toBe(modelKey({ ...two, nonHamiltonian: { py: '-py', px: '-px' } }));
  });

  it('keeps a store from handing the model without the term to a spec with it, or the other way round', async () => {
    const kept = new Map<string, CompiledModel>();
    const compiles: string[] = [];
    const store: CompiledModelStore = { get: (key) => kept.get(key), put: (m) => void kept.set(m.key, m) };
    const compile = (spec: Parameters<typeof compileModel>[0]) => {
      compiles.push(modelKey(spec));
      return compileModel(spec);
    };
    const plain = await canonicalEquations(undamped, { store, compile });
    const damped = await canonicalEquations(DAMPED, { store, compile });
    await canonicalEquations(DAMPED, { store, compile });
    await canonicalEquations(undamped, { store, compile });
    expect(compiles).toEqual([modelKey(undamped), modelKey(DAMPED)]);
    expect(plain.nonHamiltonian).toBeUndefined();
    expect(damped.nonHamiltonian).toBeDefined();
    // and data compiled for one key is never good for the other
    const [a, b] = [kept.get(modelKey(undamped))!, kept.get(modelKey(DAMPED))!];
    expect(isCompiledModel(a, modelKey(DAMPED))).toBe(false);
    expect(isCompiledModel(b, modelKey(undamped))).toBe(false);
    expect(isCompiledModel(b, modelKey(DAMPED))).toBe(true);
    // a damaged record of the terms means "compile again"
    expect(isCompiledModel({ ...b, nonHamiltonian: { terms: { v: '-v' } } }, b.key)).toBe(false);
    expect(isCompiledModel({ ...b, nonHamiltonian: { terms: {} } }, b.key)).toBe(false);
  });
});

describe('refusals, each an InputError of one sentence', () => {
  it('an unknown name in a term names the term', async () => {
    expect(await refusal({ ...DAMPED, nonHamiltonian: { p: '-gama*p' } })).toMatch(/^unknown name gama in the non-Hamiltonian term of p: give it a value as a parameter$/);
    expect(await refusal({ ...DAMPED, nonHamiltonian: { p: '-gamma*(p' } })).toMatch(/^syntax error in the non-Hamiltonian term of p/);
  });

  it('a key that is not a state name lists the names', async () => {
    expect(await refusal({ ...DAMPED, nonHamiltonian: { v: '-gamma*v' } })).toBe('the non-Hamiltonian term of v names no state component: the state is q, p');
  });

  it('a term with H as a JS function, a function object, a vector field or a gradient', async () => {
    const needs = /^a non-Hamiltonian term needs H as a math expression/;
    expect(await refusal({ ...DAMPED, hamiltonian: '(t, x) => (x[0]**2 + x[1]**2)/2' })).toMatch(needs);
    expect(await refusal({ ...DAMPED, hamiltonian: (_t: number, x: Float64Array) => (x[0] ** 2 + x[1] ** 2) / 2 })).toMatch(needs);
    const field = (_t: number, x: Float64Array, out: Float64Array) => {
      out[0] = x[1];
      out[1] = -x[0];
    };
    expect(await refusal({ dof: 1, vectorField: field, nonHamiltonian: { p: '-p' } })).toMatch(/vector field is the whole of dx\/dt, so write the term into it/);
    expect(await refusal({ dof: 1, gradient: field, nonHamiltonian: { p: '-p' } })).toMatch(needs);
  });

  it.each(['verlet', 'yoshida4', 'midpoint'] as const)('a term with the method %s, also when compiled directly', async (name) => {
    const message = await refusal({ ...DAMPED, method: methodChoice(name) });
    expect(message).toMatch(new RegExp(`^the method ${name} .*, and .*this model's non-Hamiltonian term \\(-gamma\\*p in dp/dt\\).*; use rk38 or adaptive$`));
    expect(await refusal(compileModel({ ...DAMPED, hamiltonian: OSCILLATOR, method: name }))).toBe(message);
  });
});

describe('the canonical checks leave the term out', () => {
  const T = 10;
  const [epsilon, dt] = [1e-5, 0.01];
  const flowOf = (model: Model, h: number) => (x0: Float64Array) => run(model, Array.from(x0), h, Math.round(T / h));

  /** The action–angle chapter's check of MᵀΩM = Ω (content/action-angle.mdx), with the validity symplecticCheck states. */
  const canonicalVerdict = (model: Model) => {
    const full = symplecticCheck(flowOf(model, dt), [1, 0], epsilon, model);
    const half = symplecticCheck(flowOf(model, dt / 2), [1, 0], epsilon, model);
    const rounding = Math.round(T / dt) * 2 ** -52 / epsilon;
    return {
      full,
      verdict: judge({
        measured: full.defect,
        predicted: 0,
        validity: full.validity,
        errors: {
          formula: { value: 0, why: 'every Hamiltonian flow is symplectic' },
          integration: { value: 2 * (16 / 15) * Math.abs(full.defect - half.defect), why: 'RK 3/8, from Δt to Δt/2' },
          measurement: { value: 2 * full.truncation + rounding, why: 'central differences and rounding' },
        },
      }),
    };
  };

  it('symplecticCheck: the damped model is outside validity, with the term named; its defect is Liouville’s |e^{−γT} − 1|', async () => {
    const { full, verdict } = canonicalVerdict(await canonicalEquations(DAMPED));
    expect(verdict.verdict).toBe('outside');
    expect(verdict.reason).toBe('the model has a non-Hamiltonian term (-gamma*p in dp/dt), so its flow is not canonical');
    expect(Math.abs(full.defect - Math.abs(Math.exp(-0.1 * T) - 1))).toBeLessThan(1e-6);
  });

  it('symplecticCheck: the undamped model still agrees, as does a bare flow given no model', async () => {
    const model = await canonicalEquations({ dof: 1, hamiltonian: OSCILLATOR, params: { gamma: 0.1 } });
    const { full, verdict } = canonicalVerdict(model);
    expect(full.validity.every((c) => c.holds)).toBe(true);
    expect(verdict.verdict).toBe('agrees');
    expect(symplecticCheck(flowOf(model, dt), [1, 0], epsilon).validity.every((c) => c.holds)).toBe(true);
  });

  it('the energy-drift law says H is not conserved by the damped model, not that the integrator drifts', async () => {
    const model = await canonicalEquations(DAMPED);
    const h = model.hamiltonian!;
    const x = Float64Array.of(1, 0);
    const h0 = h(0, x);
    const e = Float64Array.from({ length: 2000 }, (_, k) => {
      model.stepper.advance(x, 1, model.params, 0, k, dt, 1);
      return (h((k + 1) * dt, x) - h0) / h0;
    });
    const verdict = judge(driftCheck(energyDrift(e, dt), { method: 'rk38', dt, rate: 1, autonomous: true, nonHamiltonian: model.nonHamiltonian }));
    expect(verdict.verdict).toBe('outside');
    expect(verdict.reason).toMatch(/^the model has a non-Hamiltonian term \(-gamma\*p in dp\/dt\), so the exact motion does not conserve H/);
  });
});

describe('the damped model in a worker', () => {
  it('is portable, and rebuilt from its source text it computes the same numbers bit for bit', async () => {
    const model = await canonicalEquations(DAMPED);
    const source = portableModel(model);
    expect(source).not.toBeNull();
    const copy = modelFromPortable(source!, Float64Array.from(model.params));
    const [here, there] = [Float64Array.of(1, 0, 0.5, -0.3), Float64Array.of(1, 0, 0.5, -0.3)];
    model.stepper.advance(here, 2, model.params, 0, 0, 0.01, 1000);
    copy.stepper.advance(there, 2, copy.params, 0, 0, 0.01, 1000);
    expect(Array.from(there)).toEqual(Array.from(here));
    expect(here[0]).not.toBe(1);
    // and the worker's live parameter array damps it too
    copy.params[0] = 0.4;
    const stronger = Float64Array.of(1, 0);
    copy.stepper.advance(stronger, 1, copy.params, 0, 0, 0.01, 1000);
    const exact = dampedExact(0.4, 10);
    for (let i = 0; i < 2; i++) expect(Math.abs(stronger[i] - exact[i])).toBeLessThan(1e-8);
  });
});
