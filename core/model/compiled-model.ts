/**
 * A model's canonical equations as plain data: the generated stepper and
 * evaluators as source text, and the LaTeX of H and Hamilton's equations.
 *
 * Compiling (symbolic derivatives with mathjs, translation of a JS function
 * with acorn) is the slow, heavy half of building a model; turning the
 * result into a running model is a few `new Function` calls. Keeping the two
 * apart lets the compile happen where mathjs is at hand — the book's build,
 * the CLI's first run of an H, a worker — and the model be built where it
 * is not: a page before the reader edits anything, the stability chart's
 * worker, a later CLI run. The data is JSON, so it travels in a page, a
 * message or a cache file. This module is the data and its checks;
 * model-from-compiled.ts builds a model from it, compile-model.ts makes it.
 *
 * A compiled model is found by its key, which is everything that decides the
 * generated code: H's source, the degrees of freedom, the names of the state
 * and of the parameters, the route asked for, and any non-Hamiltonian terms.
 * Parameter VALUES are not part of it: the generated code reads them live
 * from an array.
 */
import { CODE_METHODS, type MethodChoice, type MethodName } from '../integrators/methods.ts';
import type { OpaqueHamiltonian } from '../js-function/stencil.ts';
import type { NonHamiltonianPart, NonHamiltonianTerms } from '../types.ts';

/**
 * Bumped whenever the generated code or this layout changes, so that data
 * compiled by another version is never used: it is compiled afresh instead.
 * 3: models may carry non-Hamiltonian terms (`nonHamiltonian`).
 */
export const COMPILED_FORMAT = 3;

/** The routes that start from H and so can be compiled ahead. */
export type CompiledRoute = 'expression' | 'js-translated' | 'js-stencil';

export interface CompiledModel {
  readonly format: typeof COMPILED_FORMAT;
  /** {@link modelKey} of the spec this was compiled from. */
  readonly key: string;
  readonly route: CompiledRoute;
  readonly dof: number;
  /** Names of the state, q's then p's. */
  readonly names: readonly string[];
  readonly paramNames: readonly string[];
  /** H as given, for export metadata (and, for a stencil model, to rebuild the function). */
  readonly source: string;
  /**
   * The method the code was generated for, when it is one that needs code
   * of its own (integrators/methods.ts, CODE_METHODS); absent for RK 3/8,
   * whose code every other method's model carries too.
   */
  readonly method?: 'verlet' | 'yoshida4' | 'midpoint';
  /** Generated code (absent for a stencil model): each is the body of a function returning a factory. */
  readonly code?: {
    /** `return function advance(x, count, P, t0, k0, dt, steps) {…}` */
    readonly stepper: string;
    /** `return function (P) { return function (t, x, out, o) {…} }` */
    readonly field: string;
    /** `return function (P) { return function (t, x, o) {…} }` */
    readonly hamiltonian: string;
    /** for the midpoint rule: `return function (P) { return function (t, x, J) {…} }`, ∂f/∂x row-major */
    readonly jacobian?: string;
  };
  /** LaTeX of H and of Hamilton's equations, for a symbolic H (the equations with any non-Hamiltonian term in them). */
  readonly latex?: { readonly hamiltonian: string; readonly equations: readonly string[] };
  /** The non-Hamiltonian terms the code carries, when there are any (model/non-hamiltonian.ts); only on the expression route. */
  readonly nonHamiltonian?: NonHamiltonianPart;
}

/** What decides a model's generated code; see {@link modelKey}. */
export interface ModelKeySpec {
  dof: number;
  hamiltonian: string | OpaqueHamiltonian;
  params?: Readonly<Record<string, number>>;
  coordinates?: readonly string[];
  momenta?: readonly string[];
  differentiation?: 'auto' | 'stencil';
  /** the integration method; only those that need code of their own change the key */
  method?: MethodName | MethodChoice;
  /** terms added to Hamilton's equations, by state name (model/non-hamiltonian.ts) */
  nonHamiltonian?: NonHamiltonianTerms;
}

