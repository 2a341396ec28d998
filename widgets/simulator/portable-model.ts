/**
 * A model that can be sent to another thread: one whose stepper (and H) is
 * generated code, which closes over nothing but its parameter array and
 * reads no name but Math's (core/expression/fused-stepper.ts). Its source
 * text alone rebuilds it there, the same functions, so a worker computes
 * the same numbers, bit for bit. An opaque JS function, a vector field, or
 * any stepper wrapped in a closure is not portable and stays on the page.
 *
 * The generated functions are recognised by their signatures, whose `$`
 * names no user code can declare (expression/names.ts reserves them).
 */
import type { HamiltonianFunction, Model, Stepper } from '../../core/index.ts';

export interface PortableModel {
  dof: number;
  names: readonly string[];
  paramNames: readonly string[];
  /** `function advance($x, $count, $P, $t0, $k0, $dt, $steps) {…}` */
  stepper: string;
  /** `function ($t, $x, $o = 0) {…}`, reading parameters from `$P`; absent when H is not generated code */
  hamiltonian?: string;
}

const STEPPER = /^function advance\(\$x, \$count, \$P, \$t0, \$k0, \$dt, \$steps\) \{/;
const HAMILTONIAN = /^function \(\$t, \$x, \$o = 0\) \{/;

const portable = new WeakMap<Model, PortableModel | null>();

/** The model as source text, or null when it is not generated code (see the module comment). */
export function portableModel(model: Model): PortableModel | null {
  if (portable.has(model)) return portable.get(model)!;
  const stepper = Function.prototype.toString.call(model.stepper.advance);
  let found: PortableModel | null = null;
  if ((model.route === 'expression' || model.route === 'js-translated') && STEPPER.test(stepper)) {
    const h = model.hamiltonian ? Function.prototype.toString.call(model.hamiltonian) : '';
    found = { dof: model.dof, names: model.names, paramNames: model.paramNames, stepper, ...(HAMILTONIAN.test(h) ? { hamiltonian: h } : {}) };
  }
  portable.set(model, found);
  return found;
}

/** True when H of the model is part of its portable source, so another thread computes it too. */
export function hamiltonianTravels(model: Model): boolean {
  return !!portableModel(model)?.hamiltonian;
}

/** The model rebuilt from its source (in the worker), with `params` as its live parameter array. */
export function modelFromPortable(source: PortableModel, params: Float64Array): Model {
  if (!STEPPER.test(source.stepper) || (source.hamiltonian !== undefined && !HAMILTONIAN.test(source.hamiltonian))) {
    throw new Error('not the code of a generated stepper');
  }
  const dim = 2 * source.dof;
  const advance = new Function(`"use strict";\nreturn ${source.stepper};`)() as Stepper['advance'];
  const hamiltonian = source.hamiltonian
    ? (new Function('$P', `"use strict";\nreturn ${source.hamiltonian};`)(params) as HamiltonianFunction)
    : undefined;
  return {
    dof: source.dof,
    dim,
    names: source.names,
    paramNames: source.paramNames,
    params,
    route: 'expression',
    accuracy: '',
    source: '',
    stepper: { dim, advance },
    hamiltonian,
    field: () => {
      throw new Error('the worker integrates with the stepper alone');
    },
  };
}
