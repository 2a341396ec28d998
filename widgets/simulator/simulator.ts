import '../widgets.css';
import { canonicalEquations, type HamiltonianSpec } from '../core/canonical-equations.ts';
import { Simulation, type DerivedSeries } from '../core/simulation.ts';
import type { Model } from '../core/types.ts';
import { h } from '../controls/dom.ts';
import { Readouts } from '../controls/readouts.ts';
import { Transport } from '../controls/transport.ts';
import { DataPanel } from '../data/data-panel.ts';
import { phasePortrait, type PhasePortraitOptions } from '../plots/phase-portrait.ts';
import { spectrumView, type SpectrumViewOptions } from '../plots/spectrum-view.ts';
import { timePlot, type TimePlotOptions } from '../plots/time-plot.ts';
import { trajectoryView, type TrajectoryOptions } from '../plots/trajectory-view.ts';
import { Driver } from './driver.ts';
import { Notices } from './notices.ts';
import {
  BATCH_EVERY, checkOptionNames, defaultCapacity, derivedSeries, flattenInitial, oneLine, recordWidth, viewNames,
  type DerivedFunction, type ViewName,
} from './options.ts';
import type { View } from './view.ts';

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
  /** start running at once (default true) */
  autoplay?: boolean;
  /** the cell's invalidation promise: the simulator stops and frees its memory when it resolves */
  invalidation?: Promise<unknown>;
  /** an accessible name for the widget */
  label?: string;
}

/** What a simulator element offers scripts: its driver and the current simulation. */
export interface SimulatorHandle {
  readonly driver: Driver;
  readonly simulation: Simulation;
  readonly model: Model;
  play(): void;
  pause(): void;
  restart(): void;
  step(): void;
  setSpeed(speed: number): void;
  setDt(dt: number): void;
  dispose(): void;
}

export type SimulatorElement = HTMLElement & { simulator: SimulatorHandle };

const FACTORIES: Record<ViewName, (o: SimulatorOptions) => View> = {
  time: (o) => timePlot(o.timePlot),
  trajectory: (o) => trajectoryView(o.trajectory),
  phase: (o) => phasePortrait(o.phase),
  spectrum: (o) => spectrumView(o.spectrum),
};

/**
 * A running simulation with its controls, readouts, views and data panel:
 * the paper's simulator as one widget. Resolves to the root element
 * (data-widget="simulator", data-ready once every view has drawn); rejects
 * with a one-line Error when the options are wrong.
 */
export async function simulator(options: SimulatorOptions): Promise<SimulatorElement> {
  if (typeof options !== 'object' || options === null) throw new Error('simulator: pass an options object, e.g. simulator({hamiltonian, initial})');
  checkOptionNames(options);
  const names = viewNames(options.views);
  const model = await buildModel(options);
  const { values, count } = flattenInitial(options.initial, model.dim);
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
  const views = names.map((name) => FACTORIES[name](options));
  return mount(options, model, simulation, views, make);
}

async function buildModel(options: SimulatorOptions): Promise<Model> {
  if (options.model) {
    if (options.dof !== undefined && options.dof !== options.model.dof) throw new Error(`simulator: dof ${options.dof} does not match the model's ${options.model.dof}`);
    return options.model;
  }
  if (options.hamiltonian === undefined && !options.vectorField && !options.gradient) {
    throw new Error('simulator: give a hamiltonian (or a model, vectorField or gradient)');
  }
  let dof = options.dof;
  if (dof === undefined) dof = flattenInitial(options.initial).dim / 2;
  if (!Number.isInteger(dof) || dof < 1) throw new Error(`simulator: dof must be a whole number ≥ 1, not ${dof}`);
  const { hamiltonian, vectorField, gradient, params, coordinates, momenta, differentiation } = options;
  try {
    return await canonicalEquations({ dof, hamiltonian, vectorField, gradient, params, coordinates, momenta, differentiation });
  } catch (error) {
    throw new Error(`simulator: ${oneLine(error)}`);
  }
}

