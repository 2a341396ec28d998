/**
 * What a run needs to know of its model besides its numbers: the names of
 * its state and parameters, the parameters' values, how its equations were
 * obtained, its method, its H's source, and whether it has an H (which
 * decides the H column). The file's columns and meta are made from these.
 *
 * For a model built here they are read off the model. For one that runs the
 * user's JavaScript, which is built only in the sandbox, they are read off
 * its recipe, so that the sandboxed code decides nothing of the file but its
 * numbers. Both readings must agree; a test holds them to it.
 */
import { type MethodChoice, type Model, type Route, stateNames } from '../../core/index.ts';
import type { ModelRecipe } from './model.ts';

export interface ModelFacts {
  readonly dof: number;
  /** q's then p's */
  readonly names: readonly string[];
  readonly paramNames: readonly string[];
  /** in the order of paramNames */
  readonly params: Float64Array;
  readonly route: Route;
  /** H as given (for a vector field, the field's source) */
  readonly source: string;
  /** the method, when it is not RK 3/8 */
  readonly method?: MethodChoice;
  readonly hasHamiltonian: boolean;
}

export function factsOfModel(model: Model): ModelFacts {
  const { dof, names, paramNames, params, route, source, method } = model;
  return { dof, names, paramNames, params, route, source, method, hasHamiltonian: model.hamiltonian !== undefined };
}

/** The facts of the model a recipe makes, without making it. */
export function factsOfRecipe(recipe: ModelRecipe): ModelFacts {
  // A model run by RK 3/8 carries no method (integrators/apply.ts leaves it as it is).
  const method = recipe.method && recipe.method.name !== 'rk38' ? recipe.method : undefined;
  if (recipe.kind === 'compiled') {
    const { compiled } = recipe;
    const params = Float64Array.from(compiled.paramNames, (name) => recipe.params[name]);
    return { dof: compiled.dof, names: compiled.names, paramNames: compiled.paramNames, params, route: compiled.route, source: compiled.source, method, hasHamiltonian: true };
  }
  const paramNames = Object.keys(recipe.params);
  return {
    dof: recipe.dof,
    names: stateNames(recipe.dof, recipe.coordinates, recipe.momenta).names,
    paramNames,
    params: Float64Array.from(paramNames, (name) => recipe.params[name]),
    route: 'vector-field',
    source: recipe.vectorField,
    method,
    hasHamiltonian: recipe.hamiltonian !== undefined,
  };
}
