import type { MathNode } from 'mathjs';
import { InputError } from '../errors.ts';
import { LOGICAL_OPERATORS } from './emit.ts';
import type { MathJs } from './mathjs.ts';

interface Term {
  node: MathNode;
  negative: boolean;
}

/**
 * The partial derivatives of H, term by term. H is split once into its
 * top-level terms (through +, −, unary ± and parentheses), and ∂H/∂x is the
 * sum of the derivatives of the terms that contain x: the others contribute
 * exactly 0. A chain's H has a few terms per coordinate, so all 2·dof
 * partials together cost O(size of H) instead of 2·dof walks over the whole
 * of it; an H that is one big term (Kepler's 1/r) costs what it did.
 *
 * Derivatives are taken without mathjs's simplification, which measured
 * exponential in the terms of H; the caller tidies them (tidy.ts).
 */
export class Partials {
  private readonly termsWith = new Map<string, Term[]>();

  constructor(
    private readonly math: MathJs,
    hamiltonian: MathNode,
    names: readonly string[],
  ) {
    const state = new Set(names);
    const terms: Term[] = [];
    collectTerms(hamiltonian, false, terms);
    for (const term of terms) {
      for (const name of stateSymbols(term.node, state)) {
        let list = this.termsWith.get(name);
        if (!list) this.termsWith.set(name, (list = []));
        list.push(term);
      }
    }
  }

  /** ∂H/∂name as an untidied tree: 0 when no term of H contains `name`. */
  of(name: string): MathNode {
    const terms = this.termsWith.get(name) ?? [];
    const { OperatorNode, ConstantNode } = this.math;
    let sum: MathNode | undefined;
    for (const { node, negative } of terms) {
      const d = differentiate(this.math, node, name);
      if (sum === undefined) sum = negative ? new OperatorNode('-', 'unaryMinus', [d]) : d;
      else sum = new OperatorNode(negative ? '-' : '+', negative ? 'subtract' : 'add', [sum, d]);
    }
    return sum ?? new ConstantNode(0);
  }
}

function collectTerms(node: MathNode, negative: boolean, out: Term[]): void {
  if (node.type === 'ParenthesisNode') return collectTerms((node as unknown as { content: MathNode }).content, negative, out);
  if (node.type === 'OperatorNode') {
    const { fn, args } = node as unknown as { fn: string; args: MathNode[] };
    if ((fn === 'add' || fn === 'subtract') && args.length === 2) {
      collectTerms(args[0], negative, out);
      collectTerms(args[1], fn === 'subtract' ? !negative : negative, out);
      return;
    }
    if (fn === 'unaryMinus' || fn === 'unaryPlus') return collectTerms(args[0], fn === 'unaryMinus' ? !negative : negative, out);
  }
  out.push({ node, negative });
}

/** The state components a term mentions (a function's own name is no symbol of the state). */
function stateSymbols(node: MathNode, state: ReadonlySet<string>): Set<string> {
  const found = new Set<string>();
  node.traverse((n: MathNode, path: string) => {
    if (n.type !== 'SymbolNode' || path === 'fn') return;
    const name = (n as unknown as { name: string }).name;
    if (state.has(name)) found.add(name);
  });
  return found;
}

/**
 * mathjs's `derivative` knows neither min, max, atan2 nor conditionals and
 * comparisons. Each such subexpression S is stood in for by a fresh symbol s
 * (mathjs takes an unknown symbol for a constant), and the chain rule puts
 * it back:
 *     d/dx F(S(x), x) = ∂F/∂x + Σ ∂F/∂s · dS/dx,
 * with dS/dx by the rules below, differentiating S's own arguments the same
 * way. The rules are those of the pieces: where min picks a it has a's
 * derivative; a comparison is piecewise constant, derivative 0.
 */
function differentiate(math: MathJs, node: MathNode, name: string): MathNode {
  try {
    return derivativeWith(math, node, name);
  } catch (error) {
    if (error instanceof InputError) throw error;
    throw new InputError(`cannot differentiate H with respect to ${name}: ${(error as Error).message}`);
  }
}

/** The stand-in symbols' prefix: `$` is no name a user can write. */
const STAND_IN = '$piece';

function isPiece(node: MathNode): boolean {
  if (node.type === 'ConditionalNode') return true;
  if (node.type === 'FunctionNode') return PIECEWISE.has((node as unknown as { fn: { name: string } }).fn.name);
  if (node.type === 'OperatorNode') return LOGICAL_OPERATORS.has((node as unknown as { fn: string }).fn);
  return false;
}

const PIECEWISE = new Set(['min', 'max', 'atan2']);

function derivativeWith(math: MathJs, node: MathNode, name: string): MathNode {
  const pieces: MathNode[] = [];
  // The outermost pieces, each replaced by its stand-in; pieces inside them are met when they are differentiated.
  const standIn = node.transform((n: MathNode, path: string) => {
    if (path === 'fn' || !isPiece(n)) return n;
    pieces.push(n);
    return new math.SymbolNode(`${STAND_IN}${pieces.length - 1}`);
  });
  const variable = new math.SymbolNode(name);
  let result = math.derivative(standIn, variable, { simplify: false }) as MathNode;
  pieces.forEach((piece, i) => {
    const d = pieceDerivative(math, piece, name);
    if (d === undefined) return;
    const outer = math.derivative(standIn, new math.SymbolNode(`${STAND_IN}${i}`), { simplify: false }) as MathNode;
    result = new math.OperatorNode('+', 'add', [result, new math.OperatorNode('*', 'multiply', [outer, d])]);
  });
  if (pieces.length === 0) return result;
  return result.transform((n: MathNode) => {
    if (n.type !== 'SymbolNode') return n;
    const m = /^\$piece(\d+)$/.exec((n as unknown as { name: string }).name);
    return m ? pieces[Number(m[1])] : n;
  });
}

/** dS/dx for a piece S; undefined when it is 0 (comparisons, logic). */
function pieceDerivative(math: MathJs, piece: MathNode, name: string): MathNode | undefined {
  const { OperatorNode, ConditionalNode } = math;
  if (piece.type === 'OperatorNode') return undefined;
  const d = (n: MathNode) => derivativeWith(math, n, name);
  if (piece.type === 'ConditionalNode') {
    const c = piece as unknown as { condition: MathNode; trueExpr: MathNode; falseExpr: MathNode };
    return new ConditionalNode(c.condition, d(c.trueExpr), d(c.falseExpr));
  }
  const f = piece as unknown as { fn: { name: string }; args: MathNode[] };
  const [a, b] = f.args;
  switch (f.fn.name) {
    case 'min':
      return new ConditionalNode(new OperatorNode('<=', 'smallerEq', [a, b]), d(a), d(b));
    case 'max':
      return new ConditionalNode(new OperatorNode('>=', 'largerEq', [a, b]), d(a), d(b));
    default: {
      // atan2(y, x)' = (x·y' − y·x') / (x² + y²)
      const [y, x] = [a, b];
      const two = new math.ConstantNode(2);
      const numerator = new OperatorNode('-', 'subtract', [new OperatorNode('*', 'multiply', [x, d(y)]), new OperatorNode('*', 'multiply', [y, d(x)])]);
      const denominator = new OperatorNode('+', 'add', [new OperatorNode('^', 'pow', [x, two]), new OperatorNode('^', 'pow', [y, two])]);
      return new OperatorNode('/', 'divide', [numerator, denominator]);
    }
  }
}
