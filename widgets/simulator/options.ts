import { capacityFor } from '../core/capacity.ts';
import type { HamiltonianSpec } from '../core/canonical-equations.ts';
import { methodChoice } from '../core/integrators/methods.ts';
import type { DerivedSeries } from '../core/simulation.ts';
import type { Model } from '../core/types.ts';

/**
 * Checking and normalising what a cell passes to simulator(). Every problem
 * is an Error with a one-line message, which the cell shows under itself.
 */

/** A derived series as a cell writes it: x is this trajectory's state [q…, p…], H its energy (NaN without H). */
export type DerivedFunction = (t: number, x: Float64Array, H: number) => number;

export const VIEW_NAMES = ['time', 'trajectory', 'phase', 'spectrum'] as const;
export type ViewName = (typeof VIEW_NAMES)[number];

/** Memory for a simulator's record when no capacity is given. */
export const RECORD_BYTES = 64 * 2 ** 20;
/** Most rows kept by default, whatever the memory allows. */
export const MAX_ROWS = 1_000_000;
/** Steps between samples of a batch by default: a beam needs no 2000 samples per time unit. */
export const BATCH_EVERY = 20;

const KNOWN = [
  'hamiltonian', 'vectorField', 'gradient', 'model', 'dof', 'initial', 'params', 'dt', 'every', 'speed', 'derived',
  'capacity', 'views', 'timePlot', 'spectrum', 'trajectory', 'phase', 'coordinates', 'momenta', 'autoplay',
  'invalidation', 'label', 'differentiation', 'method', 'rtol', 'atol',
];

/** Throws on an option name that is not known, suggesting the closest known one. */
export function checkOptionNames(options: object): void {
  for (const key of Object.keys(options)) {
    if (KNOWN.includes(key)) continue;
    const near = KNOWN.find((k) => editDistance(k.toLowerCase(), key.toLowerCase()) <= 2);
    throw new Error(`simulator: unknown option "${key}"${near ? `; did you mean "${near}"?` : ''}`);
  }
}

/** What simulator() options say about the model, when they define it rather than pass one. */
export interface ModelOptions extends Omit<HamiltonianSpec, 'dof' | 'method'> {
  dof?: number;
  initial?: unknown;
  /** rk38 (default), verlet, yoshida4, midpoint or adaptive (core/integrators/methods.ts) */
  method?: unknown;
  /** the adaptive method's tolerances */
  rtol?: unknown;
  atol?: unknown;
}

/**
 * The model spec of simulator() options that define a model (hamiltonian,
 * vectorField or gradient), with dof taken from `initial` when not given.
 * The build reads the same spec from a chapter's cells, so the model it
 * compiles ahead is the one the simulator asks for.
 */
export function modelSpec(options: ModelOptions): HamiltonianSpec {
  if (options.hamiltonian === undefined && !options.vectorField && !options.gradient) {
    throw new Error('simulator: give a hamiltonian (or a model, vectorField or gradient)');
  }
  const dof = options.dof ?? flattenInitial(options.initial).dim / 2;
  if (!Number.isInteger(dof) || dof < 1) throw new Error(`simulator: dof must be a whole number ≥ 1, not ${dof}`);
  const { hamiltonian, vectorField, gradient, params, coordinates, momenta, differentiation } = options;
  let method;
  try {
    method = methodChoice(options.method ?? 'rk38', options.rtol, options.atol);
  } catch (error) {
    throw new Error(`simulator: ${(error as Error).message}`);
  }
  // RK 3/8 is left out of the spec, so the default model's spec (and its compiled model) is what it was.
  return { dof, hamiltonian, vectorField, gradient, params, coordinates, momenta, differentiation, ...(method.name === 'rk38' ? {} : { method }) };
}

/**
 * The initial state(s) as one flat array: a list of numbers is one
 * trajectory, a list of lists a batch. `dim` (2·dof), when known, is checked.
 */
export function flattenInitial(initial: unknown, dim?: number): { values: Float64Array; count: number; dim: number } {
  if (!isList(initial) || initial.length === 0) throw new Error('simulator: initial must be a list of numbers [q…, p…], or a list of such lists for a batch');
  const rows: ArrayLike<unknown>[] = isList(initial[0]) ? Array.from(initial as ArrayLike<ArrayLike<unknown>>) : [initial];
  const width = rows[0].length;
  const expected = dim ?? width;
  rows.forEach((row, j) => {
    const which = rows.length > 1 ? `initial[${j}]` : 'initial';
    if (!isList(row)) throw new Error(`simulator: ${which} is not a list of numbers`);
    if (row.length !== expected) {
      const need = dim === undefined ? `${width}, like initial[0]` : `${dim} (q's then p's for ${dim / 2} degree(s) of freedom)`;
      throw new Error(`simulator: ${which} has ${row.length} value${row.length === 1 ? '' : 's'}; it needs ${need}`);
    }
    for (let i = 0; i < row.length; i++) {
      if (typeof row[i] !== 'number' || !Number.isFinite(row[i])) throw new Error(`simulator: ${which}[${i}] is ${String(row[i])}, not a finite number`);
    }
  });
  if (expected === 0 || expected % 2 !== 0) throw new Error(`simulator: initial has ${expected} values; a state is q's then p's, so it needs an even number`);
  const values = new Float64Array(rows.length * expected);
  rows.forEach((row, j) => values.set(Array.from(row as ArrayLike<number>), j * expected));
  return { values, count: rows.length, dim: expected };
}

