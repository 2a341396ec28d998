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
 */
import { canonicalEquations, type CompiledModel, compiledModelFor, DEFAULT_METHOD, firstEvaluation, InputError, isFunctionSource, type MethodChoice, type Model, modelFromCompiled, type OpaqueHamiltonian, type Stepper, type VectorField } from '../core/index.ts';
import { functionFromArgument } from './js-source.ts';
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

const FIELD_SHAPE = '(t, x, dxdt) => { dxdt[0] = …; … }';
const H_SHAPE = '(t, x) => …';

/** The recipe of the model `args` describe: compiles H (or takes it from the cache) when there is one to compile. */
export async function modelRecipe(args: ModelArguments): Promise<ModelRecipe> {
  const { dof, params, coordinates, momenta, method } = args;
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

/** The running model of a recipe; no compiler is loaded. */
export async function modelFromRecipe(recipe: ModelRecipe): Promise<Model> {
  if (recipe.kind === 'compiled') {
    const model = modelFromCompiled(recipe.compiled, recipe.params, recipe.compiled.source, recipe.method ?? DEFAULT_METHOD);
    return recipe.compiled.route === 'js-stencil' ? userCodeModel(model, 'H') : model;
  }
  const { params } = recipe;
  const vectorField = functionFromArgument(recipe.vectorField, '--vector-field', FIELD_SHAPE, params) as VectorField;
  const hamiltonian =
    recipe.hamiltonian === undefined ? undefined : (functionFromArgument(recipe.hamiltonian, '--hamiltonian', H_SHAPE, params) as OpaqueHamiltonian);
  const model = await canonicalEquations({ dof: recipe.dof, vectorField, hamiltonian, params, coordinates: recipe.coordinates, momenta: recipe.momenta, method: recipe.method });
  return userCodeModel(model, 'the vector field');
}

/**
 * A model whose equations run the user's own JavaScript, made to report an
 * exception thrown during the run as the user's (an InputError saying when
 * and what), rather than as an internal error, and H returning anything but
 * a number as such.
 */
function userCodeModel(model: Model, what: string): Model {
  const fails = (when: string, error: unknown) => new InputError(`${what} fails ${when}: ${(error as Error)?.message ?? String(error)}`);
  const advance: Stepper['advance'] = (x, count, params, t0, k0, dt, steps) => {
    try {
      return model.stepper.advance(x, count, params, t0, k0, dt, steps);
    } catch (error) {
      if (error instanceof InputError) throw error;
      throw fails(`between t = ${t0 + k0 * dt} and t = ${t0 + (k0 + steps) * dt}`, error);
    }
  };
  const h = model.hamiltonian;
  return {
    ...model,
    stepper: { dim: model.dim, advance },
    field: (t, x, dxdt) => {
      try {
        model.field(t, x, dxdt);
      } catch (error) {
        throw fails(`at t = ${t}`, error);
      }
    },
    hamiltonian: h
      ? (t, x, offset) => {
          let value: unknown;
          try {
            value = h(t, x, offset);
          } catch (error) {
            throw new InputError(`H fails at t = ${t}: ${(error as Error)?.message ?? String(error)}`);
          }
          if (typeof value !== 'number') throw new InputError(`H must return a number, but returns ${describe(value)} at t = ${t}`);
          return value;
        }
      : undefined,
  };
}

function describe(value: unknown): string {
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
