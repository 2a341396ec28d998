/**
 * The shapes shared by every part of the core. A state vector is always laid
 * out as `[q0 … q(n-1), p0 … p(n-1)]` for n degrees of freedom, and a batch of
 * M trajectories of one model is M such vectors back to back in one
 * Float64Array.
 */

import type { MethodChoice } from './integrators/methods.ts';

/** Writes dx/dt at (t, x) into `dxdt`; both have length 2·dof. */
export type VectorField = (t: number, x: Float64Array, dxdt: Float64Array) => void;

/** Evaluates H at (t, x) where x starts at `offset` in a (possibly batched) state array. */
export type HamiltonianFunction = (t: number, x: Float64Array, offset?: number) => number;

/**
 * Advances trajectories by whole steps of the model's method (RK 3/8 unless
 * the model says otherwise; for the adaptive method a "step" is one
 * interval between samples, integrated in steps of its own choosing). Step k of a run starts at
 * t = t0 + k·dt, computed rather than accumulated so that long runs carry no
 * summed rounding in t.
 */
export interface Stepper {
  /** 2·dof */
  readonly dim: number;
  /**
   * Advances `count` trajectories packed in `x` by `steps` steps, the first of
   * which is step number `k0`. Returns the number of steps that every
   * trajectory completed with a finite state; if that is less than `steps`,
   * the trajectory that failed holds the first non-finite state it reached.
   */
  advance(
    x: Float64Array,
    count: number,
    params: Float64Array,
    t0: number,
    k0: number,
    dt: number,
    steps: number,
  ): number;
}

/** How the canonical equations of a model were obtained. */
export type Route =
  | 'expression' // H as a math expression, exact symbolic derivatives
  | 'js-translated' // H as a JS function translated to an expression
  | 'js-stencil' // H as an opaque JS function, 5-point central differences
  | 'vector-field' // dx/dt supplied by the author
  | 'gradient'; // ∇H supplied by the author

/**
 * Terms added to Hamilton's equations, by state component name, each a math
 * expression in H's syntax, names and parameters: e.g. `{p: '-gamma*p'}`
 * (model/non-hamiltonian.ts).
 */
export type NonHamiltonianTerms = Readonly<Record<string, string>>;

/** What a model says of its non-Hamiltonian terms: see Model.nonHamiltonian. */
export interface NonHamiltonianPart {
  /** the terms as given, in the order of the state */
  readonly terms: NonHamiltonianTerms;
  /** the LaTeX of each term, by component name */
  readonly latex?: Readonly<Record<string, string>>;
}

/** A Hamiltonian system ready to integrate: model, not solver, not view. */
export interface Model {
  readonly dof: number;
  /** 2·dof */
  readonly dim: number;
  /** Names of the state components, q's then p's: e.g. ['q', 'p'] or ['q0', 'q1', 'p0', 'p1']. */
  readonly names: readonly string[];
  /** Parameter names, in the order of `params`. */
  readonly paramNames: readonly string[];
  /** Current parameter values; writing one takes effect at the next step, with no recompilation. */
  readonly params: Float64Array;
  readonly route: Route;
  /** One sentence on the accuracy of the canonical equations for this route. */
  readonly accuracy: string;
  /** The source of H as given (expression or function text), for export metadata. */
  readonly source: string;
  readonly stepper: Stepper;
  /** The integration method of `stepper`, when it is not RK 3/8 (integrators/methods.ts). */
  readonly method?: MethodChoice;
  /** H itself, when known (not for a bare vector field). */
  readonly hamiltonian?: HamiltonianFunction;
  /** dx/dt at one state, for readouts and tests. */
  readonly field: VectorField;
  /** LaTeX of H and of Hamilton's equations, when H is symbolic (the equations with any non-Hamiltonian term in them). */
  readonly latex?: { readonly hamiltonian: string; readonly equations: readonly string[] };
  /**
   * Present when the flow is not Hamiltonian: the terms added to Hamilton's
   * equations, ẋ_i = (Ω∇H)_i + term_i (a friction −γp, say), by state
   * component, with their LaTeX. Such a flow is not canonical and does not
   * conserve H, so the canonical checks (analysis/flow-map.ts,
   * analysis/energy-drift.ts) say it is outside their validity, and the
   * symplectic methods refuse it. `stepper`, `field` and `latex` include the
   * terms; `hamiltonian` is H alone.
   */
  readonly nonHamiltonian?: NonHamiltonianPart;
}
