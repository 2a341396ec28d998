/**
 * Parsing an expression of the state, time and parameters — H, or a
 * non-Hamiltonian term added to a rate (expression/non-hamiltonian.ts) —
 * into a tree the compiler can differentiate and emit. Every error names
 * what was parsed, so a typo in a term is not reported as one in H.
 */
import type { MathNode } from 'mathjs';
import { InputError } from '../errors.ts';
import { LOGICAL_OPERATORS, SUPPORTED_FUNCTIONS } from './emit.ts';
import type { MathJs } from './mathjs.ts';
import { CONSTANTS } from './names.ts';

const ARITHMETIC = new Set(['add', 'subtract', 'multiply', 'divide', 'unaryMinus', 'unaryPlus', 'pow']);

/** The names an expression may use besides the state's: the parameters (time and the constants are always there). */
export interface ExpressionNames {
  /** q's then p's */
  readonly names: readonly string[];
  /** other spellings of state names, e.g. q0 for q */
  readonly aliases: ReadonlyMap<string, string>;
  readonly paramNames: readonly string[];
}

/**
 * `source` parsed, its aliases resolved and checked to be what the compiler
 * handles; `what` names it in errors ("H", "the non-Hamiltonian term of p").
 */
export function parseChecked(math: MathJs, source: string, what: string, known: ExpressionNames): MathNode {
  return prepare(math, parseExpression(math, source, what), what, known);
}

function parseExpression(math: MathJs, source: string, what: string): MathNode {
  if (!source.trim()) throw new InputError(`${what} is empty`);
  try {
    return math.parse(source);
  } catch (error) {
    const e = error as Error & { char?: number };
    const where = e.char !== undefined ? ` at column ${e.char}` : '';
    const message = e.message.replace(/\s*\(char \d+\)$/, '');
    throw new InputError(`syntax error in ${what}${where}: ${message}`);
  }
}

/**
 * Resolves aliases, rewrites functions mathjs cannot differentiate into ones
 * it can (hypot(a, b) = √(a² + b²)), and rejects unknown names and functions
 * before any derivative is taken, so the user hears about a typo, not about
 * a failed derivative.
 */
function prepare(math: MathJs, node: MathNode, what: string, known: ExpressionNames): MathNode {
  const { names, aliases, paramNames } = known;
  const allowedNames = new Set([...names, ...paramNames, 't', ...Object.keys(CONSTANTS)]);
  return node.transform((n: MathNode, path: string) => {
    if (path === 'fn') return n;
    if (n.type === 'FunctionNode') {
      const f = n as unknown as { fn: { name: string }; args: MathNode[] };
      const name = f.fn.name;
      if (name === 'hypot') {
        const squares = f.args.map((a) => `(${a.toString()})^2`).join(' + ');
        return prepare(math, math.parse(`sqrt(${squares})`), what, known);
      }
      if ((name === 'min' || name === 'max') && f.args.length > 2) {
        // min(a, b, c) = min(min(a, b), c): the emitter and the derivative rules take two arguments.
        const nested = f.args.slice(1).reduce((acc, arg) => new math.FunctionNode(new math.SymbolNode(name), [acc, arg]), f.args[0]);
        return prepare(math, nested, what, known);
      }
      if (!SUPPORTED_FUNCTIONS.has(name)) throw new InputError(`${what} calls ${name}(), which is not a supported function`);
      const arity = name === 'min' || name === 'max' || name === 'atan2' ? 2 : 1;
      if (f.args.length !== arity) throw new InputError(`${what} calls ${name}() with ${f.args.length} argument(s); it takes ${arity}`);
      return n;
    }
    if (n.type === 'SymbolNode') {
      const name = (n as unknown as { name: string }).name;
      const alias = aliases.get(name);
      if (alias) return new math.SymbolNode(alias);
      if (!allowedNames.has(name)) throw new InputError(`unknown name ${name} in ${what}: give it a value as a parameter`);
    }
    if (n.type === 'OperatorNode') {
      const fn = (n as unknown as { fn: string }).fn;
      if (!ARITHMETIC.has(fn) && !LOGICAL_OPERATORS.has(fn)) throw new InputError(`${what} may not use the operator ${(n as unknown as { op: string }).op}`);
    }
    const allowed = ['ConstantNode', 'OperatorNode', 'ParenthesisNode', 'SymbolNode', 'ConditionalNode'];
    if (!allowed.includes(n.type)) {
      throw new InputError(`${what} may use only arithmetic, comparisons, conditionals (c ? a : b), functions, numbers and names, not ${n.toString()}`);
    }
    return n;
  });
}