/** The method of a spec that needs code of its own, if it has one. */
export function codeMethodOf(spec: ModelKeySpec): 'verlet' | 'yoshida4' | 'midpoint' | undefined {
  const name = typeof spec.method === 'string' ? spec.method : spec.method?.name;
  return name !== undefined && CODE_METHODS.has(name) ? (name as 'verlet' | 'yoshida4' | 'midpoint') : undefined;
}

/** The text of H: an expression or function source as is, a function by its source. */
export function hamiltonianSource(hamiltonian: string | OpaqueHamiltonian): string {
  return typeof hamiltonian === 'string' ? hamiltonian : hamiltonian.toString();
}

/**
 * The key of a compiled model: a JSON array of everything that decides its
 * code. Two specs with one key compile to the same code, whatever their
 * parameter values.
 */
export function modelKey(spec: ModelKeySpec): string {
  const key: unknown[] = [
    COMPILED_FORMAT,
    spec.dof,
    hamiltonianSource(spec.hamiltonian),
    Object.keys(spec.params ?? {}),
    spec.coordinates ?? null,
    spec.momenta ?? null,
    spec.differentiation ?? 'auto',
  ];
  // RK 3/8's key is as it always was, so models compiled before methods existed stay valid.
  const method = codeMethodOf(spec);
  if (method) key.push(method);
  // Terms only when there are some, sorted by name: the order they were written in changes no code.
  const terms = Object.keys(spec.nonHamiltonian ?? {}).sort();
  if (terms.length) key.push({ nonHamiltonian: terms.map((name) => [name, spec.nonHamiltonian![name]]) });
  return JSON.stringify(key);
}

const ROUTES: readonly string[] = ['expression', 'js-translated', 'js-stencil'];
const isStrings = (v: unknown): v is string[] => Array.isArray(v) && v.every((s) => typeof s === 'string');

/**
 * True when `value` is compiled-model data of this version for `key`. Data
 * from a page, a file or a message is checked before its code runs, so that
 * a stale or damaged entry means "compile again", never a wrong model.
 */
export function isCompiledModel(value: unknown, key: string): value is CompiledModel {
  if (typeof value !== 'object' || value === null) return false;
  const c = value as Record<string, unknown>;
  if (c.format !== COMPILED_FORMAT || c.key !== key || typeof c.route !== 'string' || !ROUTES.includes(c.route)) return false;
  if (!Number.isInteger(c.dof) || !isStrings(c.names) || c.names.length !== 2 * (c.dof as number)) return false;
  if (!isStrings(c.paramNames) || typeof c.source !== 'string') return false;
  if (c.method !== undefined && !(typeof c.method === 'string' && CODE_METHODS.has(c.method as MethodName))) return false;
  if (c.nonHamiltonian !== undefined && !(c.route === 'expression' && isTermsPart(c.nonHamiltonian, c.names as string[]))) return false;
  if (c.route === 'js-stencil') return true;
  const code = c.code as Record<string, unknown> | undefined;
  if (c.method === 'midpoint' && typeof code?.jacobian !== 'string') return false;
  return typeof code?.stepper === 'string' && typeof code.field === 'string' && typeof code.hamiltonian === 'string';
}

const isStringRecord = (v: unknown): v is Record<string, string> =>
  typeof v === 'object' && v !== null && !Array.isArray(v) && Object.values(v).every((s) => typeof s === 'string');

/** A model's record of its non-Hamiltonian terms: at least one, each keyed by a state name, with LaTeX if any by the same names. */
function isTermsPart(value: unknown, names: readonly string[]): value is NonHamiltonianPart {
  if (typeof value !== 'object' || value === null) return false;
  const { terms, latex } = value as Record<string, unknown>;
  if (!isStringRecord(terms) || Object.keys(terms).length === 0 || !Object.keys(terms).every((name) => names.includes(name))) return false;
  return latex === undefined || (isStringRecord(latex) && Object.keys(latex).every((name) => Object.hasOwn(terms, name)));
}

/** Where compiled models are kept between uses: a page's build-time data, the CLI's cache. */
export interface CompiledModelStore {
  get(key: string): CompiledModel | undefined | Promise<CompiledModel | undefined>;
  put?(model: CompiledModel): void | Promise<void>;
}
