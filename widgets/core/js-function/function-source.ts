import { InputError } from '../errors.ts';
import { checkName } from '../expression/names.ts';
import type { OpaqueHamiltonian } from './stencil.ts';

/** Math's functions and constants, usable by bare name in H as in the paper's examples. */
export const MATH_NAMES: readonly string[] = Object.getOwnPropertyNames(Math).filter(
  (name) => name !== 'toString' && !name.startsWith('_') && /^[A-Za-z]\w*$/.test(name),
);
const MATH_VALUES = MATH_NAMES.map((name) => (Math as unknown as Record<string, unknown>)[name]);

export function isFunctionSource(source: string): boolean {
  return /=>/.test(source) || /^\s*(async\s+)?function\b/.test(source);
}

type Acorn = typeof import('acorn');
let acorn: Promise<Acorn> | undefined;
export function loadAcorn(): Promise<Acorn> {
  return (acorn ??= import('acorn'));
}

/** Hands over acorn imported statically, for hosts where a dynamic import cannot run (see provideMathjs). */
export function provideAcorn(module: Acorn): void {
  acorn = Promise.resolve(module);
}

/** Parses JS function source, turning a syntax error into one line with its position. */
export async function parseFunction(source: string) {
  const { parse } = await loadAcorn();
  try {
    return parse(`(${source}\n)`, { ecmaVersion: 'latest', locations: true });
  } catch (error) {
    const e = error as SyntaxError & { loc?: { line: number; column: number } };
    const message = e.message.replace(/\s*\(\d+:\d+\)$/, '');
    const lines = source.split('\n').length;
    // The source was wrapped in "(…\n)": line 1 is one column off, and a line past the end means H stopped short.
    if (e.loc && e.loc.line > lines) throw new InputError(`syntax error in H: it ends too early (${message})`);
    const where = e.loc ? ` at line ${e.loc.line}, column ${e.loc.line === 1 ? e.loc.column : e.loc.column + 1}` : '';
    throw new InputError(`syntax error in H${where}: ${message}`);
  }
}

/**
 * A JS function H built from source, with the model's parameters and Math's
 * names in scope. Parameters are `let` bindings refreshed by `sync` from the
 * params array, so that editing a parameter needs no recompilation here
 * either.
 */
export function functionFromSource(
  source: string,
  paramNames: readonly string[],
  params: Float64Array,
): { hamiltonian: OpaqueHamiltonian; sync: () => void } {
  paramNames.forEach(checkName);
  const shadowed = MATH_NAMES.filter((n) => !paramNames.includes(n));
  const body = [
    '"use strict";',
    ...paramNames.map((n, j) => `let ${n} = $P[${j}];`),
    `const $H = (${source}\n);`,
    `if (typeof $H !== "function") throw new TypeError("H is not a function");`,
    `return { hamiltonian: $H, sync() { ${paramNames.map((n, j) => `${n} = $P[${j}];`).join(' ')} } };`,
  ].join('\n');
  try {
    const make = new Function('$P', ...shadowed, body);
    return make(params, ...shadowed.map((n) => MATH_VALUES[MATH_NAMES.indexOf(n)]));
  } catch (error) {
    throw new InputError(`H: ${(error as Error).message}`);
  }
}