/** Evaluates H and the derived series once, so a mistake is reported now rather than as NaN later. */
function checkEvaluates(model: Model, initial: Float64Array, derived: readonly DerivedSeries[]): void {
  const rate = new Float64Array(model.dim);
  const check = (what: string, f: () => unknown): void => {
    try {
      const v = f();
      if (typeof v === 'number' && Number.isNaN(v) && what !== 'the equations') throw new Error('it is NaN');
    } catch (error) {
      throw new Error(`simulator: ${what} fails at the initial state: ${oneLine(error)}`);
    }
  };
  check('the equations', () => model.field(0, initial, rate));
  if (model.hamiltonian) check('H', () => model.hamiltonian!(0, initial, 0));
  for (const d of derived) check(`derived series ${d.name}`, () => d.evaluate(0, initial, 0));
}

function mount(
  options: SimulatorOptions,
  model: Model,
  first: Simulation,
  views: View[],
  make: (dt: number) => Simulation,
): SimulatorElement {
  const notices = new Notices();
  const readouts = new Readouts();
  const viewBox = h('div', 'pb-views', {}, ...views.map((v) => v.element));
  const panel = new DataPanel(() =>
    views.flatMap((v) => (v.canvases ? v.canvases().map((c) => ({ name: c.name, canvas: () => v.canvases!().find((d) => d.name === c.name)!.canvas })) : [])),
  );
  const root = h('section', 'pb-simulator', { 'data-widget': 'simulator', tabindex: '-1', 'aria-label': options.label ?? 'Simulator' }) as SimulatorElement;
  const driver = new Driver(first, views, { speed: options.speed, element: root });
  const transport = new Transport(
    {
      toggle: () => driver.toggle(),
      restart: () => driver.restart(),
      step: () => driver.step(),
      setSpeed: (s) => driver.setSpeed(s),
      setDt: (dt) => driver.replace(make(dt)),
    },
    driver.speed,
    first.dt,
  );
  root.append(h('div', 'pb-bar', {}, transport.element, readouts.element), notices.alert, notices.note, viewBox, panel.element);

  let slow = 0;
  driver.on('frame', (stats) => {
    const sim = driver.simulation;
    readouts.update(sim);
    const now = performance.now();
    if (now - slow > 500) {
      slow = now;
      transport.showRate(driver.targetRate, driver.playing ? stats.pace : 1);
      notices.showCap(sim);
      panel.update(sim);
    }
    if (!root.hasAttribute('data-ready') && views.every((v) => v.element.hasAttribute('data-ready'))) root.setAttribute('data-ready', '');
  });
  driver.on('state', ({ playing, error }) => {
    readouts.update(driver.simulation, true);
    panel.update(driver.simulation, true);
    transport.setPlaying(playing, !!error);
    notices.showError(error);
    root.classList.toggle('pb-playing', playing);
  });
  driver.on('reset', (sim) => {
    transport.showDt(sim.dt);
    readouts.reset(sim);
    notices.showCap(sim);
    panel.update(sim, true);
    panel.listPlots();
  });

  root.addEventListener('keydown', (e) => {
    if (e.key !== ' ' || e.ctrlKey || e.metaKey || e.altKey || isControl(e.target)) return;
    e.preventDefault();
    driver.toggle();
  });
  const resize = typeof ResizeObserver === 'undefined' ? null : new ResizeObserver(() => driver.requestDraw());
  resize?.observe(root);
  driver.on('dispose', () => resize?.disconnect());
  void options.invalidation?.then(() => driver.dispose());

  readouts.reset(first);
  panel.update(first, true);
  panel.listPlots();
  views.forEach((v) => v.reset(first));
  transport.setPlaying(false, false);
  driver.requestDraw();
  if (options.autoplay !== false) driver.play();

  root.simulator = {
    driver,
    get simulation() {
      return driver.simulation;
    },
    model,
    play: () => driver.play(),
    pause: () => driver.pause(),
    restart: () => driver.restart(),
    step: () => driver.step(),
    setSpeed: (s) => driver.setSpeed(s),
    setDt: (dt) => driver.replace(make(dt)),
    dispose: () => driver.dispose(),
  };
  return root;
}

/** True for targets that handle Space themselves: buttons, fields, links, editors. */
function isControl(target: EventTarget | null): boolean {
  if (!(target instanceof HTMLElement)) return false;
  return target.isContentEditable || /^(BUTTON|INPUT|SELECT|TEXTAREA|A|SUMMARY)$/.test(target.tagName);
}
