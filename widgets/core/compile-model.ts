/**
 * Compiles H into a {@link CompiledModel}: the heavy half of building a
 * model, which loads mathjs (for an expression) or acorn (for a JS function)
 * on first use.
 */
import { throwIfAborted, type BuildControl } from './build-control.ts';
import { codeMethodOf, COMPILED_FORMAT, hamiltonianSource, modelKey, type CompiledModel, type ModelKeySpec } from './compiled-model.ts';
import { InputError } from './errors.ts';
import { compileExpression } from './expression/compile-expression.ts';
import { stateNames } from './expression/names.ts';
import { functionFromSource, isFunctionSource, parseFunction } from './js-function/function-source.ts';
import { translateFunction } from './js-function/translate.ts';

/**
 * The canonical equations of H by the most exact route its form allows:
 * - a math expression gets exact symbolic derivatives;
 * - a JS function whose body is arithmetic, Math functions and parameters is
 *   translated to an expression and gets the same;
 * - any other JS function (or `differentiation: 'stencil'`) is left opaque,
 *   for 5-point central differences.
 *
 * `control` lets the caller abort a build superseded by a new edit (it stops
 * between two derivatives with an AbortError) and follow its progress.
 */
export async function compileModel(spec: ModelKeySpec, control: BuildControl = {}): Promise<CompiledModel> {
  throwIfAborted(control.signal);
  const key = modelKey(spec);
  const source = hamiltonianSource(spec.hamiltonian);
  const paramNames = Object.keys(spec.params ?? {});
  const { names } = stateNames(spec.dof, spec.coordinates, spec.momenta);
  const common = { format: COMPILED_FORMAT, key, dof: spec.dof, names, paramNames, source } as const;
  // Only the methods with code of their own change what is compiled (integrators/methods.ts).
  const method = codeMethodOf(spec);
  const expression = { dof: spec.dof, paramNames, coordinates: spec.coordinates, momenta: spec.momenta, method };
  const withMethod = method ? { method } : {};

  if (typeof spec.hamiltonian === 'string' && !isFunctionSource(spec.hamiltonian)) {
    const { code, latex } = await compileExpression({ ...expression, source }, control);
    return { ...common, ...withMethod, route: 'expression', code, latex };
  }
  const program = await parseFunction(source);
  if (spec.differentiation !== 'stencil') {
    const translated = translateFunction(program, names, paramNames);
    if ('expression' in translated) {
      try {
        const { code, latex } = await compileExpression({ ...expression, source: translated.expression }, control);
        return { ...common, ...withMethod, route: 'js-translated', code, latex };
      } catch (error) {
        // A function mathjs cannot differentiate: finite differences still work.
        if (!(error instanceof InputError) || !/differentiate/.test(error.message)) throw error;
      }
    }
  }
  // Built once here so that source which is no function fails now, with its reason.
  if (typeof spec.hamiltonian === 'string') functionFromSource(source, paramNames, new Float64Array(paramNames.length));
  return { ...common, ...withMethod, route: 'js-stencil' };
}
