import type { MathNode } from 'mathjs';
import { BuildTracker, throwIfAborted, type BuildControl } from '../model/build-control.ts';
import { InputError } from '../errors.ts';
import { describeTerms, requireHamiltonianFlow } from '../model/non-hamiltonian.ts';
import type { NonHamiltonianPart, NonHamiltonianTerms } from '../types.ts';
import { evaluatorSource, fusedStepperSource, type RateExpressions } from './fused-stepper.ts';
import { jacobianEntries, jacobianSource } from './jacobian.ts';
import { parseTerms, rateWithTerm, type ParsedTerm } from './non-hamiltonian.ts';
import { parseChecked } from './parse.ts';
import { requireSeparable } from './separable.ts';
import { splitStepperSource } from './split-stepper.ts';
import { checkName, stateNames } from './names.ts';
import { expressionTex, latexOf } from './latex.ts';
import { loadMathjs, type MathJs } from './mathjs.ts';
import { Partials } from './partials.ts';
import { Tidy } from './tidy.ts';

export interface ExpressionSpec {
  /** H in mathjs syntax, e.g. `p^2/2 + omega0^2*q^2/2 + alpha*q^3` */
  source: string;
  dof: number;
  paramNames?: readonly string[];
  coordinates?: readonly string[];
  momenta?: readonly string[];
  /**
   * A method that needs code of its own (integrators/methods.ts): the
   * splittings get their fused stepper in place of RK 3/8's, after H is
   * checked to separate; the midpoint rule gets the Jacobian as well.
   */
  method?: 'verlet' | 'yoshida4' | 'midpoint';
  /**
   * Terms added to Hamilton's equations, by state name, in H's syntax
   * (model/non-hamiltonian.ts): part of the rates, so of the stepper, the
   * field and the equations' LaTeX, but not of H.
   */
  nonHamiltonian?: NonHamiltonianTerms;
}

/** The generated code and LaTeX of an expression H (see CompiledModel). */
export interface CompiledExpression {
  names: string[];
  code: { stepper: string; field: string; hamiltonian: string; jacobian?: string };
  latex: { hamiltonian: string; equations: string[] };
  /** the non-Hamiltonian terms the code carries, when there are any */
  nonHamiltonian?: NonHamiltonianPart;
}

/** H parsed, checked and with its names resolved: the first stage of a compile. */
export interface ParsedHamiltonian {
  dof: number;
  /** q's then p's */
  names: string[];
  paramNames: readonly string[];
  hamiltonian: MathNode;
  /** the non-Hamiltonian terms, parsed as H is, in the state's order (none for a Hamiltonian flow) */
  terms: readonly ParsedTerm[];
}

/** Hamilton's equations of H: the second stage of a compile. */
export interface HamiltonEquations {
  /**
   * The rate of each state component, as the stepper computes it: ∂H/∂p, or
   * ∂H/∂q to be negated; a component with a non-Hamiltonian term has the
   * whole of its rate, term included, not negated.
   */
  rates: { node: MathNode; negate: boolean }[];
  /** The right-hand sides as read: ∂H/∂p, and −∂H/∂q with the minus worked in, plus any term. */
  readable: MathNode[];
}

/**
 * Compiles H given as a math expression: exact symbolic partial derivatives
 * (mathjs `derivative`, term by term) written out as one fused RK 3/8
 * stepper and two evaluators, all as source text for `new Function`.
 *
 * The work is 2·dof derivatives and then the code; `control` can watch it
 * (one unit per derivative, one for the code) and abort it between any two.
 */
export async function compileExpression(spec: ExpressionSpec, control: BuildControl = {}): Promise<CompiledExpression> {
  throwIfAborted(control.signal);
  const math = await loadMathjs();
  const parsed = parseHamiltonian(math, spec);
  // A method's own code is made from H's derivatives alone, which the terms are not part of.
  if (spec.method && parsed.terms.length) requireHamiltonianFlow(spec.method, describeTerms(termsOf(parsed)));
  const extra = spec.method === 'midpoint' ? parsed.names.length : 0;
  const tracker = new BuildTracker(control, parsed.names.length + 1 + extra);
  const equations = await hamiltonEquations(math, parsed, tracker);
  const compiled = spec.method ? await methodCode(math, parsed, equations, spec.method, tracker) : generateCode(parsed, equations);
  await tracker.step();
  return compiled;
}

