/**
 * A surface of section as the reader sees and works it: the energy chooser,
 * the section on a point panel (plots/point-panel.ts), the readings, the
 * summary, the progress bar and Stop; and the conversation with the worker
 * that computes the orbits. `start(E)` computes the section at E; a click
 * or Enter launches an orbit from the chosen point.
 */
import type { Plane } from '../../../core/index.ts';
import { PointPanel } from '../../plots/point-panel.ts';
import { type Crossings, drawCrossings, drawLaunched, drawRim, type LaunchedOrbit, sectionDomains } from './poincare-section-draw.ts';
import { crossingCount, cursorReading, launchReading, outsideReading, sectionSummary, spread } from './poincare-section-text.ts';
import type { SectionRequest } from './poincare-section-worker.ts';
import { energyName, henonHeilesView, type KeplerSetting, keplerView, launchGrid, type SectionSystem, type SectionView } from './section-systems.ts';

/** The section's settings, resolved from the cell's options (poincare-section.ts). */
export interface SectionSetting {
  system: SectionSystem;
  /** the Kepler problem's setting, or null for Hénon–Heiles */
  kepler: KeplerSetting | null;
  energies: number[];
  /** the energy shown first */
  energy: number;
  plane: Plane;
  orbits: number;
  crossings: number;
  dt: number;
  height: number;
  onLaunch?: (orbit: { energy: number; u: number; pu: number; exponent: number; crossings: number }) => void;
}

/** What the worker sends: an orbit of the section (orbit ≥ 0) or the reader's (orbit −1), progress, the end, or an error. */
type SectionMessage = { id: number; orbit?: number; u?: Float64Array; pu?: Float64Array; exponent?: number; progress?: number; done?: boolean; error?: string };

/** Crossings of one launched orbit, and the time its Lyapunov exponent is measured over (shorter for the Kepler problem, whose orbits are slower to compute). */
const LAUNCH_CROSSINGS = 400;
const LYAPUNOV_TIME = { 'henon-heiles': 2000, 'anisotropic-kepler': 500 };

/** Launch steps of the keys: a fiftieth of the region's box, five times that with Shift. */
const KEY_STEPS = 50;
const LARGER_STEP = 5;

export class SectionFigure {
  readonly root: HTMLElement;
  readonly #setting: SectionSetting;
  readonly #newWorker: () => Worker;
  readonly #panel: PointPanel;
  /** where the launch point is, and what came of the last launch: said as it changes */
  readonly #reading = paragraph('pb-stability-reading');
  readonly #summary = paragraph('pb-poincare-summary');
  readonly #status = document.createElement('figcaption');
  readonly #progress = document.createElement('progress');
  readonly #stopButton = document.createElement('button');
  #worker: Worker | null = null;
  /** the request the figure listens to: messages for earlier ones are from a section since superseded */
  #request = 0;
  #energy: number;
  #view: SectionView;
  #orbitsDone: Crossings[] = [];
  #launched: LaunchedOrbit[] = [];
  #cursor: [number, number] = [0, 0];

