/**
 * One-line summaries of the core's objects, for whatever shows them to a
 * reader (the cells' inspector, cells/inspect.ts): a model is
 * `Model: 1 DOF, exact derivatives, H = p^2/2 + q^2/2`, not a dump of its
 * generated functions. An object carries its summary under the registered
 * symbol, so the inspector needs to know nothing of models.
 */
import type { Model, Route } from './types.ts';

/** The key of an object's one-line summary method. */
export const SUMMARY = Symbol.for('phasebook.summary');

const DERIVATIVES: Record<Route, string> = {
  expression: 'exact derivatives',
  'js-translated': 'exact derivatives (translated from JavaScript)',
  'js-stencil': 'derivatives by 5-point differences',
  'vector-field': 'vector field as given',
  gradient: 'gradient as given',
};

/** Cuts a source to one short line. */
function shortSource(source: string, max = 70): string {
  const line = source.replace(/\s+/g, ' ').trim();
  return line.length > max ? `${line.slice(0, max - 1)}…` : line;
}

export function modelSummary(model: Model): string {
  const h = model.route === 'vector-field' || model.route === 'gradient' ? '' : `, H = ${shortSource(model.source)}`;
  // The method is named only when it is not the default RK 3/8.
  const method = model.method ? `, ${model.method.name}` : '';
  return `Model: ${model.dof} DOF, ${DERIVATIVES[model.route]}${method}${h}`;
}

/** The model with its summary attached (not enumerable: it is no field of the model's). */
export function withSummary<M extends Model>(model: M): M {
  Object.defineProperty(model, SUMMARY, { value: () => modelSummary(model), enumerable: false });
  return model;
}
