/**
 * The running model of a recipe that runs the user's JavaScript (model.ts,
 * userCodeOf): an H left opaque for finite differences, or a vector field
 * with an optional H. Built only in the sandbox (sandbox-child.ts), never in
 * the CLI's own process.
 */
import { canonicalEquations, DEFAULT_METHOD, InputError, type Model, modelFromCompiled, type OpaqueHamiltonian, type Stepper, type VectorField } from '../../core/index.ts';
import { functionFromArgument } from './js-source.ts';
import { describe, FIELD_SHAPE, H_SHAPE, type ModelRecipe } from './model.ts';

/** The model of `recipe`, its user code compiled here, and reported as the user's when it fails. */
export async function userModelFromRecipe(recipe: ModelRecipe): Promise<Model> {
  const { params } = recipe;
  if (recipe.kind === 'compiled') {
    const { compiled } = recipe;
    const hamiltonian = functionFromArgument(compiled.source, 'H', H_SHAPE, params) as OpaqueHamiltonian;
    // The parameters are fixed for a run, so the function closes over their values rather than live bindings.
    return userCodeModel(modelFromCompiled(compiled, params, hamiltonian, recipe.method ?? DEFAULT_METHOD), 'H');
  }
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
