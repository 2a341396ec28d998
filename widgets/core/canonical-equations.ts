import { InputError } from './errors.ts';
import { expressionModel } from './expression/compile.ts';
import { stateNames } from './expression/names.ts';
import { functionFromSource, isFunctionSource, parseFunction } from './js-function/compile.ts';
import { gradientField, stencilField, type OpaqueHamiltonian } from './js-function/stencil.ts';
import { translateFunction } from './js-function/translate.ts';
import { rk38 } from './rk38.ts';
import type { HamiltonianFunction, Model, Route, VectorField } from './types.ts';

/**
 * What defines a model: `hamiltonian` (a math expression, JS function source,
 * or a JS function), or else `vectorField` or `gradient`, which may come with
 * a `hamiltonian` function used only for readouts.
 */
export interface HamiltonianSpec {
  dof: number;
  hamiltonian?: string | OpaqueHamiltonian;
  /** dx/dt written by the author */
  vectorField?: VectorField;
  /** ∇H = (∂H/∂q…, ∂H/∂p…) written by the author */
  gradient?: VectorField;
  params?: Readonly<Record<string, number>>;
  /** names of the coordinates q (default q0…, or q for one degree of freedom) */
  coordinates?: readonly string[];
  /** names of the momenta p (default p0…, or p) */
  momenta?: readonly string[];
  /** 'stencil' forces finite differences for a JS function, to compare routes */
  differentiation?: 'auto' | 'stencil';
}

/**
 * Hamilton's canonical equations q̇ = ∂H/∂p, ṗ = −∂H/∂q (the paper's eq. 4)
 * for a model, by the most exact route its definition allows:
 * - a math expression gets exact symbolic derivatives and a fused stepper;
 * - a JS function whose body is arithmetic, Math functions and parameters is
 *   translated to an expression and gets the same;
 * - any other JS function gets 5-point central differences;
 * - a vector field or gradient is used as given.
 */
export async function canonicalEquations(spec: HamiltonianSpec): Promise<Model> {
  const fields = [spec.vectorField, spec.gradient].filter((v) => v !== undefined).length;
  if (fields > 1 || (fields === 0 && spec.hamiltonian === undefined)) {
    throw new InputError('give a hamiltonian, or one of vectorField and gradient (with an optional hamiltonian function for readouts)');
  }
  const { names } = stateNames(spec.dof, spec.coordinates, spec.momenta);
  const params = spec.params ?? {};
  const common = { dof: spec.dof, params, coordinates: spec.coordinates, momenta: spec.momenta };

  if (spec.vectorField) return fieldModel(spec, names, 'vector-field', spec.vectorField, String(spec.vectorField));
  if (spec.gradient) {
    return fieldModel(spec, names, 'gradient', gradientField(spec.gradient, 2 * spec.dof), String(spec.gradient));
  }
  const h = spec.hamiltonian!;
  if (typeof h === 'string' && !isFunctionSource(h)) return expressionModel({ ...common, source: h });

  const source = typeof h === 'string' ? h : h.toString();
  const program = await parseFunction(source);
  if (spec.differentiation !== 'stencil') {
    const translated = translateFunction(program, names, Object.keys(params));
    if ('expression' in translated) {
      try {
        return await expressionModel({ ...common, source: translated.expression, route: 'js-translated', original: source });
      } catch (error) {
        // A function mathjs cannot differentiate: finite differences still work.
        if (!(error instanceof InputError) || !/differentiate/.test(error.message)) throw error;
      }
    }
  }
  const values = Float64Array.from(Object.keys(params), (n) => params[n]);
  const built =
    typeof h === 'string'
      ? functionFromSource(h, Object.keys(params), values)
      : { hamiltonian: h, sync: () => {} };
  return stencilModel(spec, names, built.hamiltonian, built.sync, values, source);
}

function stencilModel(
  spec: HamiltonianSpec,
  names: string[],
  hamiltonian: OpaqueHamiltonian,
  sync: () => void,
  values: Float64Array,
  source: string,
): Model {
  const dim = 2 * spec.dof;
  const field = stencilField(hamiltonian, dim);
  const stepper = rk38(field, dim);
  const scratch = new Float64Array(dim);
  const evaluate: HamiltonianFunction = (t, x, offset = 0) => {
    sync();
    for (let i = 0; i < dim; i++) scratch[i] = x[offset + i];
    return hamiltonian(t, scratch);
  };
  return {
    dof: spec.dof,
    dim,
    names,
    paramNames: Object.keys(spec.params ?? {}),
    params: values,
    route: 'js-stencil',
    accuracy:
      'H is an opaque function, so its gradient comes from a 5-point central difference with h = ε^(1/5)·max(1, |x|): about 1e-13 relative error per derivative for a smooth H, below the RK 3/8 error at the default dt',
    source,
    stepper: {
      dim,
      advance(x, count, p, t0, k0, dt, steps) {
        sync();
        return stepper.advance(x, count, p, t0, k0, dt, steps);
      },
    },
    hamiltonian: evaluate,
    field: (t, x, dxdt) => {
      sync();
      field(t, x, dxdt);
    },
  };
}

function fieldModel(spec: HamiltonianSpec, names: string[], route: Route, field: VectorField, source: string): Model {
  const dim = 2 * spec.dof;
  const params = spec.params ?? {};
  const h = spec.hamiltonian;
  return {
    dof: spec.dof,
    dim,
    names,
    paramNames: Object.keys(params),
    params: Float64Array.from(Object.keys(params), (n) => params[n]),
    route,
    accuracy: 'the vector field is the author’s own, so its accuracy is theirs; the integration adds the RK 3/8 error, O(dt⁴)',
    source,
    stepper: rk38(field, dim),
    field,
    hamiltonian: typeof h === 'function' ? opaqueAsHamiltonian(h, dim) : undefined,
  };
}

function opaqueAsHamiltonian(h: OpaqueHamiltonian, dim: number): HamiltonianFunction {
  const scratch = new Float64Array(dim);
  return (t, x, offset = 0) => {
    for (let i = 0; i < dim; i++) scratch[i] = x[offset + i];
    return h(t, scratch);
  };
}
