import type { MathNode } from 'mathjs';
import { InputError } from '../errors.ts';
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

function differentiate(math: MathJs, node: MathNode, name: string): MathNode {
  try {
    return math.derivative(node, name, { simplify: false });
  } catch (error) {
    throw new InputError(`cannot differentiate H with respect to ${name}: ${(error as Error).message}`);
  }
}
