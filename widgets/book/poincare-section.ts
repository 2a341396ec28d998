/**
 * A surface of section of Hénon–Heiles at one energy: the crossings of many
 * orbits, computed in a worker (poincare-section-worker.ts) and drawn as they
 * arrive, with a progress bar and a Stop button. The reader chooses the
 * energy, and clicks a point of the section (or moves a cursor with the
 * arrow keys and presses Enter) to launch an orbit from it, its momentum
 * across the plane solved from the energy; the orbit is drawn in the accent
 * colour and its Lyapunov exponent reported. A text summary says what the
 * canvas shows.
 *
 * The root's data attributes, for the end-to-end tests: data-energy,
 * data-points (crossings drawn), data-launched (orbits the reader launched),
 * data-exponent (the last launched orbit's λ), data-ready once the section is done.
 */
import { allowed, type ChaoticArea, henonHeiles, type Plane, planeIndices, sectionBox } from '../core/index.ts';
import { makeMapping } from '../plots/axis-scale.ts';
import { pixelRatio, sizeCanvas } from '../plots/canvas.ts';
import { drawAxes, MARGIN } from '../plots/draw-axes.ts';
import { readTheme, seriesColor } from '../plots/view-theme.ts';
import type { SectionRequest } from './poincare-section-worker.ts';

