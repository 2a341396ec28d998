/**
 * The model of a `simulate` run: H through the core's compiler (with the
 * disk cache of compiled models unless --no-cache), or a vector field the
 * user wrote, with an optional H function for the H column.
 *
 * A model is made in two steps: a recipe (the compiled model as data, or the
 * field's source), which may need mathjs and is made once, and the running
 * model built from it, which needs no compiler. Every worker thread builds
 * its model from the same recipe, so all run the same generated code: the
 * numbers are the same whichever thread computes a trajectory.
 *
 * Making a recipe never runs the user's code: an expression, or a JS
 * function that translates to one, becomes generated code; any other JS is
 * only parsed. A recipe that needs the user's JavaScript to run (userCodeOf)
 * is built only in the sandbox (user-model.ts, run-model.ts); this module
 * builds the others.
 */
import { compiledModelFor, type CompiledModel, DEFAULT_METHOD, firstEvaluation, InputError, isFunctionSource, type MethodChoice, type Model, modelFromCompiled } from '../../core/index.ts';
import { diskModelStore, modelCacheDirectory } from './model-cache.ts';

export interface ModelArguments {
  dof: number;
  params: Record<string, number>;
  /** --hamiltonian: an expression or JS function source */
  hamiltonian?: string;
  /** --vector-field: JS function source writing dx/dt */
  vectorField?: string;
  /** --coordinates and --momenta: names of the state other than q0…, p0… */
  coordinates?: string[];
  momenta?: string[];
  /** false for --no-cache */
  cache: boolean;
  /** --method; RK 3/8 when absent */
  method?: MethodChoice;
}

/** What a model is built from, as plain data that can be sent to a worker. */
export type ModelRecipe =
  | { kind: 'compiled'; compiled: CompiledModel; params: Record<string, number>; method?: MethodChoice }
  | { kind: 'field'; dof: number; vectorField: string; hamiltonian?: string; params: Record<string, number>; coordinates?: string[]; momenta?: string[]; method?: MethodChoice };

export const FIELD_SHAPE = '(t, x, dxdt) => { dxdt[0] = …; … }';
export const H_SHAPE = '(t, x) => …';

/**
 * The longest H or vector field taken, in characters: sixteen times the
 * 200-degree-of-freedom chains of the book. A longer one is a mistake or a
 * file made to hurt, and compiling it would take long before failing.
 */
export const MAX_SOURCE_CHARS = 65_536;

function checkLength(source: string | undefined, what: string): void {
  if (source !== undefined && source.length > MAX_SOURCE_CHARS) {
    throw new InputError(`${what} is ${source.length} characters long; phasebook takes at most ${MAX_SOURCE_CHARS} (64 KiB)`);
  }
}

/** The recipe of the model `args` describe: compiles H (or takes it from the cache) when there is one to compile. */
export async function modelRecipe(args: ModelArguments): Promise<ModelRecipe> {
  const { dof, params, coordinates, momenta, method } = args;
  checkLength(args.hamiltonian, 'H');
  checkLength(args.vectorField, 'the vector field');
  if (args.vectorField === undefined) {
    if (args.hamiltonian === undefined) throw new InputError('give --hamiltonian H, or --vector-field with a JS function (t, x, dxdt) => { … }');
    const store = args.cache ? diskModelStore(modelCacheDirectory()) : undefined;
    const compiled = await compiledModelFor({ dof, hamiltonian: args.hamiltonian, params, coordinates, momenta, method }, { store });
    return { kind: 'compiled', compiled, params, method };
  }
  if (args.hamiltonian !== undefined && !isFunctionSource(args.hamiltonian)) {
    // Beside a vector field, H only fills the H column: a function evaluates it without compiling anything.
    throw new InputError(`with --vector-field, --hamiltonian must be a JS function ${H_SHAPE}, since it only fills the H column`);
  }
  return { kind: 'field', dof, vectorField: args.vectorField, hamiltonian: args.hamiltonian, params, coordinates, momenta, method };
}

/** The user's code a recipe runs, named as messages name it, or undefined when it runs only code the compiler generated. */
export function userCodeOf(recipe: ModelRecipe): { what: 'H' | 'the vector field'; source: string } | undefined {
  if (recipe.kind === 'field') return { what: 'the vector field', source: recipe.vectorField };
  return recipe.compiled.route === 'js-stencil' ? { what: 'H', source: recipe.compiled.source } : undefined;
}

/** The running model of a recipe whose code the compiler generated; no compiler is loaded. */
export function modelFromRecipe(recipe: ModelRecipe): Model {
  if (userCodeOf(recipe) || recipe.kind !== 'compiled') throw new Error('a model that runs the user\'s code is built in the sandbox only');
  return modelFromCompiled(recipe.compiled, recipe.params, recipe.compiled.source, recipe.method ?? DEFAULT_METHOD);
}

/** A value H returned, in words. */
export function describe(value: unknown): string {
  if (typeof value === 'string') return `the string ${JSON.stringify(value.length > 40 ? value.slice(0, 40) + '…' : value)}`;
  if (value === null) return 'null';
  if (Array.isArray(value)) return 'an array';
  return typeof value === 'object' ? 'an object' : String(value) === 'undefined' ? 'undefined' : `a ${typeof value}`;
}

/**
 * Evaluates the model once at an initial state (core's firstEvaluation), so
 * that a name error in a JS function, H returning something other than a
 * number, or a vector field that leaves a component unwritten, is reported
 * before any output. H is looked at before the equations, whose failure in
 * the H routes is H's; a NaN of H is the physics and not reported here.
 */
export function checkEvaluates(model: Model, initial: ArrayLike<number>, t0 = 0): void {
  const faults = firstEvaluation(model, initial, t0);
  const fault = faults.find((f) => f.part === 'H' && f.reason !== 'NaN') ?? faults.find((f) => f.part === 'equations');
  if (!fault) return;
  if (fault.reason === 'threw') {
    if (fault.error instanceof InputError) throw fault.error;
    const what = fault.part === 'equations' && model.route === 'vector-field' ? 'the vector field' : 'H';
    throw new InputError(`${what} fails at t = ${t0}: ${(fault.error as Error)?.message ?? String(fault.error)}`);
  }
  if (fault.reason === 'not a number') throw new InputError(`H must return a number, but returns ${describe(fault.value)} at t = ${t0}`);
  if (fault.reason === 'unset') {
    const k = fault.component;
    throw new InputError(`the vector field gives no finite dx/dt for ${model.names[k]} (dxdt[${k}]) at t = ${t0}; it must write every component: ${FIELD_SHAPE}`);
  }
}
