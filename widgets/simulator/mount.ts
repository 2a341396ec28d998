import type { Model, Simulation } from '../../core/index.ts';
import { h, prefersReducedMotion } from '../controls/dom.ts';
import { Readouts } from '../controls/readouts.ts';
import { Transport } from '../controls/transport.ts';
import { DataPanel } from '../exports/data-panel.ts';
import { Driver } from './driver.ts';
import { Notices } from './notices.ts';
import { isBehind } from './pace.ts';
import { spanningViews } from '../plots/sizes.ts';
import type { View } from '../plots/view.ts';
import { offerToCell } from '../controls/widget-input.ts';

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
  /** writes parameters into the model (no recompilation) and restarts from the initial state */
  setParams(values: Readonly<Record<string, number>>): void;
  dispose(): void;
}

export type SimulatorElement = HTMLElement & { simulator: SimulatorHandle };

/** What mount needs of the options: the speed, autoplay, invalidation and label. */
export interface MountOptions {
  speed?: number;
  autoplay?: boolean;
  invalidation?: Promise<unknown>;
  label?: string;
}

/** The pieces of one simulator, wired to its driver. */
interface Parts {
  readonly root: SimulatorElement;
  readonly driver: Driver;
  readonly transport: Transport;
  readonly readouts: Readouts;
  readonly notices: Notices;
  readonly panel: DataPanel;
}

/**
 * Assembles a simulator widget: controls and readouts, the blow-up alert and
 * the capped-record note, the views, and the data panel, all wired to one
 * Driver; `make(dt)` builds the simulation again for a new time step.
 */
export function mount(
  options: MountOptions,
  model: Model,
  first: Simulation,
  views: View[],
  make: (dt: number) => Simulation,
): SimulatorElement {
  const parts = assemble(options, first, views, make);
  const { root, driver } = parts;
  followFrames(parts, views);
  followState(parts);
  // Space plays and pauses from anywhere in the simulator, except on a control that takes Space itself.
  root.addEventListener('keydown', (e) => {
    if (e.key !== ' ' || e.ctrlKey || e.metaKey || e.altKey || isControl(e.target)) return;
    e.preventDefault();
    driver.toggle();
  });
  followLifetime(root, driver, options.invalidation);
  showFirst(parts, first, views);
  // A reader whose system asks for reduced motion starts each simulator themselves.
  const reducedMotion = prefersReducedMotion();
  if (reducedMotion) root.dataset.reducedMotion = '';
  if (options.autoplay !== false && !reducedMotion) driver.play();
  root.simulator = simulatorHandle(driver, model, make);
  return root;
}

/** The simulator's element with its bar (transport and readouts), notices, views and data panel, and the driver that runs them. */
function assemble(options: MountOptions, first: Simulation, views: View[], make: (dt: number) => Simulation): Parts {
  const notices = new Notices();
  const readouts = new Readouts();
  const viewBox = h('div', 'pb-views', {}, ...views.map((v) => v.element));
  // Which views take the whole width where they go two abreast: as the box reserved for them has it (reserve.ts).
  const spans = spanningViews(views.map((v) => v.element.dataset.widget === 'spectrum'));
  views.forEach((v, i) => v.element.classList.toggle('pb-span', spans[i]));
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
      // The chapter's cell that gives dt, if there is one, takes the new value (and the widget is rebuilt from it),
      // so that the chapter's checks and this widget use one dt; otherwise the widget changes its own.
      setDt: (dt) => {
        if (offerToCell(root, { name: 'dt', value: dt })) driver.replace(make(dt));
      },
    },
    driver.speed,
    first.dt,
  );
  root.append(h('div', 'pb-bar', {}, transport.element, readouts.element), notices.alert, notices.note, viewBox, panel.element);
  return { root, driver, transport, readouts, notices, panel };
}

/** Each frame updates the readouts, and twice a second the rate, the cap note and the data panel; the simulator is ready once every view is. */
function followFrames({ root, driver, transport, readouts, notices, panel }: Parts, views: View[]): void {
  let slow = 0;
  driver.on('frame', (stats) => {
    const sim = driver.simulation;
    readouts.update(sim);
    const now = performance.now();
    if (now - slow > 500) {
      slow = now;
      transport.showRate(driver.targetRate, driver.playing && isBehind(stats.pace) ? stats.pace : null);
      notices.showCap(sim);
      panel.update(sim);
    }
    if (!root.hasAttribute('data-ready') && views.every((v) => v.element.hasAttribute('data-ready'))) root.setAttribute('data-ready', '');
  });
}

/** Playing, pausing, an error, and a new simulation (a restart, a new dt) show at once in the bar, the notices and the data panel. */
function followState({ root, driver, transport, readouts, notices, panel }: Parts): void {
  driver.on('state', ({ playing, error }) => {
    readouts.update(driver.simulation, true);
    panel.update(driver.simulation, true);
    transport.setPlaying(playing, !!error);
    // Paused or stopped is not "behind real time": drop the note the last frames may have left.
    if (!playing) transport.showRate(driver.targetRate, null);
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
}

/** Redraws as the simulator resizes, and ends with the cell that made it (`invalidation`). */
function followLifetime(root: HTMLElement, driver: Driver, invalidation: Promise<unknown> | undefined): void {
  const resize = typeof ResizeObserver === 'undefined' ? null : new ResizeObserver(() => driver.requestDraw());
  resize?.observe(root);
  driver.on('dispose', () => resize?.disconnect());
  void invalidation?.then(() => driver.dispose());
}

/** The first simulation shown, paused, before the first frame. */
function showFirst({ driver, transport, readouts, panel }: Parts, first: Simulation, views: View[]): void {
  readouts.reset(first);
  panel.update(first, true);
  panel.listPlots();
  views.forEach((v) => v.reset(first));
  transport.setPlaying(false, false);
  driver.requestDraw();
}

/** What scripts get as element.simulator: the driver's controls, and parameters set by name. */
function simulatorHandle(driver: Driver, model: Model, make: (dt: number) => Simulation): SimulatorHandle {
  return {
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
    setParams: (values) => {
      for (const [name, value] of Object.entries(values)) {
        const i = model.paramNames.indexOf(name);
        if (i < 0) throw new Error(`simulator: the model has no parameter ${name}; it has ${model.paramNames.join(', ') || 'none'}`);
        if (!Number.isFinite(value)) throw new Error(`simulator: ${name} must be a finite number, not ${value}`);
        model.params[i] = value;
      }
      driver.restart();
    },
    dispose: () => driver.dispose(),
  };
}

/** True for targets that handle Space themselves: buttons, fields, links, editors. */
function isControl(target: EventTarget | null): boolean {
  if (!(target instanceof HTMLElement)) return false;
  return target.isContentEditable || /^(BUTTON|INPUT|SELECT|TEXTAREA|A|SUMMARY)$/.test(target.tagName);
}
