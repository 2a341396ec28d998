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
import { type ChaoticArea, type Plane } from '../core/index.ts';
import { makeMapping } from '../plots/scale.ts';
import { pixelRatio, sizeCanvas } from '../plots/canvas.ts';
import { drawAxes, MARGIN } from '../plots/axes.ts';
import { readTheme, seriesColor } from '../plots/theme.ts';
import type { KeplerRun } from './kepler-run.ts';
import type { SectionRequest } from './poincare-section-worker.ts';
import { energyName, henonHeilesView, keplerSetting, keplerView, launchGrid, type SectionSystem, type SectionView } from './section-systems.ts';

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

/** A λ(T) above this is called chaotic: several times what a regular orbit still shows at T (ln T / T ≈ 0.004 at T = 2000; at isotropy |λ(T)| ≤ ln κ / T ≈ 0.004 at T = 500). */
const CHAOTIC_EXPONENT = 0.02;

export function poincareSection(options: PoincareSectionOptions = {}): HTMLElement {
  const { energies = [1 / 12, 1 / 8, 1 / 6], plane = 'y', orbits = 24, crossings = 250, dt = 0.02, height = 360 } = options;
  // The Kepler problem's setting is checked first: a factor that is no number, or leaves the orbit unbound, fails the cell with its reason.
  const kepler = options.system === 'anisotropic-kepler' ? keplerSetting(options.factor ?? 1.5) : null;
  if (options.system !== undefined && options.system !== 'henon-heiles' && !kepler) {
    throw new TypeError(`poincareSection: system must be 'henon-heiles' or 'anisotropic-kepler', not ${String(options.system)}`);
  }
  const system: SectionSystem = kepler ? { kind: 'anisotropic-kepler', factor: kepler.factor } : { kind: 'henon-heiles', plane };
  let energy = kepler ? kepler.energy : (options.energy ?? energies[0]);
  const viewAt = (E: number): SectionView => (kepler ? keplerView(kepler) : henonHeilesView(E, plane));
  let view = viewAt(energy);
  const label = view.labels;
  // Launches off the centre line: for the Kepler problem σ = 0 is the collision.
  const across = kepler ? 0.35 : 0;

  const root = document.createElement('figure');
  root.className = 'pb-stability pb-poincare';
  root.dataset.widget = 'poincare-section';
  root.dataset.system = system.kind;
  if (kepler) Object.assign(root.dataset, { factor: String(kepler.factor), mu: String(kepler.mu) });

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

  const canvas = document.createElement('canvas');
  canvas.style.cursor = 'crosshair';
  canvas.tabIndex = 0;
  canvas.setAttribute('role', 'application');
  canvas.setAttribute('aria-roledescription', 'surface of section');
  canvas.setAttribute('aria-label', `Surface of section ${view.plane} in ${label.u} and ${label.pu}: arrow keys move the launch point (Shift for larger steps), Enter or Space launches an orbit from it; or click`);
  const reading = document.createElement('p');
  reading.className = 'pb-stability-reading';
  reading.setAttribute('aria-live', 'polite');
  const summary = document.createElement('p');
  summary.className = 'pb-poincare-summary';
  const status = document.createElement('figcaption');
  const progress = document.createElement('progress');
  progress.max = 1;
  const stop = document.createElement('button');
  stop.type = 'button';
  stop.textContent = 'Stop';
  // The Kepler problem has no energy to choose: its orbits at any E < 0 are those at one E, rescaled.
  root.append(...(kepler ? [] : [chooser]), canvas, reading, summary, status);

  let worker: Worker | null = null;
  let request = 0;
  let orbitsDone: { u: Float64Array; pu: Float64Array }[] = [];
  let launched: { u: Float64Array; pu: Float64Array; exponent: number }[] = [];
  let cursor: [number, number] = [0, 0];

  const count = () => orbitsDone.reduce((n, o) => n + o.u.length, 0) + launched.reduce((n, o) => n + o.u.length, 0);
  /** The largest distance of an orbit's crossing from its first: 0 when every orbit closes. */
  const spread = () => {
    let most = 0;
    for (const o of orbitsDone) for (let i = 1; i < o.u.length; i++) most = Math.max(most, Math.hypot(o.u[i] - o.u[0], o.pu[i] - o.pu[0]));
    return most;
  };
  const describe = () => {
    root.dataset.points = String(count());
    root.dataset.launched = String(launched.length);
    const last = launched[launched.length - 1];
    const what = kepler
      ? `The rim is p_v = 0 and the vertical line σ = 0 the collision. ` +
        (kepler.mu === 1
          ? `At isotropy every orbit is a closed Kepler ellipse: each orbit's crossings fall on one point.`
          : `Curves are orbits confined by an integral; scattered dots are orbits with none.`)
      : `Closed curves are regular orbits on invariant tori; scattered dots fill the chaotic sea.`;
    if (kepler) root.dataset.spread = String(spread());
    summary.textContent =
      `At ${view.setting}: ${orbitsDone.length} orbits, ${count()} crossings of ${view.plane}, ` +
      `inside the allowed region (the outer curve). ${what}` +
      (last ? ` Your last orbit: ${last.u.length} crossings, largest Lyapunov exponent ${last.exponent.toPrecision(2)} (${last.exponent > CHAOTIC_EXPONENT ? 'chaotic' : 'regular'}).` : '');
  };

  let geometry: { mx: ReturnType<typeof makeMapping>; my: ReturnType<typeof makeMapping> } | null = null;
  const draw = () => {
    const width = Math.max(280, root.clientWidth || 640);
    const side = Math.min(height, width);
    const dpr = pixelRatio();
    sizeCanvas(canvas, width, side, dpr);
    const g = canvas.getContext('2d')!;
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    const theme = readTheme(root);
    g.fillStyle = theme.bg;
    g.fillRect(0, 0, width, side);
    const box = view.box;
    const rect = { left: MARGIN.left, top: MARGIN.top, width: width - MARGIN.left - MARGIN.right, height: side - MARGIN.top - MARGIN.bottom };
    const pad = 1.08;
    const mid = (box.uMin + box.uMax) / 2;
    const half = ((box.uMax - box.uMin) / 2) * pad;
    const mx = makeMapping('linear', [mid - half, mid + half], [rect.left, rect.left + rect.width]);
    const my = makeMapping('linear', [-box.puMax * pad, box.puMax * pad], [rect.top + rect.height, rect.top]);
    geometry = { mx, my };
    // The energy's boundary on the plane: V(u) + p²/2 = E for Hénon–Heiles, the unit circle for the Kepler problem.
    g.strokeStyle = theme.muted;
    g.lineWidth = 1;
    g.beginPath();
    for (let sign = -1, first = true; sign <= 1; sign += 2) {
      for (let i = 0; i <= 200; i++) {
        const u = sign < 0 ? box.uMin + ((box.uMax - box.uMin) * i) / 200 : box.uMax - ((box.uMax - box.uMin) * i) / 200;
        const p = sign * view.rim(u);
        (first ? g.moveTo : g.lineTo).call(g, mx.scale(u), my.scale(p));
        first = false;
      }
    }
    g.closePath();
    g.stroke();
    // A closed orbit's crossings all fall on one point: drawn larger, so that it shows.
    const dot = kepler?.mu === 1 ? 4 : 1.5;
    orbitsDone.forEach((o, k) => {
      g.fillStyle = seriesColor(theme, k);
      for (let i = 0; i < o.u.length; i++) g.fillRect(mx.scale(o.u[i]) - dot / 2, my.scale(o.pu[i]) - dot / 2, dot, dot);
    });
    g.fillStyle = theme.accent;
    for (const o of launched) for (let i = 0; i < o.u.length; i++) g.fillRect(mx.scale(o.u[i]) - 1.25, my.scale(o.pu[i]) - 1.25, 2.5, 2.5);
    g.strokeStyle = theme.accent;
    g.lineWidth = 2;
    g.beginPath();
    g.arc(mx.scale(cursor[0]), my.scale(cursor[1]), 6, 0, 2 * Math.PI);
    g.stroke();
    drawAxes(g, rect, mx, my, theme, { xLabel: label.u, yLabel: label.pu }, dpr);
  };

  const fail = (message: string) => {
    status.textContent = `Could not compute the section: ${message}`;
    status.className = 'pb-error';
  };

  const listen = (w: Worker) => {
    w.onmessage = (event: MessageEvent<{ id: number; orbit?: number; u?: Float64Array; pu?: Float64Array; exponent?: number; progress?: number; done?: boolean; error?: string }>) => {
      const m = event.data;
      if (m.id !== request) return; // from a section since superseded
      if (m.error) {
        reading.textContent = `Could not compute the orbit: ${m.error}`;
        return;
      }
      if (m.orbit === -1 && m.u && m.pu) {
        launched.push({ u: m.u, pu: m.pu, exponent: m.exponent ?? NaN });
        root.dataset.exponent = String(m.exponent);
        reading.textContent = `Launched from ${label.u} = ${cursor[0].toPrecision(3)}, ${label.pu} = ${cursor[1].toPrecision(3)}: ${m.u.length} crossings, λ ≈ ${(m.exponent ?? NaN).toPrecision(2)}${(m.exponent ?? 0) > CHAOTIC_EXPONENT ? ', chaotic' : ', regular'}.`;
        options.onLaunch?.({ energy, u: cursor[0], pu: cursor[1], exponent: m.exponent ?? NaN, crossings: m.u.length });
      } else if (m.u && m.pu) {
        orbitsDone.push({ u: m.u, pu: m.pu });
        progress.value = m.progress ?? 0;
      }
      if (m.done) {
        status.textContent = `Section at ${view.setting} complete. Click inside the curve, or use the arrow keys and Enter, to launch an orbit.`;
        root.dataset.ready = '';
      }
      describe();
      draw();
    };
    w.onerror = (event) => fail(event.message || 'the worker failed');
  };

  /** (Re)starts the section at energy E, cancelling any section in progress by ending its worker. */
  const start = (E: number) => {
    worker?.terminate();
    worker = newWorker();
    listen(worker);
    energy = E;
    view = viewAt(E);
    cursor = kepler ? [0.5, 0] : [(view.box.uMin + view.box.uMax) / 2, 0];
    orbitsDone = [];
    launched = [];
    delete root.dataset.ready;
    delete root.dataset.exponent;
    root.dataset.energy = String(E);
    status.className = '';
    progress.value = 0;
    status.replaceChildren(progress, ` computing orbits at ${view.setting}… `, stop);
    request++;
    const message: SectionRequest = { id: request, kind: 'section', system, energy, plane, launches: launchGrid(view, orbits, across), crossings, dt };
    worker.postMessage(message);
    describe();
    draw();
  };

  stop.addEventListener('click', () => {
    worker?.terminate();
    worker = newWorker();
    listen(worker);
    request++;
    status.textContent = `Stopped after ${orbitsDone.length} orbits. Click inside the curve to launch one.`;
    root.dataset.ready = '';
  });

  const launch = (u: number, pu: number) => {
    cursor = [u, pu];
    if (!view.allowed(u, pu)) {
      reading.textContent = `${label.u} = ${u.toPrecision(3)}, ${label.pu} = ${pu.toPrecision(3)} lies outside the region ${kepler ? 'the energy' : `E = ${energyName(energy)}`} allows${kepler && u === 0 ? ' (σ = 0 is a collision)' : ''}: choose a point inside the curve.`;
      draw();
      return;
    }
    reading.textContent = `Launching from ${label.u} = ${u.toPrecision(3)}, ${label.pu} = ${pu.toPrecision(3)}…`;
    const message: SectionRequest = { id: request, kind: 'orbit', system, energy, plane, launch: [u, pu], crossings: 400, dt, lyapunovTime: kepler ? 500 : 2000 };
    worker?.postMessage(message);
    draw();
  };

  canvas.addEventListener('click', (event) => {
    if (!geometry) return;
    const r = canvas.getBoundingClientRect();
    launch(geometry.mx.scale.invert(event.clientX - r.left), geometry.my.scale.invert(event.clientY - r.top));
  });
  canvas.addEventListener('keydown', (event) => {
    const box = view.box;
    const du = ((box.uMax - box.uMin) / 50) * (event.shiftKey ? 5 : 1);
    const dp = ((2 * box.puMax) / 50) * (event.shiftKey ? 5 : 1);
    const moves: Record<string, [number, number]> = { ArrowLeft: [-du, 0], ArrowRight: [du, 0], ArrowDown: [0, -dp], ArrowUp: [0, dp] };
    if (event.key in moves) {
      event.preventDefault();
      cursor = [cursor[0] + moves[event.key][0], cursor[1] + moves[event.key][1]];
      const inside = view.allowed(cursor[0], cursor[1]);
      reading.textContent = `${label.u} = ${cursor[0].toPrecision(3)}, ${label.pu} = ${cursor[1].toPrecision(3)}${inside ? '' : ' (outside the allowed region)'}`;
      draw();
    } else if (event.key === 'Enter' || event.key === ' ') {
      event.preventDefault();
      launch(cursor[0], cursor[1]);
    }
  });

  start(energy);
  requestAnimationFrame(draw);
  new ResizeObserver(() => draw()).observe(root);
  // Part of a cell's output: when the cell re-runs and this element is dropped, so is its worker.
  new MutationObserver((_, observer) => {
    if (!root.isConnected) {
      worker?.terminate();
      observer.disconnect();
    }
  }).observe(document.body, { childList: true, subtree: true });
  return root;
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
