import {
  canonicalEquations, capacityFor, DEFAULT_METHOD, firstEvaluation, InputError, MAX_BATCH, MAX_DOF, MAX_DT, MAX_SPEED, methodChoice, MIN_DT, outside,
  Simulation, type BuildOptions, type DerivedSeries, type HamiltonianSpec, type MethodChoice, type Model,
} from '../../core/index.ts';
import type { PhasePortraitOptions } from '../plots/plane/phase-portrait.ts';
import type { SpectrumViewOptions } from '../plots/spectrum/spectrum-view.ts';
import type { TimePlotOptions } from '../plots/time/time-plot.ts';
import type { TrajectoryOptions } from '../plots/plane/trajectory-view.ts';

/**
 * What a cell passes to simulator(), turned in one step into settings the
 * widget only reads (parseSimulatorOptions). Every problem is an InputError
 * with a one-line message starting "simulator: ", which the cell shows
 * under itself; every such message is written here.
 */

/** A derived series as a cell writes it: x is this trajectory's state [q…, p…], H its energy (NaN without H). */
export type DerivedFunction = (t: number, x: Float64Array, H: number) => number;

export const VIEW_NAMES = ['time', 'trajectory', 'phase', 'spectrum'] as const;
export type ViewName = (typeof VIEW_NAMES)[number];

export interface SimulatorOptions {
  /** H as a math expression ('p^2/2 + q^2/2') or a JS function (t, x) => … (source or function) */
  hamiltonian?: HamiltonianSpec['hamiltonian'];
  vectorField?: HamiltonianSpec['vectorField'];
  gradient?: HamiltonianSpec['gradient'];
  /** a ready model instead of a hamiltonian */
  model?: Model;
  /** degrees of freedom; inferred from `initial` when left out */
  dof?: number;
  /** [q…, p…], or a list of them for a batch of trajectories */
  initial: readonly number[] | readonly (readonly number[])[] | Float64Array;
  params?: Readonly<Record<string, number>>;
  /** time step (default 5e-4) */
  dt?: number;
  /** steps between samples (default 1; 20 for a batch) */
  every?: number;
  /** simulated time per real second (default 1) */
  speed?: number;
  /** series computed from each sample, e.g. {I: (t, x, H) => H / (4 + 0.05 * t)} */
  derived?: Readonly<Record<string, DerivedFunction>> | readonly DerivedSeries[];
  /** rows the record keeps (default: what 64 MiB holds, at most a million) */
  capacity?: number;
  views?: readonly ViewName[];
  timePlot?: TimePlotOptions;
  spectrum?: SpectrumViewOptions;
  trajectory?: TrajectoryOptions;
  phase?: PhasePortraitOptions;
  coordinates?: readonly string[];
  momenta?: readonly string[];
  differentiation?: HamiltonianSpec['differentiation'];
  /**
   * the integration method: 'rk38' (default), 'verlet', 'yoshida4', 'midpoint' or 'adaptive' (with rtol, atol);
   * with a model, the model's own unless given ('midpoint' and 'adaptive' apply to any model)
   */
  method?: string;
  rtol?: number;
  atol?: number;
  /** start running at once (default true) */
  autoplay?: boolean;
  /** the cell's invalidation promise: the simulator stops and frees its memory when it resolves */
  invalidation?: Promise<unknown>;
  /** an accessible name for the widget */
  label?: string;
}

/** The options each view is made with. */
export type ViewOptions = Pick<SimulatorOptions, 'timePlot' | 'spectrum' | 'trajectory' | 'phase'>;

/** simulator()'s options, checked: everything the widget needs, and nothing it must check again. */
export interface SimulatorSettings {
  /** the model to run: built from the options, or the one given, run by the method asked for */
  readonly model: Model;
  readonly views: readonly ViewName[];
  readonly viewOptions: ViewOptions;
  /** the simulation the options describe, not yet started */
  readonly simulation: Simulation;
  /** the same simulation with another time step (the widget's dt field); throws a one-line InputError */
  readonly withDt: (dt: number) => Simulation;
  readonly speed?: number;
  readonly autoplay?: boolean;
  readonly invalidation?: Promise<unknown>;
  readonly label?: string;
}

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
] as const satisfies readonly (keyof SimulatorOptions)[];

// KNOWN names every option, or this fails to compile: the check and the documented options (the editor's catalogue) agree.
true satisfies [Exclude<keyof SimulatorOptions, (typeof KNOWN)[number]>] extends [never] ? true : never;

