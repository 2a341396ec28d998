/**
 * The parts of a running model from compiled-model data (compiled-model.ts):
 * a few `new Function` calls, no mathjs and no acorn. The model comes with
 * RK 3/8's stepper and the parts another method needs; the method itself is
 * applied by its caller (model-from-compiled.ts), so that a page whose
 * models all run RK 3/8, the book's default, never loads the other
 * methods' code (canonical-equations.ts).
 */
import type { CompiledModel, CompiledRoute } from './compiled-model.ts';
import { InputError } from '../errors.ts';
import type { MethodParts } from '../integrators/apply.ts';
import { DEFAULT_METHOD, type MethodChoice } from '../integrators/methods.ts';
import type { JacobianFunction } from '../integrators/midpoint.ts';
import { functionFromSource } from '../js-function/function-source.ts';
import { stencilField, type OpaqueHamiltonian } from '../js-function/stencil.ts';
import { rk38 } from '../integrators/rk38.ts';
import { withSummary } from '../summary.ts';
import type { HamiltonianFunction, Model, Stepper, VectorField } from '../types.ts';

const ACCURACY: Record<CompiledRoute, string> = {
  expression:
    'exact symbolic derivatives: the only errors are the RK 3/8 truncation error, O(dt⁴) over a fixed time, and rounding',
  'js-translated':
    'exact symbolic derivatives: the only errors are the RK 3/8 truncation error, O(dt⁴) over a fixed time, and rounding',
  'js-stencil':
    'H is an opaque function, so its gradient comes from a 5-point central difference with h = ε^(1/5)·max(1, |x|): about 1e-13 relative error per derivative for a smooth H, below the RK 3/8 error at the default dt',
};

/** The parameter values in the compiled order, each checked to be a finite number. */
function parameterValues(compiled: CompiledModel, params: Readonly<Record<string, number>>): Float64Array {
  return Float64Array.from(compiled.paramNames, (name) => {
    const value = params[name];
    if (typeof value !== 'number' || !Number.isFinite(value)) {
      throw new InputError(`the parameter ${name} must be a finite number, not ${String(value)}`);
    }
    return value;
  });
}

/**
 * A running model from compiled data, with RK 3/8's stepper, and the parts
 * `method` needs beside it: `params` gives the parameter values, and
 * `hamiltonian`, for a stencil model, the function itself when H was
 * given as one (its source alone would lose what it closes over).
 * `method` is the integration method, by default the one the code was
 * compiled for (RK 3/8 unless compiled.method says otherwise); code
 * compiled for another method than it is refused.
 */
export function compiledParts(
  compiled: CompiledModel,
  params: Readonly<Record<string, number>> = {},
  hamiltonian?: string | OpaqueHamiltonian,
  method: MethodChoice = compiled.method ? { name: compiled.method } : DEFAULT_METHOD,
): { model: Model; parts: MethodParts } {
  const values = parameterValues(compiled, params);
  const common = {
    dof: compiled.dof,
    dim: 2 * compiled.dof,
    names: compiled.names,
    paramNames: compiled.paramNames,
    params: values,
    route: compiled.route,
    accuracy: ACCURACY[compiled.route],
    source: compiled.source,
  };
  if (compiled.route === 'js-stencil') {
    const opaque = typeof hamiltonian === 'function' ? hamiltonian : undefined;
    return { model: withSummary({ ...common, ...stencilParts(compiled, values, opaque) }), parts: {} };
  }
  const code = compiled.code!;
  const { nonHamiltonian } = compiled;
  // A method that cannot run the terms was refused by canonicalEquations (model/non-hamiltonian.ts), and their
  // code is RK 3/8's, which the check below keeps from any other method's use.
  // code.stepper is RK 3/8's unless the code was generated for a splitting, whose stepper it then is.
  const split = compiled.method === 'verlet' || compiled.method === 'yoshida4';
  const needsOwnCode = method.name === 'verlet' || method.name === 'yoshida4' || method.name === 'midpoint';
  if ((needsOwnCode && compiled.method !== method.name) || (method.name === 'rk38' && split)) {
    throw new Error(`the model was compiled for ${compiled.method ?? 'rk38'}, not for ${method.name}`);
  }
  const advance = new Function(code.stepper)() as Stepper['advance'];
  const model = withSummary({
    ...common,
    stepper: { dim: common.dim, advance },
    field: new Function(code.field)()(values) as VectorField,
    hamiltonian: new Function(code.hamiltonian)()(values) as HamiltonianFunction,
    latex: compiled.latex,
    ...(nonHamiltonian ? { nonHamiltonian } : {}),
  });
  const jacobian = code.jacobian ? exactJacobian(code.jacobian, values, common.dim) : undefined;
  return { model, parts: { split: split ? advance : undefined, jacobian } };
}

/** The generated Jacobian, written into a zeroed matrix of its own and copied out (its zero entries are never written). */
function exactJacobian(source: string, values: Float64Array, dim: number): JacobianFunction {
  const evaluate = new Function(source)()(values) as JacobianFunction;
  const own = new Float64Array(dim * dim);
  return (t, x, out) => {
    evaluate(t, x, own);
    out.set(own);
  };
}

/**
 * The stepper, field and H of an opaque H: a JS function from source gets
 * the parameters as live bindings (refreshed by `sync` before each use), a
 * function object is used as it is.
 */
function stencilParts(compiled: CompiledModel, values: Float64Array, opaque: OpaqueHamiltonian | undefined) {
  const dim = 2 * compiled.dof;
  const built = opaque ? { hamiltonian: opaque, sync: () => {} } : functionFromSource(compiled.source, compiled.paramNames, values);
  const { hamiltonian, sync } = built;
  const field = stencilField(hamiltonian, dim);
  const stepper = rk38(field, dim);
  const scratch = new Float64Array(dim);
  const evaluate: HamiltonianFunction = (t, x, offset = 0) => {
    sync();
    for (let i = 0; i < dim; i++) scratch[i] = x[offset + i];
    return hamiltonian(t, scratch);
  };
  return {
    stepper: {
      dim,
      advance(x: Float64Array, count: number, p: Float64Array, t0: number, k0: number, dt: number, steps: number) {
        sync();
        return stepper.advance(x, count, p, t0, k0, dt, steps);
      },
    },
    hamiltonian: evaluate,
    field: ((t, x, dxdt) => {
      sync();
      field(t, x, dxdt);
    }) as VectorField,
  };
}
