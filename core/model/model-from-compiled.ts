/**
 * A running model from compiled-model data (compiled-model.ts), run by its
 * method: a few `new Function` calls, no mathjs and no acorn.
 */
import type { CompiledModel } from './compiled-model.ts';
import { compiledParts } from './compiled-parts.ts';
import { applyMethod } from '../integrators/apply.ts';
import { DEFAULT_METHOD, type MethodChoice } from '../integrators/methods.ts';
import type { OpaqueHamiltonian } from '../js-function/stencil.ts';
import type { Model } from '../types.ts';

/**
 * A running model from compiled data: `params` gives the parameter values,
 * and `hamiltonian`, for a stencil model, the function itself when H was
 * given as one (its source alone would lose what it closes over).
 * `method` is the integration method, by default the one the code was
 * compiled for (RK 3/8 unless compiled.method says otherwise).
 */
export function modelFromCompiled(
  compiled: CompiledModel,
  params: Readonly<Record<string, number>> = {},
  hamiltonian?: string | OpaqueHamiltonian,
  method: MethodChoice = compiled.method ? { name: compiled.method } : DEFAULT_METHOD,
): Model {
  const { model, parts } = compiledParts(compiled, params, hamiltonian, method);
  return applyMethod(model, method, parts);
}
