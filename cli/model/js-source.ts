/**
 * The user's JavaScript — a vector field `(t, x, dxdt) => { … }`, an H
 * `(t, x) => …` beside one, or an H left opaque for finite differences — as
 * a function, with the parameters and Math's functions visible by name.
 *
 * Only the sandbox (sandbox-child.ts) makes these: the CLI itself never runs
 * the user's code. The source is compiled by node:vm, not by `new Function`,
 * for two reasons: the sandbox forbids making code from strings, which
 * `new Function` is and node:vm is not; and code compiled without an
 * `importModuleDynamically` hook cannot `import()` any module, Node's own
 * included. No parser is loaded, so a vector-field run loads neither acorn
 * nor mathjs.
 */
import { compileFunction } from 'node:vm';
import { checkName, InputError, isFunctionSource, MATH_NAMES } from '../../core/index.ts';

/**
 * The function `source` evaluates to, with the parameters fixed at their
 * values. `what` names the code in messages (--vector-field, H) and `shape`
 * shows its expected form.
 */
export function functionFromArgument(
  source: string,
  what: string,
  shape: string,
  params: Readonly<Record<string, number>>,
): (...args: never[]) => unknown {
  if (!isFunctionSource(source)) throw new InputError(`${what} must be a JS function ${shape}, not "${source}"`);
  const paramNames = Object.keys(params);
  for (const name of paramNames) {
    try {
      checkName(name, 'parameter');
    } catch (error) {
      throw new InputError(`the parameter ${(error as Error).message}`);
    }
  }
  // A parameter named like a Math function hides it, as in a JS function given as --hamiltonian.
  const mathNames = MATH_NAMES.filter((name) => !paramNames.includes(name));
  const math = Math as unknown as Record<string, unknown>;
  let value: unknown;
  try {
    const make = compileFunction(`"use strict";\nreturn (${source}\n);`, [...paramNames, ...mathNames]);
    value = make(...paramNames.map((name) => params[name]), ...mathNames.map((name) => math[name]));
  } catch (error) {
    const kind = error instanceof SyntaxError ? 'syntax error' : 'error';
    throw new InputError(`${kind} in ${what}: ${(error as Error)?.message ?? String(error)}`);
  }
  if (typeof value !== 'function') throw new InputError(`${what} must be a JS function ${shape}`);
  return value as (...args: never[]) => unknown;
}