  constructor(setting: SectionSetting, newWorker: () => Worker) {
    const { kepler, system, energy } = setting;
    this.#setting = setting;
    this.#newWorker = newWorker;
    this.#energy = energy;
    this.#view = this.#viewAt(energy);
    this.root = document.createElement('figure');
    this.root.className = 'pb-stability pb-poincare';
    this.root.dataset.widget = 'poincare-section';
    this.root.dataset.system = system.kind;
    if (kepler) Object.assign(this.root.dataset, { factor: String(kepler.factor), mu: String(kepler.mu) });
    const label = this.#view.labels;
    const described = `Surface of section ${this.#view.plane} in ${label.u} and ${label.pu}: arrow keys move the launch point (Shift for larger steps), Enter or Space launches an orbit from it; or click`;
    // A section's coordinate and momentum are in one unit (the Kepler problem's scaled to the unit disk): drawn at one scale.
    this.#panel = new PointPanel(this.root, 'surface of section', described, { sameUnits: true });
    this.#panel.followWidth(() => this.draw());
    this.#reading.setAttribute('aria-live', 'polite');
    this.#progress.max = 1;
    this.#stopButton.type = 'button';
    this.#stopButton.textContent = 'Stop';
    // The Kepler problem has no energy to choose: its orbits at any E < 0 are those at one E, rescaled.
    const chooser = kepler ? [] : [energyChooser(setting.energies, energy, (E) => this.start(E))];
    this.root.append(...chooser, this.#panel.canvas, this.#reading, this.#summary, this.#status);
    this.#listen();
  }

  /** (Re)starts the section at energy E, cancelling any section in progress by ending its worker. */
  start(E: number): void {
    this.#hire();
    this.#energy = E;
    this.#view = this.#viewAt(E);
    this.#cursor = this.#setting.kepler ? [0.5, 0] : [(this.#view.box.uMin + this.#view.box.uMax) / 2, 0];
    this.#orbitsDone = [];
    this.#launched = [];
    delete this.root.dataset.ready;
    delete this.root.dataset.exponent;
    this.root.dataset.energy = String(E);
    this.#status.className = '';
    this.#progress.value = 0;
    this.#status.replaceChildren(this.#progress, ` computing orbits at ${this.#view.setting}… `, this.#stopButton);
    this.#request++;
    const { system, plane, orbits, crossings, dt, kepler } = this.#setting;
    // Launches off the centre line: for the Kepler problem σ = 0 is the collision.
    const launches = launchGrid(this.#view, orbits, kepler ? 0.35 : 0);
    this.#post({ id: this.#request, kind: 'section', system, energy: E, plane, launches, crossings, dt });
    this.#describe();
    this.draw();
  }

  /** Ends the worker for good: the figure has left the page. */
  end(): void {
    this.#worker?.terminate();
  }

  /** Draws the section as it stands: the rim, the orbits so far, the reader's, the launch point and the axes. */
  draw(): void {
    const domains = sectionDomains(this.#view);
    const f = this.#panel.frame((width) => Math.min(this.#setting.height, width), domains.u, domains.pu);
    if (!f) return;
    drawRim(f, this.#view);
    // A closed orbit's crossings all fall on one point: drawn larger, so that it shows.
    drawCrossings(f, this.#orbitsDone, this.#setting.kepler?.mu === 1 ? 4 : 1.5);
    drawLaunched(f, this.#launched);
    this.#panel.finish(f, this.#cursor, { xLabel: this.#view.labels.u, yLabel: this.#view.labels.pu });
  }

  /** A fresh worker listened to, ending the one before and whatever it was computing. */
  #hire(): void {
    this.#worker?.terminate();
    const worker = this.#newWorker();
    worker.onmessage = (event: MessageEvent<SectionMessage>) => this.#receive(event.data);
    worker.onerror = (event) => this.#fail(event.message || 'the worker failed');
    this.#worker = worker;
  }

  /** A request to the worker of the moment (none after it has ended). */
  #post(message: SectionRequest): void {
    this.#worker?.postMessage(message);
  }

  /** Stop: the orbits so far stay, and the reader may launch more. */
  #stop(): void {
    this.#hire();
    this.#request++;
    this.#status.textContent = `Stopped after ${this.#orbitsDone.length} orbits. Click inside the curve to launch one.`;
    this.root.dataset.ready = '';
  }

  /** A message of the worker: an orbit of the section or the reader's, progress, the end, or an error; the figure is redrawn. */
  #receive(m: SectionMessage): void {
    if (m.id !== this.#request) return; // from a section since superseded
    if (m.error) {
      this.#reading.textContent = `Could not compute the orbit: ${m.error}`;
      return;
    }
    if (m.orbit === -1 && m.u && m.pu) this.#launchedOrbit({ u: m.u, pu: m.pu }, m.exponent);
    else if (m.u && m.pu) {
      this.#orbitsDone.push({ u: m.u, pu: m.pu });
      this.#progress.value = m.progress ?? 0;
    }
    if (m.done) {
      this.#status.textContent = `Section at ${this.#view.setting} complete. Click inside the curve, or use the arrow keys and Enter, to launch an orbit.`;
      this.root.dataset.ready = '';
    }
    this.#describe();
    this.draw();
  }

  /** The reader's orbit is back from the worker: kept, read out, and told to the chapter. */
  #launchedOrbit(orbit: Crossings, exponent: number | undefined): void {
    this.#launched.push({ ...orbit, exponent: exponent ?? NaN });
    this.root.dataset.exponent = String(exponent);
    this.#reading.textContent = launchReading(this.#view, this.#cursor, orbit.u.length, exponent);
    this.#setting.onLaunch?.({ energy: this.#energy, u: this.#cursor[0], pu: this.#cursor[1], exponent: exponent ?? NaN, crossings: orbit.u.length });
  }

  /** Asks the worker for the orbit from (u, pu), its momentum across the plane solved from the energy; a point the energy cannot reach is refused with the reason. */
  #launch(u: number, pu: number): void {
    this.#cursor = [u, pu];
    const { system, plane, dt, kepler } = this.#setting;
    if (!this.#view.allowed(u, pu)) {
      this.#reading.textContent = outsideReading(this.#view, kepler, this.#energy, u, pu);
      this.draw();
      return;
    }
    const label = this.#view.labels;
    this.#reading.textContent = `Launching from ${label.u} = ${u.toPrecision(3)}, ${label.pu} = ${pu.toPrecision(3)}…`;
    this.#post({ id: this.#request, kind: 'orbit', system, energy: this.#energy, plane, launch: [u, pu], crossings: LAUNCH_CROSSINGS, dt, lyapunovTime: LYAPUNOV_TIME[system.kind] });
    this.draw();
  }

  /** What the canvas and the root's data attributes say of the section now. */
  #describe(): void {
    const { kepler } = this.#setting;
    this.root.dataset.points = String(crossingCount(this.#orbitsDone, this.#launched));
    this.root.dataset.launched = String(this.#launched.length);
    if (kepler) this.root.dataset.spread = String(spread(this.#orbitsDone));
    this.#summary.textContent = sectionSummary(this.#view, kepler, this.#orbitsDone, this.#launched);
  }

  /** The worker itself failed: the section stops, with the reason. */
  #fail(message: string): void {
    this.#status.textContent = `Could not compute the section: ${message}`;
    this.#status.className = 'pb-error';
  }

  /** Stop, a click, and the keys: arrows move the launch point, inside the region or out (the reading says which), Enter launches. */
  #listen(): void {
    this.#stopButton.addEventListener('click', () => this.#stop());
    this.#panel.onClick((u, pu) => this.#launch(u, pu));
    const step = () => [(this.#view.box.uMax - this.#view.box.uMin) / KEY_STEPS, (2 * this.#view.box.puMax) / KEY_STEPS] as const;
    const move = (du: number, dv: number) => {
      this.#cursor = [this.#cursor[0] + du, this.#cursor[1] + dv];
      this.#reading.textContent = cursorReading(this.#view, this.#cursor);
      this.draw();
    };
    this.#panel.onKeys(step, LARGER_STEP, move, () => this.#launch(this.#cursor[0], this.#cursor[1]));
  }

  /** The section's plane at energy E (the Kepler problem's is the same at every E). */
  #viewAt(E: number): SectionView {
    return this.#setting.kepler ? keplerView(this.#setting.kepler) : henonHeilesView(E, this.#setting.plane);
  }
}

function paragraph(className: string): HTMLParagraphElement {
  const p = document.createElement('p');
  p.className = className;
  return p;
}

/** Radio buttons for the energies offered, `energy` checked; `start(E)` when the reader picks another. */
function energyChooser(energies: number[], energy: number, start: (E: number) => void): HTMLFieldSetElement {
  const chooser = document.createElement('fieldset');
  chooser.style.border = '0';
  chooser.style.padding = '0';
  const legend = document.createElement('legend');
  legend.textContent = 'Energy E';
  chooser.append(legend);
  const group = `pb-energy-${Math.random().toString(36).slice(2)}`;
  for (const E of energies) {
    const item = document.createElement('label');
    item.style.marginRight = '1em';
    const radio = document.createElement('input');
    radio.type = 'radio';
    radio.name = group;
    radio.value = String(E);
    radio.checked = E === energy;
    radio.addEventListener('change', () => radio.checked && start(E));
    item.append(radio, ` ${energyName(E)}`);
    chooser.append(item);
  }
  return chooser;
}
