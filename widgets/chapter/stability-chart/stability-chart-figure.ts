/**
 * The stability chart's figure: the growth rates over the grid of two
 * parameters as a heat map on a point panel (plots/point-panel.ts), the
 * theoretical boundaries dashed over it, the chosen point, and a reading of
 * the rate there. The chapter hears of a chosen point through `onSelect`.
 */
import { type PanelFrame, PointPanel } from '../../plots/point-panel.ts';

/** One axis of the chart: a parameter, its range, and the grid's values along it. */
export interface ChartAxis {
  param: string;
  from: number;
  to: number;
  label?: string;
  values: number[];
}

export interface FigureOptions {
  x: ChartAxis;
  y: ChartAxis;
  boundaries: ((y: number) => number)[];
  height: number;
  /** the point chosen first */
  chosen: [number, number];
  onSelect?: (values: Record<string, number>) => void;
}

/** Warm ramp for growth rates, yellow (slow) to red (fast); readable on light and dark backgrounds. */
const heat = (v: number) => `hsl(${48 - 46 * v}, 88%, ${64 - 20 * v}%)`;

/** Grid steps an arrow moves the point with Shift held. */
const LARGER_STEP = 10;

export class StabilityFigure {
  readonly root: HTMLElement;
  readonly progress: HTMLProgressElement;
  readonly #options: FigureOptions;
  readonly #panel: PointPanel;
  readonly #reading: HTMLParagraphElement;
  readonly #status: HTMLElement;
  /** growth rates on the grid, row by row of y, once computed */
  #rates: Float64Array | null = null;
  #chosen: [number, number] | null;

  constructor(options: FigureOptions) {
    const { x, y } = options;
    this.#options = options;
    this.root = document.createElement('figure');
    this.root.className = 'pb-stability';
    this.root.dataset.widget = 'stability-chart';
    // Operable by keyboard as by pointer: arrows move the chosen point over the grid, Enter or Space applies it.
    this.#panel = new PointPanel(this.root, 'stability chart', `Stability chart over ${x.param} and ${y.param}: arrow keys move the point (Shift for larger steps), Enter or Space chooses it; or click`);
    this.#panel.followWidth(() => this.draw());
    this.#reading = document.createElement('p');
    this.#reading.className = 'pb-stability-reading';
    this.#reading.setAttribute('aria-live', 'polite');
    this.#status = document.createElement('figcaption');
    this.progress = document.createElement('progress');
    this.progress.max = 1;
    this.progress.value = 0;
    this.#status.append(this.progress, ' computing Floquet multipliers…');
    this.root.append(this.#panel.canvas, this.#reading, this.#status);
    this.#chosen = options.chosen;
    this.#listen();
  }

  /** Draws the chart as it stands: the rates once computed, the boundaries, the chosen point and the axes. */
  draw(): void {
    const { x, y, height } = this.#options;
    const f = this.#panel.frame(() => height, [x.from, x.to], [y.from, y.to]);
    if (!f) return;
    if (this.#rates) drawRates(f, this.#rates, x.values.length, y.values.length);
    drawBoundaries(f, this.#options.boundaries, y.values);
    this.#panel.finish(f, this.#chosen, { xLabel: x.label ?? x.param, yLabel: y.label ?? y.param });
  }

  /** The computed rates: counted, drawn shaded where unstable, and the chart ready. */
  show(rates: Float64Array): void {
    const { x, y } = this.#options;
    this.#rates = rates;
    const unstable = rates.filter((r) => r > 0).length;
    this.#status.textContent = `Shaded: unstable (growth rate by colour), ${unstable} of ${rates.length} points. Dashed: the first-order boundary. Click, or use the arrow keys and Enter, to choose ${x.param} and ${y.param}.`;
    this.root.dataset.unstable = String(unstable);
    this.draw();
    this.root.dataset.ready = '';
  }

  /** Says why there is no chart (the model did not compile, the worker failed). */
  fail(message: string): void {
    this.#status.textContent = `Could not compute the chart: ${message}`;
    this.#status.className = 'pb-error';
  }

  /** Moves the point; `apply` hands it to the chapter (a click, Enter or Space), as a simulator's parameters. */
  #choose(vx: number, vy: number, apply: boolean): void {
    const { x, y } = this.#options;
    this.#chosen = [vx, vy];
    this.draw();
    const rate = this.#rates && rateAt(this.#rates, x.values, y.values, vx, vy);
    const verdict = rate === null ? '' : rate > 0 ? `: unstable, growth rate ${rate.toPrecision(3)}` : ': stable';
    this.#reading.textContent = `${x.param} = ${vx.toPrecision(4)}, ${y.param} = ${vy.toPrecision(4)}${verdict}${apply ? ' (chosen)' : ''}`;
    if (apply) this.#options.onSelect?.({ [x.param]: vx, [y.param]: vy });
  }

  /** A click inside the chart chooses its point; the arrows move over the grid, kept inside it, and Enter chooses. */
  #listen(): void {
    const { x, y } = this.#options;
    const outside = (vx: number, vy: number) => vx < x.from || vx > x.to || vy < y.from || vy > y.to;
    this.#panel.onClick((vx, vy) => outside(vx, vy) || this.#choose(vx, vy, true));
    const point = () => this.#chosen ?? [(x.from + x.to) / 2, (y.from + y.to) / 2];
    const clamp = (v: number, lo: number, hi: number) => Math.min(hi, Math.max(lo, v));
    const gridStep = () => [(x.to - x.from) / (x.values.length - 1), (y.to - y.from) / (y.values.length - 1)] as const;
    this.#panel.onKeys(
      gridStep,
      LARGER_STEP,
      (du, dv) => {
        const [vx, vy] = point();
        this.#choose(clamp(vx + du, x.from, x.to), clamp(vy + dv, y.from, y.to), false);
      },
      () => this.#choose(...point(), true),
    );
  }
}

