/**
 * A model run by a chosen method: its stepper replaced, its accuracy note
 * and its `method` saying so. The splittings need code generated from a
 * separable H (expression/split-stepper.ts), so they are refused for H given
 * as an opaque function or a vector field, whose separation cannot be shown;
 * the midpoint rule uses the exact Jacobian when there is one, else central
 * differences of the field; the adaptive method needs only the field. A
 * model with a non-Hamiltonian term runs only by the methods that integrate
 * any field (methods.ts, requireHamiltonianFlow).
 */
import { InputError } from '../errors.ts';
import { withSummary } from '../summary.ts';
import type { Model, Stepper } from '../types.ts';
import { dormandPrince } from './dormand-prince.ts';
import { describeTerms, requireHamiltonianFlow } from '../model/non-hamiltonian.ts';
import { METHOD_ACCURACY, SPLITTING_METHODS, type MethodChoice } from './methods.ts';
import { differenceJacobian, implicitMidpoint, type JacobianFunction } from './midpoint.ts';

const DERIVATIVES: Record<Model['route'], string> = {
  expression: 'exact symbolic derivatives',
  'js-translated': 'exact symbolic derivatives',
  'js-stencil': 'H is an opaque function, so its gradient comes from 5-point central differences (about 1e-13 relative)',
  'vector-field': 'the vector field is the author’s own, so its accuracy is theirs',
  gradient: 'the gradient is the author’s own, so its accuracy is theirs',
};

const OPAQUE: Partial<Record<Model['route'], string>> = {
  'js-stencil': 'H is an opaque JavaScript function, whose separation into T(p) + V(q, t) cannot be shown',
  'vector-field': 'the model is a vector field, not a separable H',
  gradient: 'the model is a gradient, whose separation into T(p) + V(q, t) cannot be shown',
};

export interface MethodParts {
  /** the splitting's generated stepper, for verlet and yoshida4 */
  split?: Stepper['advance'];
  /** the exact ∂f/∂x, for the midpoint rule; central differences of the field without it */
  jacobian?: JacobianFunction;
}

/** `model` with its stepper for `choice`; RK 3/8 leaves it as it is. */
export function applyMethod(model: Model, choice: MethodChoice, parts: MethodParts = {}): Model {
  const { name } = choice;
  if (name === 'rk38') return model;
  if (model.nonHamiltonian) requireHamiltonianFlow(name, describeTerms(model.nonHamiltonian.terms));
  const { dim, field } = model;
  let stepper: Stepper;
  if (SPLITTING_METHODS.has(name)) {
    const why = OPAQUE[model.route];
    if (why) throw new InputError(`the method ${name} needs H = T(p) + V(q, t), and ${why}; use rk38, midpoint or adaptive`);
    if (!parts.split) throw new Error(`no ${name} stepper was generated for this model`);
    stepper = { dim, advance: parts.split };
  } else if (name === 'midpoint') {
    stepper = implicitMidpoint(field, parts.jacobian ?? differenceJacobian(field, dim), dim);
  } else {
    stepper = dormandPrince(field, dim, { rtol: choice.rtol!, atol: choice.atol! });
  }
  const jacobian = name === 'midpoint' && !parts.jacobian ? ' (its Newton Jacobian by central differences)' : '';
  return withSummary({
    ...model,
    stepper,
    method: choice,
    accuracy: `${DERIVATIVES[model.route]}; the errors are ${METHOD_ACCURACY[name]}${jacobian}, and rounding`,
  });
}