/** The options that go into building a model, which a given model has had already. */
const MODEL_BUILDING = ['hamiltonian', 'vectorField', 'gradient', 'params', 'coordinates', 'momenta', 'differentiation'] as const;

/**
 * The one step from a cell's options to the simulator's settings: names,
 * numbers and views checked, the model built (or the given one checked and
 * run by the method asked for), the initial states flattened and bounded,
 * the derived series named, H and them evaluated once, and the simulation
 * made. Throws one InputError, "simulator: …", at the first problem.
 * `onViews` hears the views as soon as they are checked, before the model
 * is built, so that their modules load meanwhile. `build` passes on how
 * models are built (the page's compiled models, see canonicalEquations).
 */
export async function parseSimulatorOptions(
  raw: unknown,
  build: BuildOptions = {},
  onViews?: (views: readonly ViewName[], options: ViewOptions) => void,
): Promise<SimulatorSettings> {
  if (typeof raw !== 'object' || raw === null) throw fail('pass an options object, e.g. simulator({hamiltonian, initial})');
  checkOptionNames(raw);
  const options = raw as SimulatorOptions;
  checkNumbers(options);
  const { timePlot, spectrum, trajectory, phase } = options;
  const viewOptions: ViewOptions = { timePlot, spectrum, trajectory, phase };
  const views = viewNames(options.views);
  onViews?.(views, viewOptions);

  const model = options.model != null ? await givenModel(options) : await builtModel(options, build);
  const { values: initial, count } = flattenInitial(options.initial, model.dim);
  if (count > MAX_BATCH) throw fail(`a batch of ${count} trajectories is more than the book runs at once, ${MAX_BATCH}`);
  if (model.dof > MAX_DOF) throw fail(`${model.dof} degrees of freedom are more than the book allows, ${MAX_DOF}`);
  const derived = derivedSeries(options.derived, model);
  checkEvaluates(model, initial, derived);
  const every = options.every ?? (count > 1 ? BATCH_EVERY : 1);
  const capacity = options.capacity ?? defaultCapacity(recordWidth(model, count, derived.length));
  const withDt = (dt: number | undefined): Simulation => {
    try {
      return new Simulation(model, { initial, dt, every, derived, capacity });
    } catch (error) {
      throw fail(oneLine(error));
    }
  };
  const { speed, autoplay, invalidation, label } = options;
  return { model, views, viewOptions, simulation: withDt(options.dt), withDt, speed, autoplay, invalidation, label };
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
    throw fail('give a hamiltonian (or a model, vectorField or gradient)');
  }
  const dof = options.dof ?? flattenInitial(options.initial).dim / 2;
  if (!Number.isInteger(dof) || dof < 1) throw fail(`dof must be a whole number ≥ 1, not ${dof}`);
  const { hamiltonian, vectorField, gradient, params, coordinates, momenta, differentiation } = options;
  const method = checkedMethod(options.method ?? 'rk38', options.rtol, options.atol);
  // RK 3/8 is left out of the spec, so the default model's spec (and its compiled model) is what it was.
  return { dof, hamiltonian, vectorField, gradient, params, coordinates, momenta, differentiation, ...(method.name === 'rk38' ? {} : { method }) };
}

/** The views requested, checked (also by the build's reservation of the widget's box, reserve.ts). */
export function viewNames(views: unknown): ViewName[] {
  const list = views === undefined ? ['time'] : typeof views === 'string' ? [views] : views;
  if (!Array.isArray(list)) throw fail(`views must be a list such as ['time', 'phase']`);
  return list.map((v) => {
    if (!VIEW_NAMES.includes(v)) throw fail(`unknown view ${JSON.stringify(v)}; choose from ${VIEW_NAMES.join(', ')}`);
    return v as ViewName;
  });
}

/** Columns of a record: t, the states, then H (if known) and the derived series per trajectory. */
export function recordWidth(model: Model, count: number, derived: number): number {
  return 1 + count * (model.dim + derived + (model.hamiltonian ? 1 : 0));
}

/** The record's capacity: as given, else what RECORD_BYTES holds, at most MAX_ROWS. */
export function defaultCapacity(width: number): number {
  return Math.min(MAX_ROWS, capacityFor(RECORD_BYTES, width));
}

/** The first line of an error's message, for a one-line report. */
export function oneLine(error: unknown): string {
  const text = error instanceof Error ? error.message : String(error);
  return text.split('\n')[0].trim();
}

function fail(message: string): InputError {
  return new InputError(`simulator: ${message}`);
}

