import { type BuildOptions, compiledModelFor } from '../core/index.ts';
import { makeMapping } from '../plots/scale.ts';
import { pixelRatio, sizeCanvas } from '../plots/canvas.ts';
import { drawAxes, MARGIN } from '../plots/axes.ts';
import { readTheme } from '../plots/theme.ts';
import type { StabilityRequest } from './stability-worker.ts';

export interface StabilityChartOptions {
  /** H of a linear, periodically driven 1-DOF system, as a math expression */
  hamiltonian: string;
  params: Record<string, number>;
  /** horizontal axis: a parameter and its range, e.g. {param: 'gamma', from: 15, to: 25} */
  x: { param: string; from: number; to: number; label?: string; count?: number };
  y: { param: string; from: number; to: number; label?: string; count?: number };
  /** the parameter setting the drive frequency (period 2π over it) */
  frequencyParam: string;
  /** curves drawn over the chart: each maps a y value to an x value (e.g. the first-order boundary) */
  boundaries?: ((y: number) => number)[];
  /** called with {[x.param]: …, [y.param]: …} when the reader clicks the chart */
  onSelect?: (values: Record<string, number>) => void;
  stepsPerPeriod?: number;
  height?: number;
}

/** Warm ramp for growth rates, yellow (slow) to red (fast); readable on light and dark backgrounds. */
const heat = (v: number) => `hsl(${48 - 46 * v}, 88%, ${64 - 20 * v}%)`;

const axis = (a: { from: number; to: number; count?: number }, n: number) =>
  Array.from({ length: a.count ?? n }, (_, i) => a.from + ((a.to - a.from) * i) / ((a.count ?? n) - 1));

/**
 * The stability chart of parametric resonance: Floquet growth rates over two
 * parameters, computed in a worker with a progress bar, the theoretical
 * boundary drawn over it, and a click that hands the clicked parameters to
 * the chapter (which sets them in its simulator). The model is compiled here
 * (or taken from `build.store`) and sent to the worker as data, so the
 * worker never loads mathjs.
 */
