import { type BuildOptions, compiledModelFor } from '../../../core/index.ts';
import { StabilityFigure } from './stability-chart-figure.ts';
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

/** The parameters' values the rates are computed at. */
type Grid = Pick<StabilityRequest, 'x' | 'y'>;

/** The grid's values along an axis: `count` (else n) evenly spaced from `from` to `to`, both included. */
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
  const grid: Grid = { x: { param: x.param, values: axis(x, 120) }, y: { param: y.param, values: axis(y, 60) } };
  const figure = new StabilityFigure({
    x: { ...x, values: grid.x.values },
    y: { ...y, values: grid.y.values },
    boundaries,
    height,
    chosen: [options.params[x.param], options.params[y.param]],
    onSelect: options.onSelect,
  });
  const worker = new Worker(new URL('./stability-worker.ts', import.meta.url), { type: 'module' });
  computeRates(worker, figure, options, grid, build);
  requestAnimationFrame(() => figure.draw());
  // The chart is part of a cell's output: if the cell re-runs, this instance is discarded with its worker.
  const root = figure.root;
  new MutationObserver((_, observer) => {
    if (!root.isConnected && root.dataset.ready === undefined) {
      worker.terminate();
      observer.disconnect();
    }
  }).observe(document.body, { childList: true, subtree: true });
  return root;
}

/** Compiles the model, sends it to the worker with the grid, and shows the worker's progress and rates on the figure. */
function computeRates(worker: Worker, figure: StabilityFigure, options: StabilityChartOptions, grid: Grid, build: BuildOptions): void {
  const fail = (message: string) => {
    figure.fail(message);
    worker.terminate();
  };
  worker.onmessage = (event: MessageEvent<{ progress?: number; rates?: Float64Array; error?: string }>) => {
    const m = event.data;
    if (m.progress !== undefined) figure.progress.value = m.progress;
    if (m.error) fail(m.error);
    if (m.rates) {
      worker.terminate();
      figure.show(m.rates);
    }
  };
  compiledModelFor({ dof: 1, hamiltonian: options.hamiltonian, params: options.params }, build).then(
    (model) => {
      const request: StabilityRequest = {
        model,
        params: options.params,
        ...grid,
        frequencyParam: options.frequencyParam,
        stepsPerPeriod: options.stepsPerPeriod ?? 200,
      };
      worker.postMessage(request);
    },
    (error: unknown) => fail((error as Error)?.message ?? String(error)),
  );
}