/** Throws on an option name that is not known, suggesting the closest known one. */
function checkOptionNames(options: object): void {
  const known: readonly string[] = KNOWN;
  for (const key of Object.keys(options)) {
    if (known.includes(key)) continue;
    const near = known.find((k) => editDistance(k.toLowerCase(), key.toLowerCase()) <= 2);
    throw fail(`unknown option "${key}"${near ? `; did you mean "${near}"?` : ''}`);
  }
}

/** Speed, dt, dof and capacity, checked here so their messages name the option (limits.ts); and the invalidation promise. */
function checkNumbers(options: SimulatorOptions): void {
  const { speed, capacity, dt, dof, invalidation } = options;
  if (speed !== undefined && !(typeof speed === 'number' && speed > 0 && Number.isFinite(speed))) {
    throw fail(`speed must be a positive number of time units per second, not ${String(speed)}`);
  }
  const bound =
    (speed !== undefined ? outside('speed', speed, 0, MAX_SPEED, ' time units per second') : null)
    ?? (dt !== undefined ? outside('dt', Number(dt), MIN_DT, MAX_DT) : null)
    ?? (dof !== undefined ? outside('dof', Number(dof), 1, MAX_DOF) : null);
  if (bound) throw fail(bound);
  if (capacity !== undefined && !(Number.isInteger(capacity) && capacity >= 2)) {
    throw fail(`capacity must be a whole number of rows, at least 2, not ${String(capacity)}`);
  }
  if (invalidation !== undefined && typeof (invalidation as { then?: unknown })?.then !== 'function') {
    throw fail(`invalidation must be the cell's invalidation promise, not ${String(invalidation)}`);
  }
}

/** The model the options define, built (from the page's compiled models when they hold it). */
async function builtModel(options: SimulatorOptions, build: BuildOptions): Promise<Model> {
  const spec = modelSpec(options);
  try {
    return await canonicalEquations(spec, build);
  } catch (error) {
    throw fail(oneLine(error));
  }
}

/**
 * The model the options pass, checked against the rest of them. Options
 * that would build a model are refused rather than dropped: the reader
 * would otherwise run another model than the one they wrote.
 */
async function givenModel(options: SimulatorOptions): Promise<Model> {
  const model: unknown = options.model;
  if (!isModel(model)) {
    const what = typeof (model as { then?: unknown })?.then === 'function'
      ? 'a promise; give the model a cell of its own, model = canonicalEquations({…}), and pass that'
      : String(model);
    throw fail(`model must be a model from canonicalEquations({…}), not ${what}`);
  }
  for (const key of MODEL_BUILDING) {
    if (options[key] !== undefined) throw fail(`${key} goes into building a model, and a model is given; give ${key} to canonicalEquations({…}), or leave out model`);
  }
  if (options.dof !== undefined && options.dof !== model.dof) throw fail(`dof ${options.dof} does not match the model's ${model.dof}`);
  return modelRunBy(model, options);
}

/**
 * A given model run by the method the options name. Left out, the method
 * is the model's own, with its tolerances unless rtol or atol are given.
 * The midpoint rule and the adaptive method need only the model's field,
 * so they apply to any model (the midpoint rule's Newton Jacobian then by
 * central differences, as its accuracy note says). RK 3/8 and the
 * splittings run code generated with the model, so a model built for
 * another method is refused with where to ask for them. The methods' code
 * loads only then: a simulator of the book's models runs them by RK 3/8.
 */
async function modelRunBy(model: Model, options: SimulatorOptions): Promise<Model> {
  const { method, rtol, atol } = options;
  if (method === undefined && rtol === undefined && atol === undefined) return model;
  const own = model.method ?? DEFAULT_METHOD;
  const choice = method === undefined ? checkedMethod(own.name, rtol ?? own.rtol, atol ?? own.atol) : checkedMethod(method, rtol, atol);
  if (choice.name === own.name && choice.rtol === own.rtol && choice.atol === own.atol) return model;
  const { applyMethod } = await import('../../core/integrators/apply.ts');
  if (choice.name === 'midpoint' || choice.name === 'adaptive') return applyMethod(model, choice);
  try {
    // A splitting says first when H cannot be split at all, for which no rebuilding helps.
    if (choice.name !== 'rk38') applyMethod(model, choice);
  } catch (error) {
    if (error instanceof InputError) throw fail(error.message);
  }
  throw fail(
    `the model was built for ${own.name}, and ${choice.name} needs code generated with the model; `
      + `pass method: '${choice.name}' to canonicalEquations({…}), or hamiltonian instead of model`,
  );
}

