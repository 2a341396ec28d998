import { canonicalEquations, type BuildOptions, type HamiltonianSpec } from '../core/canonical-equations.ts';
import { Simulation, type DerivedSeries } from '../core/simulation.ts';
import type { Model } from '../core/types.ts';
import type { PhasePortraitOptions } from '../plots/phase-portrait.ts';
import type { SpectrumViewOptions } from '../plots/spectrum-view.ts';
import type { TimePlotOptions } from '../plots/time-plot.ts';
import type { TrajectoryOptions } from '../plots/trajectory-view.ts';
import { mount, type SimulatorElement } from './mount.ts';
import {
  BATCH_EVERY, checkOptionNames, defaultCapacity, derivedSeries, flattenInitial, modelSpec, oneLine, recordWidth, viewNames,
  type DerivedFunction, type ViewName,
} from './options.ts';
import { MAX_BATCH, MAX_DOF, MAX_DT, MAX_SPEED, MIN_DT, outside } from '../core/limits.ts';
import { VIEW_MODULES } from './view-modules.ts';
import type { View } from '../plots/view.ts';

export type { SimulatorElement, SimulatorHandle } from './mount.ts';

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
  /** the integration method: 'rk38' (default), 'verlet', 'yoshida4', 'midpoint' or 'adaptive' (with rtol, atol) */
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

/** Each view's module loads only when a simulator shows that view. */
const FACTORIES: Record<ViewName, (o: SimulatorOptions) => Promise<View>> = {
  time: (o) => VIEW_MODULES.time().then((m) => m.timePlot(o.timePlot)),
  trajectory: (o) => VIEW_MODULES.trajectory().then((m) => m.trajectoryView(o.trajectory)),
  phase: (o) => VIEW_MODULES.phase().then((m) => m.phasePortrait(o.phase)),
  spectrum: (o) => VIEW_MODULES.spectrum().then((m) => m.spectrumView(o.spectrum)),
};

/**
 * A running simulation with its controls, readouts, views and data panel:
 * the paper's simulator as one widget. Resolves to the root element
 * (data-widget="simulator", data-ready once every view has drawn); rejects
 * with a one-line Error when the options are wrong. `build` passes on how
 * models are built (the page's compiled models, see canonicalEquations).
 */
export async function simulator(options: SimulatorOptions, build: BuildOptions = {}): Promise<SimulatorElement> {
  if (typeof options !== 'object' || options === null) throw new Error('simulator: pass an options object, e.g. simulator({hamiltonian, initial})');
  checkOptionNames(options);
  checkNumbers(options);
  const names = viewNames(options.views);
  // The views' modules load while the model is built.
  const loading = Promise.all(names.map((name) => FACTORIES[name](options)));
  loading.catch(() => undefined);
  const model = await buildModel(options, build);
  const { values, count } = flattenInitial(options.initial, model.dim);
  if (count > MAX_BATCH) throw new Error(`simulator: a batch of ${count} trajectories is more than the book runs at once, ${MAX_BATCH}`);
  if (model.dof > MAX_DOF) throw new Error(`simulator: ${model.dof} degrees of freedom are more than the book allows, ${MAX_DOF}`);
  const derived = derivedSeries(options.derived, model);
  checkEvaluates(model, values, derived);
  const every = options.every ?? (count > 1 ? BATCH_EVERY : 1);
  const capacity = options.capacity ?? defaultCapacity(recordWidth(model, count, derived.length));
  const make = (dt: number | undefined): Simulation => {
    try {
      return new Simulation(model, { initial: values, dt, every, derived, capacity });
    } catch (error) {
      throw new Error(`simulator: ${oneLine(error)}`);
    }
  };
  const simulation = make(options.dt);
  const views = await loading;
  return mount(options, model, simulation, views, make);
}

async function buildModel(options: SimulatorOptions, build: BuildOptions): Promise<Model> {
  if (options.model) {
    if (options.dof !== undefined && options.dof !== options.model.dof) throw new Error(`simulator: dof ${options.dof} does not match the model's ${options.model.dof}`);
    return options.model;
  }
  const spec = modelSpec(options);
  try {
    return await canonicalEquations(spec, build);
  } catch (error) {
    throw new Error(`simulator: ${oneLine(error)}`);
  }
}

/** Speed, dt, dof and capacity, checked here so their messages name the option (limits.ts). */
function checkNumbers(options: SimulatorOptions): void {
  const { speed, capacity, dt, dof } = options;
  if (speed !== undefined && !(typeof speed === 'number' && speed > 0 && Number.isFinite(speed))) {
    throw new Error(`simulator: speed must be a positive number of time units per second, not ${String(speed)}`);
  }
  const bound =
    (speed !== undefined ? outside('speed', speed, 0, MAX_SPEED, ' time units per second') : null)
    ?? (dt !== undefined ? outside('dt', Number(dt), MIN_DT, MAX_DT) : null)
    ?? (dof !== undefined ? outside('dof', Number(dof), 1, MAX_DOF) : null);
  if (bound) throw new Error(`simulator: ${bound}`);
  if (capacity !== undefined && !(Number.isInteger(capacity) && capacity >= 2)) {
    throw new Error(`simulator: capacity must be a whole number of rows, at least 2, not ${String(capacity)}`);
  }
}

/** Evaluates H and the derived series once, so a mistake is reported now rather than as NaN later. */
function checkEvaluates(model: Model, initial: Float64Array, derived: readonly DerivedSeries[]): void {
  const rate = new Float64Array(model.dim);
  const check = (what: string, f: () => unknown): void => {
    try {
      const v = f();
      if (typeof v === 'number' && Number.isNaN(v)) throw new Error('it is NaN');
    } catch (error) {
      throw new Error(`simulator: ${what} at the initial state: ${oneLine(error)}`);
    }
  };
  check('Hamilton’s equations fail', () => model.field(0, initial, rate));
  if (model.hamiltonian) check('H fails', () => model.hamiltonian!(0, initial, 0));
  for (const d of derived) check(`the derived series ${d.name} fails`, () => d.evaluate(0, initial, 0));
}
