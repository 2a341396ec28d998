/**
 * A JS function written on the command line — a vector field
 * `(t, x, dxdt) => { … }`, or H `(t, x) => …` beside one — with the
 * parameters and Math's functions visible by name, as they are to a JS
 * function given as --hamiltonian. Built by `new Function` alone, without a
 * parser, so that a vector-field run loads neither acorn nor mathjs.
 */
import { checkName, InputError, isFunctionSource, MATH_NAMES } from '../core/index.ts';

/**
 * The function `source` evaluates to. `option` names the command-line option
 * in messages and `shape` shows its expected form.
 */
export function functionFromArgument(
  source: string,
  option: string,
  shape: string,
  params: Readonly<Record<string, number>>,
): (...args: never[]) => unknown {
  if (!isFunctionSource(source)) throw new InputError(`${option} must be a JS function ${shape}, not "${source}"`);
  const paramNames = Object.keys(params);
  for (const name of paramNames) {
    try {
      checkName(name);
    } catch (error) {
      throw new InputError(`the parameter ${(error as Error).message}`);
    }
  }
  // A parameter named like a Math function hides it, as in a JS function given as --hamiltonian.
  const mathNames = MATH_NAMES.filter((name) => !paramNames.includes(name));
  const math = Math as unknown as Record<string, unknown>;
  let value: unknown;
  try {
    const make = new Function(...paramNames, ...mathNames, `"use strict";\nreturn (${source}\n);`);
    value = make(...paramNames.map((name) => params[name]), ...mathNames.map((name) => math[name]));
  } catch (error) {
    const kind = error instanceof SyntaxError ? 'syntax error' : 'error';
    throw new InputError(`${kind} in ${option}: ${(error as Error).message}`);
  }
  if (typeof value !== 'function') throw new InputError(`${option} must be a JS function ${shape}`);
  return value as (...args: never[]) => unknown;
}