export interface PoincareSectionOptions {
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

const FRACTIONS: Record<string, string> = { [String(1 / 12)]: '1/12', [String(1 / 8)]: '1/8', [String(1 / 6)]: '1/6' };
const energyName = (E: number) => FRACTIONS[String(E)] ?? E.toPrecision(3);

function newWorker(): Worker {
  return new Worker(new URL('./poincare-section-worker.ts', import.meta.url), { type: 'module' });
}

/** Launch points spread over the section: along p = 0 and along u = centre, inside the allowed region. */
function launchGrid(energy: number, plane: Plane, orbits: number): [number, number][] {
  const box = sectionBox(henonHeiles, energy, plane);
  const along = Math.ceil(orbits * 0.6);
  const across = orbits - along;
  const out: [number, number][] = [];
  for (let i = 0; i < along; i++) out.push([box.uMin + ((i + 0.5) / along) * (box.uMax - box.uMin), 0]);
  for (let j = 0; j < across; j++) out.push([0, -box.puMax + ((j + 0.5) / across) * 2 * box.puMax]);
  return out.filter(([u, pu]) => allowed(henonHeiles, energy, u, pu, plane));
}

export function poincareSection(options: PoincareSectionOptions = {}): HTMLElement {
  const { energies = [1 / 12, 1 / 8, 1 / 6], plane = 'y', orbits = 24, crossings = 250, dt = 0.02, height = 360 } = options;
  const names = planeIndices(plane).names;
  const label = { u: names[0] === 'x' ? 'x' : 'y', pu: names[1] === 'px' ? 'pₓ' : 'p_y' };
  let energy = options.energy ?? energies[0];

  const root = document.createElement('figure');
  root.className = 'pb-stability pb-poincare';
  root.dataset.widget = 'poincare-section';

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
  canvas.setAttribute('aria-label', `Surface of section ${plane} = 0 in ${label.u} and ${label.pu}: arrow keys move the launch point (Shift for larger steps), Enter or Space launches an orbit from it; or click`);
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
  root.append(chooser, canvas, reading, summary, status);

  let worker: Worker | null = null;
  let request = 0;
  let orbitsDone: { u: Float64Array; pu: Float64Array }[] = [];
  let launched: { u: Float64Array; pu: Float64Array; exponent: number }[] = [];
  let cursor: [number, number] = [0, 0];
  let box = sectionBox(henonHeiles, energy, plane);

  const count = () => orbitsDone.reduce((n, o) => n + o.u.length, 0) + launched.reduce((n, o) => n + o.u.length, 0);
  const describe = () => {
    root.dataset.points = String(count());
    root.dataset.launched = String(launched.length);
    const last = launched[launched.length - 1];
    summary.textContent =
      `At E = ${energyName(energy)}: ${orbitsDone.length} orbits, ${count()} crossings of ${plane} = 0 with p${plane} > 0, ` +
      `inside the allowed region (the outer curve). Closed curves are regular orbits on invariant tori; scattered dots fill the chaotic sea.` +
      (last ? ` Your last orbit: ${last.u.length} crossings, largest Lyapunov exponent ${last.exponent.toPrecision(2)} (${last.exponent > 0.02 ? 'chaotic' : 'regular'}).` : '');
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
    const rect = { left: MARGIN.left, top: MARGIN.top, width: width - MARGIN.left - MARGIN.right, height: side - MARGIN.top - MARGIN.bottom };
    const pad = 1.08;
    const mid = (box.uMin + box.uMax) / 2;
    const half = ((box.uMax - box.uMin) / 2) * pad;
    const mx = makeMapping('linear', [mid - half, mid + half], [rect.left, rect.left + rect.width]);
    const my = makeMapping('linear', [-box.puMax * pad, box.puMax * pad], [rect.top + rect.height, rect.top]);
    geometry = { mx, my };
    // The energy's boundary: V(u) + p²/2 = E on the plane.
    g.strokeStyle = theme.muted;
    g.lineWidth = 1;
    g.beginPath();
    const V = (u: number) => (plane === 'y' ? henonHeiles.potential(u, 0) : henonHeiles.potential(0, u));
    for (let sign = -1, first = true; sign <= 1; sign += 2) {
      for (let i = 0; i <= 200; i++) {
        const u = sign < 0 ? box.uMin + ((box.uMax - box.uMin) * i) / 200 : box.uMax - ((box.uMax - box.uMin) * i) / 200;
        const p = sign * Math.sqrt(Math.max(0, 2 * (energy - V(u))));
        (first ? g.moveTo : g.lineTo).call(g, mx.scale(u), my.scale(p));
        first = false;
      }
    }
    g.closePath();
    g.stroke();
    orbitsDone.forEach((o, k) => {
      g.fillStyle = seriesColor(theme, k);
      for (let i = 0; i < o.u.length; i++) g.fillRect(mx.scale(o.u[i]) - 0.75, my.scale(o.pu[i]) - 0.75, 1.5, 1.5);
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
        reading.textContent = `Launched from ${label.u} = ${cursor[0].toPrecision(3)}, ${label.pu} = ${cursor[1].toPrecision(3)}: ${m.u.length} crossings, λ ≈ ${(m.exponent ?? NaN).toPrecision(2)}${(m.exponent ?? 0) > 0.02 ? ', chaotic' : ', regular'}.`;
        options.onLaunch?.({ energy, u: cursor[0], pu: cursor[1], exponent: m.exponent ?? NaN, crossings: m.u.length });
      } else if (m.u && m.pu) {
        orbitsDone.push({ u: m.u, pu: m.pu });
        progress.value = m.progress ?? 0;
      }
      if (m.done) {
        status.textContent = `Section at E = ${energyName(energy)} complete. Click inside the curve, or use the arrow keys and Enter, to launch an orbit.`;
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
    box = sectionBox(henonHeiles, energy, plane);
    cursor = [(box.uMin + box.uMax) / 2, 0];
    orbitsDone = [];
    launched = [];
    delete root.dataset.ready;
    delete root.dataset.exponent;
    root.dataset.energy = String(E);
    status.className = '';
    progress.value = 0;
    status.replaceChildren(progress, ` computing orbits at E = ${energyName(E)}… `, stop);
    request++;
    const message: SectionRequest = { id: request, kind: 'section', energy, plane, launches: launchGrid(energy, plane, orbits), crossings, dt };
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
    if (!allowed(henonHeiles, energy, u, pu, plane)) {
      reading.textContent = `${label.u} = ${u.toPrecision(3)}, ${label.pu} = ${pu.toPrecision(3)} lies outside the region E = ${energyName(energy)} allows: choose a point inside the curve.`;
      draw();
      return;
    }
    reading.textContent = `Launching from ${label.u} = ${u.toPrecision(3)}, ${label.pu} = ${pu.toPrecision(3)}…`;
    const message: SectionRequest = { id: request, kind: 'orbit', energy, plane, launch: [u, pu], crossings: 400, dt, lyapunovTime: 2000 };
    worker?.postMessage(message);
    draw();
  };

  canvas.addEventListener('click', (event) => {
    if (!geometry) return;
    const r = canvas.getBoundingClientRect();
    launch(geometry.mx.scale.invert(event.clientX - r.left), geometry.my.scale.invert(event.clientY - r.top));
  });
  canvas.addEventListener('keydown', (event) => {
    const du = ((box.uMax - box.uMin) / 50) * (event.shiftKey ? 5 : 1);
    const dp = ((2 * box.puMax) / 50) * (event.shiftKey ? 5 : 1);
    const moves: Record<string, [number, number]> = { ArrowLeft: [-du, 0], ArrowRight: [du, 0], ArrowDown: [0, -dp], ArrowUp: [0, dp] };
    if (event.key in moves) {
      event.preventDefault();
      cursor = [cursor[0] + moves[event.key][0], cursor[1] + moves[event.key][1]];
      const inside = allowed(henonHeiles, energy, cursor[0], cursor[1], plane);
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
