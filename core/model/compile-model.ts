/**
 * Compiles H into a {@link CompiledModel}: the heavy half of building a
 * model, which loads mathjs (for an expression) or acorn (for a JS function)
 * on first use.
 */
import { throwIfAborted, type BuildControl } from './build-control.ts';
import { codeMethodOf, COMPILED_FORMAT, hamiltonianSource, modelKey, type CompiledModel, type ModelKeySpec } from './compiled-model.ts';
import { InputError } from '../errors.ts';
import { compileExpression } from '../expression/compile-expression.ts';
import { checkedTerms, describeTerms, requireExpressionRoute, requireHamiltonianFlow } from './non-hamiltonian.ts';
import { stateNames } from '../expression/names.ts';
import { isFunctionSource, isStackOverflow, parseFunction, requireFunctionExpression } from '../js-function/function-source.ts';
import { translateFunction } from '../js-function/translate.ts';

/**
 * The canonical equations of H by the most exact route its form allows:
 * - a math expression gets exact symbolic derivatives;
 * - a JS function whose body is arithmetic, Math functions and parameters is
 *   translated to an expression and gets the same;
 * - any other JS function (or `differentiation: 'stencil'`) is left opaque,
 *   for 5-point central differences.
 *
 * Non-Hamiltonian terms are compiled with an expression H only, and only for
 * the methods that integrate any field (model/non-hamiltonian.ts).
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
  const terms = checkedTerms(spec.nonHamiltonian, names);
  if (terms) {
    requireExpressionRoute(spec);
    if (method) requireHamiltonianFlow(method, describeTerms(terms));
  }

  if (typeof spec.hamiltonian === 'string' && !isFunctionSource(spec.hamiltonian)) {
    const { code, latex, nonHamiltonian } = await deepTreesSaid(source, () => compileExpression({ ...expression, source, nonHamiltonian: terms }, control));
    return { ...common, ...withMethod, route: 'expression', code, latex, ...(nonHamiltonian ? { nonHamiltonian } : {}) };
  }
  const program = await parseFunction(source);
  // Decided from the tree: compiling never runs any of H's code, so that what H's code may do is up to whoever builds the model.
  if (typeof spec.hamiltonian === 'string') requireFunctionExpression(program);
  if (spec.differentiation !== 'stencil') {
    const translated = await deepTreesSaid(source, () => translateFunction(program, names, paramNames));
    if ('expression' in translated) {
      try {
        const { code, latex } = await deepTreesSaid(source, () => compileExpression({ ...expression, source: translated.expression }, control));
        return { ...common, ...withMethod, route: 'js-translated', code, latex };
      } catch (error) {
        // A function mathjs cannot differentiate: finite differences still work.
        if (!(error instanceof InputError) || !/differentiate/.test(error.message)) throw error;
      }
    }
  }
  return { ...common, ...withMethod, route: 'js-stencil' };
}

/**
 * A step of the compile, with a stack overflow said as what it is: mathjs
 * and the translator walk H's tree by recursion, and a sum of some thousands
 * of terms is a tree that deep, which exhausts the stack. The reader gets one
 * sentence about H instead of V8's RangeError.
 */
async function deepTreesSaid<T>(source: string, compile: () => T | Promise<T>): Promise<T> {
  try {
    return await compile();
  } catch (error) {
    if (!isStackOverflow(error)) throw error;
    throw new InputError(
      `H is too deeply nested for the compiler (${source.length} characters): a sum of thousands of terms is a tree that deep; group the terms in parentheses`,
    );
  }
}
