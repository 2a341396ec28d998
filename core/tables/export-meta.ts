import type { MethodChoice } from '../integrators/methods.ts';
import type { Simulation } from '../simulation.ts';
import { VERSION } from '../version.ts';

/** What an export says about how its numbers came about. */
export interface ExportMeta {
  /** Source of H (expression or function text). */
  hamiltonian: string;
  params: Record<string, number>;
  dof: number;
  dt: number;
  method: string;
  /** the adaptive method's tolerances */
  rtol?: number;
  atol?: number;
  /** Steps between samples. */
  every: number;
  t0: number;
  initial: number[];
  route?: string;
  names?: string[];
  derived?: string[];
  count?: number;
  version: string;
  /** Rows lost to the record's capacity before the export began. */
  dropped?: number;
  /** Exports from the book: the cells the reader had changed or added on the page, and their code. */
  provenance?: { page: string; cells: readonly { cell: string; source: string; added: boolean }[] };
  [key: string]: unknown;
}

/** The default integration method: the classical Runge–Kutta 3/8 rule, as in the paper. */
export const METHOD = 'rk38';

/**
 * The method keys of a meta: `method`, and for the adaptive method its
 * tolerances `rtol` and `atol`, which decide its numbers as dt does a fixed
 * step's.
 */
export function methodMeta(method: MethodChoice | undefined): Pick<ExportMeta, 'method' | 'rtol' | 'atol'> {
  if (!method) return { method: METHOD };
  if (method.name !== 'adaptive') return { method: method.name };
  return { method: method.name, rtol: method.rtol, atol: method.atol };
}

/**
 * The metadata of an export of a simulation's record, with the keys and key
 * order of `phasebook simulate` (cli/commands/simulate.ts): the source of H,
 * parameters, dof, dt, method (with rtol and atol for the adaptive one), sampling interval, t0, the initial state, the
 * route the canonical equations took, the state and derived names and the
 * version; then, only when they apply, the batch size (`count`) and the rows
 * the record had dropped (`dropped`).
 */
export function exportMeta(simulation: Simulation): ExportMeta {
  const { model } = simulation;
  const params: Record<string, number> = {};
  model.paramNames.forEach((name, i) => (params[name] = model.params[i]));
  const meta: ExportMeta = {
    hamiltonian: model.source,
    params,
    dof: model.dof,
    dt: simulation.dt,
    ...methodMeta(model.method),
    every: simulation.every,
    t0: simulation.t0,
    initial: Array.from(simulation.initial),
    route: model.route,
    names: [...model.names],
    derived: simulation.derived.map((d) => d.name),
    version: VERSION,
  };
  if (simulation.count > 1) meta.count = simulation.count;
  if (simulation.record.dropped > 0) meta.dropped = simulation.record.dropped;
  return meta;
}