export function stabilityChart(options: StabilityChartOptions, build: BuildOptions = {}): HTMLElement {
  const { x, y, boundaries = [], height = 300 } = options;
  const root = document.createElement('figure');
  root.className = 'pb-stability';
  root.dataset.widget = 'stability-chart';
  const canvas = document.createElement('canvas');
  canvas.style.cursor = 'crosshair';
  // Operable by keyboard as by pointer: arrows move the chosen point over the grid, Enter or Space applies it.
  canvas.tabIndex = 0;
  canvas.setAttribute('role', 'application');
  canvas.setAttribute('aria-roledescription', 'stability chart');
  canvas.setAttribute('aria-label', `Stability chart over ${x.param} and ${y.param}: arrow keys move the point (Shift for larger steps), Enter or Space chooses it; or click`);
  const reading = document.createElement('p');
  reading.className = 'pb-stability-reading';
  reading.setAttribute('aria-live', 'polite');
  const status = document.createElement('figcaption');
  const progress = document.createElement('progress');
  progress.max = 1;
  progress.value = 0;
  status.append(progress, ' computing Floquet multipliers…');
  root.append(canvas, reading, status);

  const xs = axis(x, 120);
  const ys = axis(y, 60);
  let rates: Float64Array | null = null;
  let chosen: [number, number] | null = [options.params[x.param], options.params[y.param]];

  const draw = () => {
    const width = Math.max(280, root.clientWidth || 640);
    const dpr = pixelRatio();
    sizeCanvas(canvas, width, height, dpr);
    const g = canvas.getContext('2d')!;
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    const theme = readTheme(root);
    g.fillStyle = theme.bg;
    g.fillRect(0, 0, width, height);
    const rect = { left: MARGIN.left, top: MARGIN.top, width: width - MARGIN.left - MARGIN.right, height: height - MARGIN.top - MARGIN.bottom };
    const mx = makeMapping('linear', [x.from, x.to], [rect.left, rect.left + rect.width]);
    const my = makeMapping('linear', [y.from, y.to], [rect.top + rect.height, rect.top]);
    if (rates) {
      let top = 0;
      for (const r of rates) top = Math.max(top, r);
      const cw = rect.width / xs.length;
      const ch = rect.height / ys.length;
      for (let j = 0; j < ys.length; j++) {
        for (let i = 0; i < xs.length; i++) {
          const r = rates[j * xs.length + i];
          g.fillStyle = r > 0 ? heat(Math.sqrt(r / (top || 1))) : theme.bg;
          g.fillRect(rect.left + i * cw, rect.top + rect.height - (j + 1) * ch, cw + 0.5, ch + 0.5);
        }
      }
    }
    g.strokeStyle = theme.fg;
    g.lineWidth = 1.5;
    g.setLineDash([5, 4]);
    for (const boundary of boundaries) {
      g.beginPath();
      ys.forEach((v, j) => (j ? g.lineTo : g.moveTo).call(g, mx.scale(boundary(v)), my.scale(v)));
      g.stroke();
    }
    g.setLineDash([]);
    if (chosen) {
      g.strokeStyle = theme.accent;
      g.lineWidth = 2;
      g.beginPath();
      g.arc(mx.scale(chosen[0]), my.scale(chosen[1]), 6, 0, 2 * Math.PI);
      g.stroke();
    }
    drawAxes(g, rect, mx, my, theme, { xLabel: x.label ?? x.param, yLabel: y.label ?? y.param }, dpr);
    canvas.onclick = (event) => {
      const box = canvas.getBoundingClientRect();
      const vx = mx.scale.invert(event.clientX - box.left);
      const vy = my.scale.invert(event.clientY - box.top);
      if (vx < x.from || vx > x.to || vy < y.from || vy > y.to) return;
      choose(vx, vy, true);
    };
  };

  /** The growth rate at the grid point nearest (vx, vy), once the chart is computed. */
  const rateAt = (vx: number, vy: number): number | null => {
    if (!rates) return null;
    const nearest = (values: number[], v: number) => values.reduce((best, w, k) => (Math.abs(w - v) < Math.abs(values[best] - v) ? k : best), 0);
    return rates[nearest(ys, vy) * xs.length + nearest(xs, vx)];
  };

  /** Moves the point; `apply` hands it to the chapter (a click, Enter or Space), as a simulator's parameters. */
  const choose = (vx: number, vy: number, apply: boolean) => {
    chosen = [vx, vy];
    draw();
    const rate = rateAt(vx, vy);
    const verdict = rate === null ? '' : rate > 0 ? `: unstable, growth rate ${rate.toPrecision(3)}` : ': stable';
    reading.textContent = `${x.param} = ${vx.toPrecision(4)}, ${y.param} = ${vy.toPrecision(4)}${verdict}${apply ? ' (chosen)' : ''}`;
    if (apply) options.onSelect?.({ [x.param]: vx, [y.param]: vy });
  };

  canvas.addEventListener('keydown', (event) => {
    const [vx, vy] = chosen ?? [(x.from + x.to) / 2, (y.from + y.to) / 2];
    const grid = event.shiftKey ? 10 : 1;
    const dx = ((x.to - x.from) / (xs.length - 1)) * grid;
    const dy = ((y.to - y.from) / (ys.length - 1)) * grid;
    const clamp = (v: number, lo: number, hi: number) => Math.min(hi, Math.max(lo, v));
    const moves: Record<string, [number, number]> = { ArrowLeft: [-dx, 0], ArrowRight: [dx, 0], ArrowDown: [0, -dy], ArrowUp: [0, dy] };
    if (event.key in moves) {
      event.preventDefault();
      const [mxv, myv] = moves[event.key];
      choose(clamp(vx + mxv, x.from, x.to), clamp(vy + myv, y.from, y.to), false);
    } else if (event.key === 'Enter' || event.key === ' ') {
      event.preventDefault();
      choose(vx, vy, true);
    }
  });

  const worker = new Worker(new URL('./stability-worker.ts', import.meta.url), { type: 'module' });
  const fail = (message: string) => {
    status.textContent = `Could not compute the chart: ${message}`;
    status.className = 'pb-error';
    worker.terminate();
  };
  worker.onmessage = (event: MessageEvent<{ progress?: number; rates?: Float64Array; error?: string }>) => {
    const m = event.data;
    if (m.progress !== undefined) progress.value = m.progress;
    if (m.error) fail(m.error);
    if (m.rates) {
      rates = m.rates;
      const unstable = rates.filter((r) => r > 0).length;
      status.textContent = `Shaded: unstable (growth rate by colour), ${unstable} of ${rates.length} points. Dashed: the first-order boundary. Click, or use the arrow keys and Enter, to choose ${x.param} and ${y.param}.`;
      root.dataset.unstable = String(unstable);
      worker.terminate();
      draw();
      root.dataset.ready = '';
    }
  };
  compiledModelFor({ dof: 1, hamiltonian: options.hamiltonian, params: options.params }, build).then(
    (model) => {
      const request: StabilityRequest = {
        model,
        params: options.params,
        x: { param: x.param, values: xs },
        y: { param: y.param, values: ys },
        frequencyParam: options.frequencyParam,
        stepsPerPeriod: options.stepsPerPeriod ?? 200,
      };
      worker.postMessage(request);
    },
    (error: unknown) => fail((error as Error)?.message ?? String(error)),
  );
  requestAnimationFrame(draw);
  // The chart is part of a cell's output: if the cell re-runs, this instance is discarded with its worker.
  new MutationObserver((_, observer) => {
    if (!root.isConnected && root.dataset.ready === undefined) {
      worker.terminate();
      observer.disconnect();
    }
  }).observe(document.body, { childList: true, subtree: true });
  return root;
}
