/**
 * Non-Hamiltonian terms of a model: rates added to Hamilton's equations,
 * ẋ_i = (Ω∇H)_i + term_i, such as the friction −γp of a damped oscillator.
 * They are what a chapter on Liouville's theorem needs (a flow whose
 * phase-space area decays), and what every canonical check must leave out:
 * a flow with such a term is not canonical, and H is not its invariant.
 *
 * This module is the terms' rules and wording, with no compiler in it, so
 * that a spec is refused (and a check worded) before mathjs is loaded; the
 * terms themselves are compiled with H (expression/non-hamiltonian.ts).
 */
import type { CheckCondition } from '../analysis/check-input.ts';
import { InputError } from '../errors.ts';
import { isFunctionSource } from '../js-function/function-source.ts';
import type { MethodName } from '../integrators/methods.ts';
import type { NonHamiltonianPart, NonHamiltonianTerms } from '../types.ts';

/**
 * The terms checked against the state's names and put in the state's
 * order, or undefined when there are none (an empty record is no term).
 * Throws an InputError for a key that is not a state name or a term that
 * is not a non-empty string.
 */
export function checkedTerms(terms: NonHamiltonianTerms | undefined, names: readonly string[]): NonHamiltonianTerms | undefined {
  if (terms === undefined) return undefined;
  if (typeof terms !== 'object' || terms === null || Array.isArray(terms)) {
    throw new InputError('nonHamiltonian must be a record of terms by state name, e.g. {p: "-gamma*p"}');
  }
  for (const key of Object.keys(terms)) {
    if (!names.includes(key)) {
      throw new InputError(`the non-Hamiltonian term of ${key} names no state component: the state is ${names.join(', ')}`);
    }
    const term = terms[key];
    if (typeof term !== 'string' || !term.trim()) throw new InputError(`the non-Hamiltonian term of ${key} must be a math expression, not ${JSON.stringify(term)}`);
  }
  const ordered = names.filter((name) => Object.hasOwn(terms, name));
  return ordered.length ? Object.fromEntries(ordered.map((name) => [name, terms[name]])) : undefined;
}

/**
 * Refuses the terms for H given otherwise than as a math expression: they
 * are compiled into the expression's generated equations, which a JS
 * function, a vector field or a gradient does not have.
 */
export function requireExpressionRoute(spec: { hamiltonian?: unknown; vectorField?: unknown; gradient?: unknown }): void {
  if (spec.vectorField !== undefined) {
    throw new InputError('a non-Hamiltonian term needs H as a math expression; a vector field is the whole of dx/dt, so write the term into it');
  }
  if (spec.gradient !== undefined) {
    throw new InputError('a non-Hamiltonian term needs H as a math expression; with a gradient, write the whole field, term included, as a vectorField');
  }
  const h = spec.hamiltonian;
  if (typeof h !== 'string' || isFunctionSource(h)) {
    throw new InputError('a non-Hamiltonian term needs H as a math expression, and this H is a JavaScript function: write H as an expression, or the whole field as a vectorField');
  }
}

/** The terms in one line, e.g. `-gamma*p in dp/dt`, for messages and check conditions. */
export function describeTerms(terms: NonHamiltonianTerms): string {
  return Object.entries(terms)
    .map(([name, term]) => `${term.trim()} in d${name}/dt`)
    .join(', ');
}

/**
 * The condition a canonical check puts first: the model is Hamiltonian.
 * `consequence` ends the sentence said when it fails, e.g. "its flow is not
 * canonical"; a check run on a bare flow, with no model to ask, holds it.
 */
export function hamiltonianFlowCondition(model: { readonly nonHamiltonian?: NonHamiltonianPart } | undefined, consequence: string): CheckCondition {
  const part = model?.nonHamiltonian;
  return {
    holds: part === undefined,
    condition: part ? `the model has a non-Hamiltonian term (${describeTerms(part.terms)}), so ${consequence}` : 'the model has no non-Hamiltonian term',
  };
}

/**
 * Why each method built on the flow being Hamiltonian cannot run a model
 * with a non-Hamiltonian term : the splittings
 * split H alone, and the midpoint rule is chosen for a symplecticity that
 * such a flow does not have. RK 3/8 and the adaptive method integrate any
 * field, the term included.
 */
const NEEDS_HAMILTONIAN_FLOW: Partial<Record<MethodName, (terms: string) => string>> = {
  verlet: (terms) => `splits H into T(p) + V(q, t), and a splitting of H is no splitting of this model's non-Hamiltonian term (${terms})`,
  yoshida4: (terms) => `composes splittings of H into T(p) + V(q, t), and a splitting of H is no splitting of this model's non-Hamiltonian term (${terms})`,
  midpoint: (terms) => `is there to keep the flow symplectic, and this model's non-Hamiltonian term (${terms}) makes it not`,
};

/** Throws the one-sentence InputError of a method that needs a Hamiltonian flow, for a model with the terms `terms` (described in words). */
export function requireHamiltonianFlow(name: MethodName, terms: string | undefined): void {
  const why = NEEDS_HAMILTONIAN_FLOW[name];
  if (why !== undefined && terms !== undefined) throw new InputError(`the method ${name} ${why(terms)}; use rk38 or adaptive`);
}

/**
 * A spec's terms checked, in the state's order, with everything refused
 * that cannot run them: an H that is no math expression, a method that
 * needs a Hamiltonian flow. canonicalEquations loads this module only for a
 * spec that has terms, so that no page without one carries its sentences.
 */
export function refusedOrTerms(spec: { hamiltonian?: unknown; vectorField?: unknown; gradient?: unknown; nonHamiltonian?: NonHamiltonianTerms }, names: readonly string[], method: MethodName): NonHamiltonianTerms | undefined {
  const terms = checkedTerms(spec.nonHamiltonian, names);
  if (terms) {
    requireExpressionRoute(spec);
    requireHamiltonianFlow(method, describeTerms(terms));
  }
  return terms;
}
