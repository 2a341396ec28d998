import type { MathNode } from 'mathjs';
import { InputError } from '../errors.ts';
import { SUPPORTED_FUNCTIONS } from './emit.ts';
import { evaluatorSource, fusedStepperSource, type RateExpressions } from './fused-stepper.ts';
import { CONSTANTS, checkName, stateNames } from './names.ts';
import { latexOf } from './latex.ts';
import { loadMathjs, type MathJs } from './mathjs.ts';

export interface ExpressionSpec {
  /** H in mathjs syntax, e.g. `p^2/2 + omega0^2*q^2/2 + alpha*q^3` */
  source: string;
  dof: number;
  paramNames?: readonly string[];
  coordinates?: readonly string[];
  momenta?: readonly string[];
}

/** The generated code and LaTeX of an expression H (see CompiledModel). */
export interface CompiledExpression {
  names: string[];
  code: { stepper: string; field: string; hamiltonian: string };
  latex: { hamiltonian: string; equations: string[] };
}

/**
 * Compiles H given as a math expression: exact symbolic partial derivatives
 * (mathjs `derivative`) written out as one fused RK 3/8 stepper and two
 * evaluators, all as source text for `new Function`.
 */
export async function compileExpression(spec: ExpressionSpec): Promise<CompiledExpression> {
  const math = await loadMathjs();
  const { names, aliases } = stateNames(spec.dof, spec.coordinates, spec.momenta);
  const paramNames = spec.paramNames ?? [];
  for (const name of paramNames) {
    checkName(name);
    if (names.includes(name)) throw new InputError(`the parameter ${name} has the name of a state component`);
  }
  const hamiltonian = prepare(math, parseExpression(math, spec.source), names, aliases, paramNames);
  const dof = spec.dof;
  const rates = names.map((_, i) => {
    const conjugate = i < dof ? names[i + dof] : names[i - dof];
    return { node: differentiate(math, hamiltonian, conjugate), negate: i >= dof };
  });
  const model: RateExpressions = { names, paramNames, rates };
  return {
    names,
    code: {
      stepper: fusedStepperSource(model),
      field: evaluatorSource(model, rates, 'vector'),
      hamiltonian: evaluatorSource(model, [{ node: hamiltonian, negate: false }], 'scalar'),
    },
    latex: latexOf(math, hamiltonian, rates, names, dof),
  };
}

function parseExpression(math: MathJs, source: string): MathNode {
  if (!source.trim()) throw new InputError('H is empty');
  try {
    return math.parse(source);
  } catch (error) {
    const e = error as Error & { char?: number };
    const where = e.char !== undefined ? ` at column ${e.char}` : '';
    const message = e.message.replace(/\s*\(char \d+\)$/, '');
    throw new InputError(`syntax error in H${where}: ${message}`);
  }
}

/**
 * Resolves aliases, rewrites functions mathjs cannot differentiate into ones
 * it can (hypot(a, b) = √(a² + b²)), and rejects unknown names and functions
 * before any derivative is taken, so the user hears about a typo, not about
 * a failed derivative.
 */
function prepare(
  math: MathJs,
  node: MathNode,
  names: readonly string[],
  aliases: ReadonlyMap<string, string>,
  paramNames: readonly string[],
): MathNode {
  const known = new Set([...names, ...paramNames, 't', ...Object.keys(CONSTANTS)]);
  return node.transform((n: MathNode, path: string) => {
    if (path === 'fn') return n;
    if (n.type === 'FunctionNode') {
      const f = n as unknown as { fn: { name: string }; args: MathNode[] };
      const name = f.fn.name;
      if (name === 'hypot') {
        const squares = f.args.map((a) => `(${a.toString()})^2`).join(' + ');
        return prepare(math, math.parse(`sqrt(${squares})`), names, aliases, paramNames);
      }
      if (!SUPPORTED_FUNCTIONS.has(name)) throw new InputError(`H calls ${name}(), which is not a supported function`);
      return n;
    }
    if (n.type === 'SymbolNode') {
      const name = (n as unknown as { name: string }).name;
      const alias = aliases.get(name);
      if (alias) return new math.SymbolNode(alias);
      if (!known.has(name)) throw new InputError(`unknown name ${name} in H: give it a value as a parameter`);
    }
    if (n.type !== 'ConstantNode' && n.type !== 'OperatorNode' && n.type !== 'ParenthesisNode' && n.type !== 'SymbolNode') {
      throw new InputError(`H may use only arithmetic, functions, numbers and names, not ${n.toString()}`);
    }
    return n;
  });
}

function differentiate(math: MathJs, node: MathNode, name: string): MathNode {
  try {
    return math.derivative(node, name);
  } catch (error) {
    throw new InputError(`cannot differentiate H with respect to ${name}: ${(error as Error).message}`);
  }
}
