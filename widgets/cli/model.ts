/**
 * The model of a `simulate` run: H through the core's compiler (with the
 * disk cache of compiled models unless --no-cache), or a vector field the
 * user wrote, with an optional H function for the H column.
 */
import { canonicalEquations } from '../core/canonical-equations.ts';
import { InputError } from '../core/errors.ts';
import { isFunctionSource } from '../core/js-function/compile.ts';
import type { OpaqueHamiltonian } from '../core/js-function/stencil.ts';
import type { Model, VectorField } from '../core/types.ts';
import { functionFromArgument } from './js-source.ts';
import { diskModelStore, modelCacheDirectory } from './model-cache.ts';

export interface ModelArguments {
  dof: number;
  params: Record<string, number>;
  /** --hamiltonian: an expression or JS function source */
  hamiltonian?: string;
  /** --vector-field: JS function source writing dx/dt */
  vectorField?: string;
  /** false for --no-cache */
  cache: boolean;
}

const FIELD_SHAPE = '(t, x, dxdt) => { dxdt[0] = …; … }';
const H_SHAPE = '(t, x) => …';

export async function simulationModel(args: ModelArguments): Promise<Model> {
  const { dof, params } = args;
  if (args.vectorField === undefined) {
    if (args.hamiltonian === undefined) throw new InputError('give --hamiltonian H, or --vector-field with a JS function (t, x, dxdt) => { … }');
    const store = args.cache ? diskModelStore(modelCacheDirectory()) : undefined;
    return canonicalEquations({ dof, hamiltonian: args.hamiltonian, params }, { store });
  }
  const vectorField = functionFromArgument(args.vectorField, '--vector-field', FIELD_SHAPE, params) as VectorField;
  let hamiltonian: OpaqueHamiltonian | undefined;
  if (args.hamiltonian !== undefined) {
    // Beside a vector field, H only fills the H column: a function evaluates it without compiling anything.
    if (!isFunctionSource(args.hamiltonian)) {
      throw new InputError(`with --vector-field, --hamiltonian must be a JS function ${H_SHAPE}, since it only fills the H column`);
    }
    hamiltonian = functionFromArgument(args.hamiltonian, '--hamiltonian', H_SHAPE, params) as OpaqueHamiltonian;
  }
  return canonicalEquations({ dof, vectorField, hamiltonian, params });
}

/**
 * Evaluates the model once at the initial state, so that a name error in a
 * JS function, or a vector field that leaves a component unwritten, is
 * reported before any output.
 */
export function checkEvaluates(model: Model, initial: readonly number[]): void {
  const x = Float64Array.from(initial);
  const rate = new Float64Array(model.dim);
  const field = model.route === 'vector-field';
  try {
    model.hamiltonian?.(0, x, 0);
  } catch (error) {
    throw new InputError(`H fails at t = 0: ${(error as Error).message}`);
  }
  rate.fill(NaN);
  try {
    model.field(0, x, rate);
  } catch (error) {
    throw new InputError(`${field ? 'the vector field' : 'H'} fails at t = 0: ${(error as Error).message}`);
  }
  // A Hamiltonian's NaN is the physics (bodies that meet) and is reported as a blow-up; a vector field's may be a component it forgot.
  const unset = field ? rate.findIndex((v) => !Number.isFinite(v)) : -1;
  if (unset >= 0) {
    throw new InputError(
      `the vector field gives no finite dx/dt for ${model.names[unset]} (dxdt[${unset}]) at t = 0; it must write every component: ${FIELD_SHAPE}`,
    );
  }
}
