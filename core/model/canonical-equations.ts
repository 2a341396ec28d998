import type { BuildControl } from './build-control.ts';
import { isCompiledModel, modelKey, type CompiledModel, type CompiledModelStore, type ModelKeySpec } from './compiled-model.ts';
import { InputError } from '../errors.ts';
import type { MethodParts } from '../integrators/apply.ts';
import { DEFAULT_METHOD, type MethodChoice } from '../integrators/methods.ts';
import { stateNames } from '../expression/names.ts';
import { compiledParts } from './compiled-parts.ts';
import { gradientField, type OpaqueHamiltonian } from '../js-function/stencil.ts';
import { rk38 } from '../integrators/rk38.ts';
import { withSummary } from '../summary.ts';
import type { HamiltonianFunction, Model, NonHamiltonianTerms, Route, VectorField } from '../types.ts';

/**
 * What defines a model: `hamiltonian` (a math expression, JS function source,
 * or a JS function), or else `vectorField` or `gradient`, which may come with
 * a `hamiltonian` function used only for readouts.
 */
export interface HamiltonianSpec {
  dof: number;
  hamiltonian?: string | OpaqueHamiltonian;
  /** dx/dt written by the author */
  vectorField?: VectorField;
  /** ∇H = (∂H/∂q…, ∂H/∂p…) written by the author */
  gradient?: VectorField;
  params?: Readonly<Record<string, number>>;
  /** names of the coordinates q (default q0…, or q for one degree of freedom) */
  coordinates?: readonly string[];
  /** names of the momenta p (default p0…, or p) */
  momenta?: readonly string[];
  /** 'stencil' forces finite differences for a JS function, to compare routes */
  differentiation?: 'auto' | 'stencil';
  /** the integration method, RK 3/8 by default (integrators/methods.ts) */
  method?: MethodChoice;
  /**
   * Terms added to Hamilton's equations, by state name: ẋ_i = (Ω∇H)_i +
   * term_i, e.g. `{p: '-gamma*p'}` for a damped oscillator. Each is a math
   * expression in H's syntax, names and parameters. Only with H as a math
   * expression, and only for the methods rk38 and adaptive; the model then
   * carries `nonHamiltonian`, and the canonical checks leave it out
   * (model/non-hamiltonian.ts).
   */
  nonHamiltonian?: NonHamiltonianTerms;
}

export interface BuildOptions extends BuildControl {
  /**
   * Compiled models kept from earlier: the page's build-time data, the CLI's
   * cache. A model found there is built without loading mathjs or acorn; one
   * compiled here is put there.
   */
  store?: CompiledModelStore;
  /** How to compile on a miss: by default the core's compileModel, loaded on first use. */
  compile?: (spec: ModelKeySpec, control?: BuildControl) => Promise<CompiledModel>;
}

type TermRules = typeof import('./non-hamiltonian.ts');

/** The rules of non-Hamiltonian terms, loaded when a spec first has some: no page without one carries them. */
let termRules: Promise<TermRules> | undefined;

/** Hands over the rules where nothing can be loaded on demand (the build, whose module loader is closed when cells run). */
export function provideTermRules(rules: TermRules): void {
  termRules = Promise.resolve(rules);
}

/**
 * Hamilton's canonical equations q̇ = ∂H/∂p, ṗ = −∂H/∂q (the paper's eq. 4)
 * for a model, by the most exact route its definition allows (see
 * compileModel): exact symbolic derivatives and a fused stepper for a math
 * expression or a translatable JS function, 5-point central differences for
 * any other JS function, and a vector field or gradient as given. A spec's
 * non-Hamiltonian terms are added to these equations (model/non-hamiltonian.ts).
 */
export async function canonicalEquations(spec: HamiltonianSpec, options: BuildOptions = {}): Promise<Model> {
  const fields = [spec.vectorField, spec.gradient].filter((v) => v !== undefined).length;
  if (fields > 1 || (fields === 0 && spec.hamiltonian === undefined)) {
    throw new InputError('give a hamiltonian, or one of vectorField and gradient (with an optional hamiltonian function for readouts)');
  }
  const { names } = stateNames(spec.dof, spec.coordinates, spec.momenta);
  // Refused here, before anything is compiled or looked up, so that the reader hears of the term, not of the compile.
  if (spec.nonHamiltonian !== undefined) {
    const { refusedOrTerms } = await (termRules ??= import('./non-hamiltonian.ts'));
    refusedOrTerms(spec, names, (spec.method ?? DEFAULT_METHOD).name);
  }
  if (spec.vectorField) return fieldModel(spec, names, 'vector-field', spec.vectorField, String(spec.vectorField));
  if (spec.gradient) {
    return fieldModel(spec, names, 'gradient', gradientField(spec.gradient, 2 * spec.dof), String(spec.gradient));
  }
  const hamiltonian = spec.hamiltonian!;
  const method = spec.method ?? DEFAULT_METHOD;
  const compiled = await compiledModelFor({ ...spec, hamiltonian, method }, options);
  const { model, parts } = compiledParts(compiled, spec.params, hamiltonian, method);
  return runBy(model, method, parts);
}

/**
 * `model`, built with RK 3/8's stepper, run by `method`. The other methods'
 * code loads only for a model that asks for one: the book's models run RK
 * 3/8, and a chapter whose first view builds one fetches that much less.
 */
async function runBy(model: Model, method: MethodChoice, parts: MethodParts = {}): Promise<Model> {
  if (method.name === 'rk38') return model;
  const { applyMethod } = await import('../integrators/apply.ts');
  return applyMethod(model, method, parts);
}

/**
 * The compiled form of H's model: from `options.store` when it holds a good
 * one, else compiled now (loading mathjs or acorn) and put there.
 */
export async function compiledModelFor(spec: ModelKeySpec, options: BuildOptions = {}): Promise<CompiledModel> {
  const key = modelKey(spec);
  const { store } = options;
  const stored = await store?.get(key);
  if (isCompiledModel(stored, key)) return stored;
  const compile = options.compile ?? (await import('./compile-model.ts')).compileModel;
  const compiled = await compile(spec, { signal: options.signal, progress: options.progress });
  await store?.put?.(compiled);
  return compiled;
}

function fieldModel(spec: HamiltonianSpec, names: string[], route: Route, field: VectorField, source: string): Promise<Model> {
  const dim = 2 * spec.dof;
  const params = spec.params ?? {};
  const h = spec.hamiltonian;
  const model = withSummary({
    dof: spec.dof,
    dim,
    names,
    paramNames: Object.keys(params),
    params: Float64Array.from(Object.keys(params), (n) => params[n]),
    route,
    accuracy: 'the vector field is the author’s own, so its accuracy is theirs; the integration adds the RK 3/8 error, O(dt⁴)',
    source,
    stepper: rk38(field, dim),
    field,
    hamiltonian: typeof h === 'function' ? opaqueAsHamiltonian(h, dim) : undefined,
  });
  return runBy(model, spec.method ?? DEFAULT_METHOD);
}

function opaqueAsHamiltonian(h: OpaqueHamiltonian, dim: number): HamiltonianFunction {
  const scratch = new Float64Array(dim);
  return (t, x, offset = 0) => {
    for (let i = 0; i < dim; i++) scratch[i] = x[offset + i];
    return h(t, scratch);
  };
}