/** A checked method choice, its message naming the simulator. */
function checkedMethod(name: unknown, rtol: unknown, atol: unknown): MethodChoice {
  try {
    return methodChoice(name, rtol, atol);
  } catch (error) {
    throw fail(oneLine(error));
  }
}

function isModel(value: unknown): value is Model {
  const m = value as Partial<Model> | null;
  return typeof m === 'object' && m !== null && Number.isInteger(m.dof) && m.dim === 2 * m.dof!
    && typeof m.field === 'function' && typeof m.stepper?.advance === 'function';
}

/**
 * The initial state(s) as one flat array: a list of numbers is one
 * trajectory, a list of lists a batch. `dim` (2·dof), when known, is checked.
 */
function flattenInitial(initial: unknown, dim?: number): { values: Float64Array; count: number; dim: number } {
  if (!isList(initial) || initial.length === 0) throw fail('initial must be a list of numbers [q…, p…], or a list of such lists for a batch');
  const rows: ArrayLike<unknown>[] = isList(initial[0]) ? Array.from(initial as ArrayLike<ArrayLike<unknown>>) : [initial];
  const width = rows[0].length;
  const expected = dim ?? width;
  rows.forEach((row, j) => {
    const which = rows.length > 1 ? `initial[${j}]` : 'initial';
    if (!isList(row)) throw fail(`${which} is not a list of numbers`);
    if (row.length !== expected) {
      const need = dim === undefined ? `${width}, like initial[0]` : `${dim} (q's then p's for ${dim / 2} degree(s) of freedom)`;
      throw fail(`${which} has ${row.length} value${row.length === 1 ? '' : 's'}; it needs ${need}`);
    }
    for (let i = 0; i < row.length; i++) {
      if (typeof row[i] !== 'number' || !Number.isFinite(row[i])) throw fail(`${which}[${i}] is ${String(row[i])}, not a finite number`);
    }
  });
  if (expected === 0 || expected % 2 !== 0) throw fail(`initial has ${expected} values; a state is q's then p's, so it needs an even number`);
  const values = new Float64Array(rows.length * expected);
  rows.forEach((row, j) => values.set(Array.from(row as ArrayLike<number>), j * expected));
  return { values, count: rows.length, dim: expected };
}

/**
 * The derived series of the options: an object of (t, x, H) functions, or
 * core DerivedSeries {name, evaluate(t, state, offset)}. Names may not clash
 * with t, H or the state's.
 */
function derivedSeries(derived: unknown, model: Model): DerivedSeries[] {
  if (derived === undefined) return [];
  if (typeof derived !== 'object' || derived === null) {
    throw fail('derived must be an object of functions, e.g. {I: (t, [q, p], H) => H / omega}');
  }
  const series: DerivedSeries[] = Array.isArray(derived)
    ? derived.map((d: Partial<DerivedSeries>, i) => {
        if (typeof d?.evaluate !== 'function') throw fail(`derived[${i}] must be {name, evaluate(t, x, offset)}`);
        return { name: String(d.name), evaluate: d.evaluate };
      })
    : Object.entries(derived).map(([name, f]) => {
        if (typeof f !== 'function') throw fail(`derived.${name} must be a function (t, x, H) => number`);
        return wrap(name, f as DerivedFunction, model);
      });
  const taken = new Set(['t', 'H', ...model.names]);
  for (const { name } of series) {
    if (!/^[A-Za-z_]\w*$/.test(name)) throw fail(`"${name}" cannot name a derived series; use letters, digits and _`);
    if (taken.has(name)) {
      const what = name === 't' ? 'time' : name === 'H' ? 'the energy' : 'a state component';
      throw fail(`the derived series "${name}" has the name of ${what}`);
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

/**
 * Evaluates the equations, H and the derived series once (core's
 * firstEvaluation), so a mistake is reported now rather than as NaN later.
 * At the start of a simulator a NaN H is a mistake too (log(q) at q < 0); a
 * value that is not a number is read as a number, as the record does.
 */
function checkEvaluates(model: Model, initial: Float64Array, derived: readonly DerivedSeries[]): void {
  const fault = firstEvaluation(model, initial, 0, derived).find((f) => f.reason !== 'not a number');
  if (!fault) return;
  const what = fault.part === 'equations' ? 'Hamilton’s equations fail' : fault.part === 'H' ? 'H fails' : `the derived series ${fault.name} fails`;
  const why = fault.reason === 'threw' ? oneLine(fault.error) : fault.reason === 'NaN' ? 'it is NaN' : `the vector field writes no finite rate for ${model.names[fault.component]}`;
  throw fail(`${what} at the initial state: ${why}`);
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