/** The growth rate at the grid point nearest (vx, vy). */
export function rateAt(rates: Float64Array, xs: number[], ys: number[], vx: number, vy: number): number {
  const nearest = (values: number[], v: number) => values.reduce((best, w, k) => (Math.abs(w - v) < Math.abs(values[best] - v) ? k : best), 0);
  return rates[nearest(ys, vy) * xs.length + nearest(xs, vx)];
}

/** A cell per grid point, shaded by the square root of its growth rate (so slow growth still shows); stable cells stay blank. */
function drawRates({ g, rect, theme }: PanelFrame, rates: Float64Array, columns: number, rows: number): void {
  let top = 0;
  for (const r of rates) top = Math.max(top, r);
  const cw = rect.width / columns;
  const ch = rect.height / rows;
  for (let j = 0; j < rows; j++) {
    for (let i = 0; i < columns; i++) {
      const r = rates[j * columns + i];
      g.fillStyle = r > 0 ? heat(Math.sqrt(r / (top || 1))) : theme.bg;
      // Half a pixel more each way, so that no seam of the background shows between cells.
      g.fillRect(rect.left + i * cw, rect.top + rect.height - (j + 1) * ch, cw + 0.5, ch + 0.5);
    }
  }
}

/** Each boundary x(y), dashed, through the grid's y values. */
function drawBoundaries({ g, mx, my, theme }: PanelFrame, boundaries: ((y: number) => number)[], ys: number[]): void {
  g.strokeStyle = theme.fg;
  g.lineWidth = 1.5;
  g.setLineDash([5, 4]);
  for (const boundary of boundaries) {
    g.beginPath();
    ys.forEach((v, j) => (j ? g.lineTo : g.moveTo).call(g, mx.scale(boundary(v)), my.scale(v)));
    g.stroke();
  }
  g.setLineDash([]);
}
