import type { Program } from 'acorn';
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

/**
 * Parses JS function source, turning a syntax error into one line with its
 * position. The text parsed is `(source\n)`, the very text functionFromSource
 * puts between its parentheses, so that what the tree says of it holds for
 * what would run.
 */
export async function parseFunction(source: string) {
  const { parse } = await loadAcorn();
  try {
    return parse(`(${source}\n)`, { ecmaVersion: 'latest', locations: true });
  } catch (error) {
    const e = error as SyntaxError & { loc?: { line: number; column: number } };
    // acorn says a recursion too deep for the stack as a SyntaxError of its own.
    if (isStackOverflow(error) || /not enough stack space/i.test(e.message)) {
      throw new InputError(`H nests too deeply for the parser (${source.length} characters); write it with fewer nested parentheses`);
    }
    const message = e.message.replace(/\s*\(\d+:\d+\)$/, '');
    const lines = source.split('\n').length;
    // The source was wrapped in "(…\n)": line 1 is one column off, and a line past the end means H stopped short.
    if (e.loc && e.loc.line > lines) throw new InputError(`syntax error in H: it ends too early (${message})`);
    const where = e.loc ? ` at line ${e.loc.line}, column ${e.loc.line === 1 ? e.loc.column : e.loc.column + 1}` : '';
    throw new InputError(`syntax error in H${where}: ${message}`);
  }
}

/**
 * Throws unless the program parseFunction made of H is one function
 * expression and nothing else: `(t, x) => …` or `function (t, x) {…}`. This
 * decides from the tree alone, so that no code of H runs to find out: source
 * such as `(() => { …; return (t, x) => 1 })()`, a call that would return a
 * function, or `1), evil(), ((t, x) => 1`, which closes the parentheses it is
 * put between, is refused without being run.
 */
export function requireFunctionExpression(program: Program): void {
  const [statement, ...rest] = program.body;
  const expression = statement?.type === 'ExpressionStatement' ? statement.expression : undefined;
  if (rest.length === 0 && (expression?.type === 'ArrowFunctionExpression' || expression?.type === 'FunctionExpression')) return;
  const what = expression && rest.length === 0 ? describeNode(expression.type) : 'statements';
  throw new InputError(`H must be one JS function, (t, x) => …, not ${what} that may make one: phasebook does not run H's code to find its function`);
}

/** What H is instead of a function, in words, for the refusal above. */
function describeNode(type: string): string {
  if (type === 'CallExpression') return 'a call';
  if (type === 'SequenceExpression') return 'a list of expressions';
  return 'another kind of expression';
}

/** V8's RangeError for a recursion deeper than its stack: a parser or compiler walking a very deep tree. */
export function isStackOverflow(error: unknown): boolean {
  return error instanceof RangeError && /call stack/i.test(error.message);
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
  paramNames.forEach((name) => checkName(name, 'parameter'));
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
