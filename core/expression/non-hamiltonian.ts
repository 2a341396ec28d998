/**
 * Non-Hamiltonian terms (model/non-hamiltonian.ts) in the compiler. Each is
 * parsed and checked as H is, and added to its component's rate before any
 * code is generated: the fused stepper, the field evaluator and the LaTeX
 * are all made from the rates, so each carries the term, and a worker that
 * rebuilds the stepper from its source text alone
 * (widgets/simulator/portable-model.ts) integrates the same flow.
 */
import type { MathNode } from 'mathjs';
import { checkedTerms } from '../model/non-hamiltonian.ts';
import type { NonHamiltonianTerms } from '../types.ts';
import type { MathJs } from './mathjs.ts';
import { parseChecked, type ExpressionNames } from './parse.ts';
import type { Tidy } from './tidy.ts';

/** One term, parsed: added to the rate of the state component `index`. */
export interface ParsedTerm {
  readonly index: number;
  readonly name: string;
  /** as given, for the model's record of it */
  readonly source: string;
  readonly node: MathNode;
}

/** The terms parsed in the state's order; a key that is not a state name, or an unknown name in a term, is an InputError. */
export function parseTerms(math: MathJs, terms: NonHamiltonianTerms | undefined, known: ExpressionNames): ParsedTerm[] {
  const checked = checkedTerms(terms, known.names) ?? {};
  return Object.entries(checked).map(([name, source]) => ({
    index: known.names.indexOf(name),
    name,
    source,
    node: parseChecked(math, source, `the non-Hamiltonian term of ${name}`, known),
  }));
}

/** rate + term as one tidy tree: what the stepper computes, and what the reader sees on the right of ẋ = … */
export function rateWithTerm(math: MathJs, tidy: Tidy, rate: MathNode, term: MathNode): MathNode {
  return tidy.tidy(new math.OperatorNode('+', 'add', [rate, term]));
}
