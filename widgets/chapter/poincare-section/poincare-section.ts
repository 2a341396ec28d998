/**
 * A surface of section of Hénon–Heiles at one energy, or of the anisotropic
 * Kepler problem of the paper's chaotic two-body variant (section-systems.ts):
 * the crossings of many orbits, computed in a worker
 * (poincare-section-worker.ts) and drawn as they arrive, with a progress bar
 * and a Stop button. For Hénon–Heiles the reader chooses the energy; for
 * the Kepler problem the cell gives the anisotropy factor. The reader clicks a point of the section (or moves a cursor with the
 * arrow keys and presses Enter) to launch an orbit from it, its momentum
 * across the plane solved from the energy; the orbit is drawn in the accent
 * colour and its Lyapunov exponent reported. A text summary says what the
 * canvas shows.
 *
 * The root's data attributes, for the end-to-end tests: data-system,
 * data-energy, data-points (crossings drawn), data-launched (orbits the
 * reader launched), data-exponent (the last launched orbit's λ), data-ready
 * once the section is done; for the Kepler problem also data-factor, data-mu
 * and data-spread, the largest distance of an orbit's crossing from its
 * first (0 to rounding when every orbit closes, as at isotropy).
 */
import { type ChaoticArea, type Plane } from '../../../core/index.ts';
import type { KeplerRun } from '../analysis/kepler-run.ts';
import { SectionFigure, type SectionSetting } from './poincare-section-figure.ts';
import type { SectionRequest } from './poincare-section-worker.ts';
import { keplerSetting, type SectionSystem } from './section-systems.ts';

export interface PoincareSectionOptions {
  /** 'henon-heiles' (the default) or 'anisotropic-kepler', the paper's two-body variant reduced to its relative motion */
  system?: 'henon-heiles' | 'anisotropic-kepler';
  /** for 'anisotropic-kepler': the factor c of hypot(c·x1 − x2, y1 − y2), 1.5 in the paper */
  factor?: number;
  /** the energies offered, 1/12, 1/8 and 1/6 (Hénon & Heiles's) by default */
  energies?: number[];
  energy?: number;
  /** y: the plane y = 0 drawn in (x, p_x); x: Hénon & Heiles's plane x = 0, in (y, p_y) */
  plane?: Plane;
  /** orbits launched along the section's two axes */
  orbits?: number;
  crossings?: number;
  dt?: number;
  height?: number;
  /** called when the reader launches an orbit */
  onLaunch?: (orbit: { energy: number; u: number; pu: number; exponent: number; crossings: number }) => void;
}

function newWorker(): Worker {
  return new Worker(new URL('./poincare-section-worker.ts', import.meta.url), { type: 'module' });
}

/** The widget described above: its figure started at the first energy, redrawn as its column resizes, its worker ended when the cell drops it. */
export function poincareSection(options: PoincareSectionOptions = {}): HTMLElement {
  const setting = sectionSetting(options);
  const figure = new SectionFigure(setting, newWorker);
  figure.start(setting.energy);
  requestAnimationFrame(() => figure.draw());
  new ResizeObserver(() => figure.draw()).observe(figure.root);
  // Part of a cell's output: when the cell re-runs and this element is dropped, so is its worker.
  new MutationObserver((_, observer) => {
    if (!figure.root.isConnected) {
      figure.end();
      observer.disconnect();
    }
  }).observe(document.body, { childList: true, subtree: true });
  return figure.root;
}

/** The cell's options with their defaults; the Kepler problem's setting is checked first, so that a factor that is no number, or leaves the orbit unbound, fails the cell with its reason. */
function sectionSetting(options: PoincareSectionOptions): SectionSetting {
  const { energies = [1 / 12, 1 / 8, 1 / 6], plane = 'y', orbits = 24, crossings = 250, dt = 0.02, height = 360, onLaunch } = options;
  const kepler = options.system === 'anisotropic-kepler' ? keplerSetting(options.factor ?? 1.5) : null;
  if (options.system !== undefined && options.system !== 'henon-heiles' && !kepler) {
    throw new TypeError(`poincareSection: system must be 'henon-heiles' or 'anisotropic-kepler', not ${String(options.system)}`);
  }
  const system: SectionSystem = kepler ? { kind: 'anisotropic-kepler', factor: kepler.factor } : { kind: 'henon-heiles', plane };
  const energy = kepler ? kepler.energy : (options.energy ?? energies[0]);
  return { system, kepler, energies, energy, plane, orbits, crossings, dt, height, onLaunch };
}

/** The chaotic share of the section at E (poincare-area.ts), computed in its own worker. */
export function chaoticShare(options: { energy: number; plane?: Plane; grid?: number; time?: number }): Promise<Omit<ChaoticArea, 'points'> & { energy: number }> {
  const { energy, plane = 'x', grid = 14, time = 600 } = options;
  if (!(energy > 0)) return Promise.reject(new Error(`chaoticShare: the energy must be positive, not ${String(energy)}`));
  return new Promise((resolve, reject) => {
    const worker = newWorker();
    worker.onmessage = (event: MessageEvent<{ area?: Omit<ChaoticArea, 'points'>; error?: string }>) => {
      if (event.data.error) {
        worker.terminate();
        reject(new Error(event.data.error));
      } else if (event.data.area) {
        worker.terminate();
        resolve({ ...event.data.area, energy });
      }
    };
    worker.onerror = (event) => {
      worker.terminate();
      reject(new Error(event.message || 'the worker failed'));
    };
    const message: SectionRequest = { id: 0, kind: 'area', energy, plane, grid, time };
    worker.postMessage(message);
  });
}

/**
 * The anisotropic Kepler problem's orbit from the paper's initial state with
 * anisotropy factor `factor`, integrated over `time` in the section's worker
 * at two tolerances (kepler-run.ts): what its theory checks compare.
 */
export function anisotropicKeplerRun(options: { factor: number; time?: number }): Promise<KeplerRun> {
  const { factor, time = 600 } = options;
  try {
    keplerSetting(factor);
  } catch (error) {
    return Promise.reject(error);
  }
  return new Promise((resolve, reject) => {
    const worker = newWorker();
    worker.onmessage = (event: MessageEvent<{ run?: KeplerRun; error?: string }>) => {
      worker.terminate();
      if (event.data.run) resolve(event.data.run);
      else reject(new Error(event.data.error ?? 'the worker sent no result'));
    };
    worker.onerror = (event) => {
      worker.terminate();
      reject(new Error(event.message || 'the worker failed'));
    };
    const message: SectionRequest = { id: 0, kind: 'kepler-run', factor, time };
    worker.postMessage(message);
  });
}