/**
 * The code of H for a method other than RK 3/8: a splitting's fused stepper
 * (for an H that separates, else an InputError saying why not), or RK 3/8's
 * code plus the Jacobian of the field for the midpoint rule.
 */
export async function methodCode(
  math: MathJs,
  parsed: ParsedHamiltonian,
  equations: HamiltonEquations,
  method: NonNullable<ExpressionSpec['method']>,
  tracker?: BuildTracker,
): Promise<CompiledExpression> {
  const compiled = generateCode(parsed, equations);
  const { names, paramNames, dof } = parsed;
  const model: RateExpressions = { names, paramNames, rates: equations.rates };
  if (method === 'midpoint') {
    const entries = jacobianEntries(math, model);
    for (let i = 0; i < names.length; i++) await tracker?.step();
    return { ...compiled, code: { ...compiled.code, jacobian: jacobianSource(model, entries) } };
  }
  // ∂H/∂q_i is the rate of p_i, ∂H/∂p_i that of q_i.
  const derivatives = names.map((_, i) => equations.rates[i < dof ? i + dof : i - dof].node);
  requireSeparable(method, names, derivatives);
  return { ...compiled, code: { ...compiled.code, stepper: splitStepperSource(model, method) } };
}

/** Parses H, resolves aliases and rejects what the compiler cannot handle. */
export function parseHamiltonian(math: MathJs, spec: ExpressionSpec): ParsedHamiltonian {
  const { names, aliases } = stateNames(spec.dof, spec.coordinates, spec.momenta);
  const paramNames = spec.paramNames ?? [];
  for (const name of paramNames) {
    checkName(name, 'parameter');
    if (names.includes(name)) throw new InputError(`the parameter ${name} has the name of a state component`);
  }
  const known = { names, aliases, paramNames };
  const hamiltonian = parseChecked(math, spec.source, 'H', known);
  return { dof: spec.dof, names, paramNames, hamiltonian, terms: parseTerms(math, spec.nonHamiltonian, known) };
}

/**
 * The 2·dof partial derivatives of H, term by term and unsimplified
 * (partials.ts), each tidied in time linear in its size (tidy.ts). For an H
 * that is a sum of terms of a few coordinates each, as a chain's is, the
 * whole costs time about linear in dof; at worst, an H of one term with
 * every coordinate in it, 2·dof derivatives of the whole of H.
 */
export async function hamiltonEquations(math: MathJs, parsed: ParsedHamiltonian, tracker?: BuildTracker): Promise<HamiltonEquations> {
  const { names, dof, hamiltonian } = parsed;
  const state = new Set(names);
  const partials = new Partials(math, hamiltonian, names);
  const tidy = new Tidy(math, (name) => state.has(name));
  const rates: HamiltonEquations['rates'] = [];
  for (let i = 0; i < names.length; i++) {
    const conjugate = i < dof ? names[i + dof] : names[i - dof];
    rates.push({ node: tidy.tidy(partials.of(conjugate)), negate: i >= dof });
    await tracker?.step();
  }
  const readable = rates.map(({ node, negate }) => (negate ? tidy.negated(node) : node));
  for (const { index, node } of parsed.terms) {
    readable[index] = rateWithTerm(math, tidy, readable[index], node);
    rates[index] = { node: readable[index], negate: false };
  }
  return { rates, readable };
}

/** The stepper, the two evaluators and the LaTeX, from H and its equations. */
export function generateCode(parsed: ParsedHamiltonian, equations: HamiltonEquations): CompiledExpression {
  const { names, paramNames, hamiltonian, dof, terms } = parsed;
  const { rates } = equations;
  const model: RateExpressions = { names, paramNames, rates };
  const added = names.map((_, i) => terms.find((term) => term.index === i)?.node);
  const compiled: CompiledExpression = {
    names,
    code: {
      stepper: fusedStepperSource(model),
      field: evaluatorSource(model, rates, 'vector'),
      hamiltonian: evaluatorSource(model, [{ node: hamiltonian, negate: false }], 'scalar'),
    },
    latex: latexOf(hamiltonian, equations.readable, names, dof, added),
  };
  if (!terms.length) return compiled;
  const latex = Object.fromEntries(terms.map(({ name, node }) => [name, expressionTex(node)]));
  return { ...compiled, nonHamiltonian: { terms: termsOf(parsed), latex } };
}

/** The terms of a parsed H as given, by state name. */
function termsOf(parsed: ParsedHamiltonian): NonHamiltonianTerms {
  return Object.fromEntries(parsed.terms.map(({ name, source }) => [name, source]));
}