/**
 * The derived series of the options: an object of (t, x, H) functions, or
 * core DerivedSeries {name, evaluate(t, state, offset)}. Names may not clash
 * with t, H or the state's.
 */
export function derivedSeries(derived: unknown, model: Model): DerivedSeries[] {
  if (derived === undefined) return [];
  if (typeof derived !== 'object' || derived === null) {
    throw new Error('simulator: derived must be an object of functions, e.g. {I: (t, [q, p], H) => H / omega}');
  }
  const series: DerivedSeries[] = Array.isArray(derived)
    ? derived.map((d: Partial<DerivedSeries>, i) => {
        if (typeof d?.evaluate !== 'function') throw new Error(`simulator: derived[${i}] must be {name, evaluate(t, x, offset)}`);
        return { name: String(d.name), evaluate: d.evaluate };
      })
    : Object.entries(derived).map(([name, f]) => {
        if (typeof f !== 'function') throw new Error(`simulator: derived.${name} must be a function (t, x, H) => number`);
        return wrap(name, f as DerivedFunction, model);
      });
  const taken = new Set(['t', 'H', ...model.names]);
  for (const { name } of series) {
    if (!/^[A-Za-z_]\w*$/.test(name)) throw new Error(`simulator: "${name}" cannot name a derived series; use letters, digits and _`);
    if (taken.has(name)) {
      const what = name === 't' ? 'time' : name === 'H' ? 'the energy' : 'a state component';
      throw new Error(`simulator: the derived series "${name}" has the name of ${what}`);
    }
    taken.add(name);
  }
  return series;
}

/** A cell's (t, x, H) function as a core DerivedSeries over a (possibly batched) state array. */
function wrap(name: string, f: DerivedFunction, model: Model): DerivedSeries {
  const x = new Float64Array(model.dim);
  const h = model.hamiltonian;
  return {
    name,
    evaluate(t, state, offset) {
      for (let i = 0; i < x.length; i++) x[i] = state[offset + i];
      return Number(f(t, x, h ? h(t, state, offset) : NaN));
    },
  };
}

/** Columns of a record: t, the states, then H (if known) and the derived series per trajectory. */
export function recordWidth(model: Model, count: number, derived: number): number {
  return 1 + count * (model.dim + derived + (model.hamiltonian ? 1 : 0));
}

/** The record's capacity: as given, else what RECORD_BYTES holds, at most MAX_ROWS. */
export function defaultCapacity(width: number): number {
  return Math.min(MAX_ROWS, capacityFor(RECORD_BYTES, width));
}

/** The views requested, checked. */
export function viewNames(views: unknown): ViewName[] {
  const list = views === undefined ? ['time'] : typeof views === 'string' ? [views] : views;
  if (!Array.isArray(list)) throw new Error(`simulator: views must be a list such as ['time', 'phase']`);
  return list.map((v) => {
    if (!VIEW_NAMES.includes(v)) throw new Error(`simulator: unknown view ${JSON.stringify(v)}; choose from ${VIEW_NAMES.join(', ')}`);
    return v as ViewName;
  });
}

/** The first line of an error's message, for a one-line report. */
export function oneLine(error: unknown): string {
  const text = error instanceof Error ? error.message : String(error);
  return text.split('\n')[0].trim();
}

function isList(v: unknown): v is ArrayLike<unknown> {
  return Array.isArray(v) || (ArrayBuffer.isView(v) && !(v instanceof DataView));
}

function editDistance(a: string, b: string): number {
  const d = Array.from({ length: b.length + 1 }, (_, j) => j);
  for (let i = 1; i <= a.length; i++) {
    let diagonal = d[0];
    d[0] = i;
    for (let j = 1; j <= b.length; j++) {
      const above = d[j];
      d[j] = Math.min(d[j] + 1, d[j - 1] + 1, diagonal + (a[i - 1] === b[j - 1] ? 0 : 1));
      diagonal = above;
    }
  }
  return d[b.length];
}
