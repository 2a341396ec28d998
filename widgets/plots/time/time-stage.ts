import { h as el } from '../../controls/dom.ts';
import type { TrajectoryRecord } from '../../../core/index.ts';
import { type AxisReadout, drawXFrame, drawXTicks, drawYAxis, fontOf, type Rect, TICK_FONT, TIME_MARGIN, yLabelRoom } from '../axes.ts';
import { type Context, context2d, createSurface, sizeCanvas, type Surface } from '../canvas.ts';
import { type Domain, scaleFor, scaleLinear, type SignedKind } from '../scale.ts';
import type { Theme } from '../theme.ts';
import { type AxisLabels, axisLabels } from '../ticks.ts';
import { multiples, TimeAxisStrips, timeTicks } from './time-axis.ts';
import { TimeRenderer } from './time-renderer.ts';

/** CSS pixels the t labels may show left of the plot area: enough for a label at its left edge, not for the next. */
const STRIP_LEFT = 8;

/**
 * The layers of a time plot, bottom to top: the frame canvas (grid, axes,
 * redrawn only when the y range changes); the live trace as the scroll
 * ring's tile canvases, moved by CSS transforms like the paper's sprites, so
 * showing a frame repaints nothing; a canvas for a scrolled-back window
 * drawn from the record; and the t ticks, as strips moving with the tiles
 * (live) or a band canvas (scrolled back).
 */
export class TimeStage {
  readonly element: HTMLElement;
  readonly renderer: TimeRenderer;
  ratio = 1;
  cssWidth = 0;
  private readonly frame: HTMLCanvasElement;
  private readonly tiles: HTMLElement;
  private readonly history: HTMLCanvasElement;
  private readonly stripBox: HTMLElement;
  private readonly strips: TimeAxisStrips;
  private readonly band: HTMLCanvasElement;
  private newTiles: HTMLCanvasElement[] = [];
  private newStrips: HTMLCanvasElement[] = [];
  private readonly tileX = new Float64Array(3).fill(NaN);
  private readonly stripX = new Float64Array(3).fill(NaN);
  private frameKey = '';
  private bandKey = '';
  /** the y axis's ticks and labels as last drawn */
  yLabels: AxisLabels | null = null;

  constructor(
    readonly cssHeight: number,
    window: number,
    kind: SignedKind,
    label: string,
  ) {
    this.renderer = new TimeRenderer((w, h) => this.layer(w, h, this.newTiles), window, kind);
    this.strips = new TimeAxisStrips((w, h) => this.layer(w, h, this.newStrips));
    const hidden = { 'aria-hidden': 'true' };
    this.frame = el('canvas', 'pb-frame', hidden);
    this.tiles = el('div', 'pb-tiles', hidden);
    this.history = el('canvas', 'pb-data-layer', hidden);
    this.stripBox = el('div', 'pb-tiles pb-xstrips', hidden);
    this.band = el('canvas', 'pb-xaxis', hidden);
    this.history.hidden = this.band.hidden = true;
    for (const layer of [this.tiles, this.history]) Object.assign(layer.style, { left: `${TIME_MARGIN.left}px`, top: `${TIME_MARGIN.top}px` });
    const aria = { tabindex: '0', role: 'group', 'aria-roledescription': 'plot', 'aria-label': label };
    this.element = el('div', 'pb-stage', aria, this.frame, this.tiles, this.history, this.stripBox, this.band);
    this.element.style.height = `${cssHeight}px`;
  }

  /** Sizes every layer for a width in CSS pixels and a pixel ratio; the caller then redraws. */
  layout(cssWidth: number, ratio: number, lineWidth: number): void {
    this.cssWidth = cssWidth;
    this.ratio = ratio;
    const box = plotBox(cssWidth, this.cssHeight);
    sizeCanvas(this.frame, cssWidth, this.cssHeight, ratio);
    sizeCanvas(this.history, box.width, box.height, ratio);
    sizeCanvas(this.band, cssWidth, TIME_MARGIN.bottom, ratio);
    this.band.style.top = `${xBandTop(box)}px`;
    Object.assign(this.tiles.style, { width: `${box.width}px`, height: `${box.height}px` });
    this.renderer.resize(this.history.width, this.history.height, lineWidth);
    this.strips.resize(this.renderer.width, Math.round(TIME_MARGIN.bottom * ratio), ratio, this.renderer);
    Object.assign(this.stripBox.style, {
      left: `${box.left - STRIP_LEFT}px`,
      top: `${xBandTop(box)}px`,
      width: `${box.width + STRIP_LEFT + TIME_MARGIN.right}px`,
      height: `${TIME_MARGIN.bottom}px`,
    });
    this.tiles.replaceChildren(...this.newTiles);
    this.stripBox.replaceChildren(...this.newStrips);
    this.newTiles = [];
    this.newStrips = [];
    this.tileX.fill(NaN);
    this.stripX.fill(NaN);
    this.invalidate();
  }

  /** Forgets the drawn axes (a new theme, window or origin). */
  invalidate(): void {
    this.frameKey = this.bandKey = '';
    this.strips.reset(this.renderer);
  }

  /** Shows the live trace: moves tiles and strips into place, redraws the frame if the y range changed. */
  showLive(theme: Theme): void {
    this.setMode(true);
    const move = (positions: Float64Array, shift: number) => (slot: number, surface: Surface, x: number): void => {
      if (Object.is(positions[slot], x)) return;
      positions[slot] = x;
      const style = (surface as HTMLCanvasElement).style;
      if (x !== x) style.visibility = 'hidden';
      else {
        style.visibility = '';
        style.transform = `translateX(${x / this.ratio + shift}px)`;
      }
    };
    const r = this.renderer;
    r.place(move(this.tileX, 0));
    this.strips.place(r.end, r, theme, move(this.stripX, STRIP_LEFT - this.strips.spill / this.ratio));
    this.drawFrame(theme, this.axes0(r.left));
  }

  /** Shows the window of columns [end − width, end) drawn from the record, with its t ticks. */
  showHistory(record: TrajectoryRecord, end: number, theme: Theme): void {
    this.setMode(false);
    const r = this.renderer;
    r.renderWindow(context2d(this.history), record, end);
    const state = this.axes0(end - r.width);
    this.drawFrame(theme, state);
    const key = `${end} ${r.width} ${r.window} ${this.frameKey}`;
    if (key === this.bandKey) return;
    this.bandKey = key;
    const ctx = context2d(this.band);
    ctx.setTransform(this.ratio, 0, 0, this.ratio, 0, 0);
    drawTimeTicks(ctx, state, theme, r.window, this.cssWidth, TIME_MARGIN.bottom);
  }

  /** The picture as shown, for a PNG: opaque, with a legend line, at device resolution. */
  composite(theme: Theme, legend: readonly { name: string; color: string }[], live: boolean): HTMLCanvasElement {
    const box = plotBox(this.cssWidth, this.cssHeight);
    const r = this.ratio;
    return compositePlot(this.frame.width, this.frame.height, r, theme, legend, (ctx, top) => {
      ctx.drawImage(this.frame, 0, top);
      const x = Math.round(box.left * r);
      const y = top + Math.round(box.top * r);
      const band = top + Math.round(xBandTop(box) * r);
      const clip = (x0: number, y0: number, w: number, h: number, paint: () => void): void => {
        ctx.save();
        ctx.beginPath();
        ctx.rect(x0, y0, w, h);
        ctx.clip();
        paint();
        ctx.restore();
      };
      clip(x, y, this.history.width, this.history.height, () => (live ? this.renderer.composite(ctx, x, y) : ctx.drawImage(this.history, x, y)));
      if (!live) ctx.drawImage(this.band, 0, band);
      else clip(x - STRIP_LEFT * r, band, (box.width + STRIP_LEFT + TIME_MARGIN.right) * r, TIME_MARGIN.bottom * r, () => this.strips.composite(ctx, this.renderer.end, x, band));
    });
  }

  private setMode(live: boolean): void {
    this.tiles.style.visibility = this.stripBox.style.visibility = live ? '' : 'hidden';
    this.history.hidden = this.band.hidden = live;
  }

  private axes0(left: number): AxesState {
    const r = this.renderer;
    return { box: plotBox(this.cssWidth, this.cssHeight), kind: r.kind, domain: r.domain, inset: r.inset, t0: r.timeOf(left), t1: r.timeOf(left + r.width) };
  }

  /** Redraws grid and y axis when the range, size or theme changed. */
  private drawFrame(theme: Theme, state: AxesState): void {
    const key = `${state.kind} ${state.domain[0]} ${state.domain[1]} ${this.cssWidth} ${this.ratio} ${theme.muted} ${theme.axis} ${theme.grid} ${theme.font}`;
    if (key === this.frameKey) return;
    this.frameKey = key;
    const ctx = context2d(this.frame);
    ctx.setTransform(this.ratio, 0, 0, this.ratio, 0, 0);
    this.yLabels = drawTimeFrame(ctx, state, theme, this.cssWidth, this.cssHeight);
  }

  /** The axes as a reader sees them: y labels (and the t labels of the window shown) with positions and widths, CSS px. */
  axes(end: number, theme: Theme): { x: AxisReadout; y: AxisReadout } {
    const r = this.renderer;
    const state = this.axes0(end - r.width);
    const { box } = state;
    const ctx = context2d(this.frame);
    ctx.save();
    ctx.font = fontOf(theme, TICK_FONT);
    const font = TICK_FONT;
    const width = (text: string) => ctx.measureText(text).width;
    const y = scaleFor(state.kind, state.domain, [box.top + box.height * (1 - state.inset), box.top + box.height * state.inset]);
    const labels = this.yLabels ?? { values: [], labels: [], offset: 0, offsetText: '' };
    const yAxis: AxisReadout = {
      domain: [state.domain[0], state.domain[1]],
      kind: state.kind,
      labels: labels.values.flatMap((v, i) => (labels.labels[i] ? [{ text: labels.labels[i], at: y(v), width: width(labels.labels[i]) }] : [])),
      offset: labels.offsetText,
      font,
      room: yLabelRoom(box.left),
    };
    const { step, format } = timeTicks(r.window, box.width);
    const x = scaleLinear().domain([state.t0, state.t1]).range([box.left, box.left + box.width]);
    const xAxis: AxisReadout = {
      domain: [state.t0, state.t1],
      kind: 'linear',
      labels: multiples(state.t0, state.t1 + 1e-9 * step, step).map((t) => ({ text: format(t), at: x(t), width: width(format(t)) })),
      offset: '',
      font,
    };
    ctx.restore();
    return { x: xAxis, y: yAxis };
  }

  /** A tile or axis strip of a scroll ring: a canvas the page moves rather than repaints. */
  private layer(width: number, height: number, into: HTMLCanvasElement[]): Surface {
    const canvas = createSurface(width, height) as HTMLCanvasElement;
    canvas.style.width = `${width / this.ratio}px`;
    canvas.style.height = `${height / this.ratio}px`;
    canvas.style.visibility = 'hidden';
    into.push(canvas);
    return canvas;
  }
}

/** The time windows offered, in time units across the plot. */
export const WINDOWS = [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000];

/** The plot area inside a stage of `width × height` CSS pixels. */
export function plotBox(width: number, height: number): Rect {
  return {
    left: TIME_MARGIN.left,
    top: TIME_MARGIN.top,
    width: Math.max(1, width - TIME_MARGIN.left - TIME_MARGIN.right),
    height: Math.max(1, height - TIME_MARGIN.top - TIME_MARGIN.bottom),
  };
}

export interface AxesState {
  box: Rect;
  kind: SignedKind;
  domain: Domain;
  /** fraction of the plot height kept free at top and bottom */
  inset: number;
  t0: number;
  t1: number;
}

/**
 * The still part of a time plot, on its frame canvas (context scaled to CSS
 * pixels): grid, y axis, the t axis line and its name. Redrawn only when the
 * y range, size or theme changes.
 */
export function drawTimeFrame(ctx: Context, state: AxesState, theme: Theme, width: number, height: number): AxisLabels {
  const { box, kind, domain, inset } = state;
  ctx.clearRect(0, 0, width, height);
  const y = scaleFor(kind, domain, [box.top + box.height * (1 - inset), box.top + box.height * inset]);
  ctx.font = fontOf(theme, TICK_FONT);
  const labels = axisLabels(kind, domain, {
    along: 'y',
    position: y,
    length: box.height,
    measure: (text) => ctx.measureText(text).width,
    font: TICK_FONT,
    room: yLabelRoom(box.left),
  });
  drawYAxis(ctx, box, labels, y, theme);
  drawXFrame(ctx, box, theme, 't');
  return labels;
}

/** The top of the band under the plot that holds the t ticks, in CSS pixels. */
export function xBandTop(box: Rect): number {
  return box.top + box.height;
}

/**
 * The t ticks of a scrolled-back window on the band canvas under the plot
 * (context scaled to CSS pixels, origin at the band's top left); the same
 * steps and labels as the live strips (time-axis.ts).
 */
export function drawTimeTicks(ctx: Context, state: AxesState, theme: Theme, window: number, width: number, height: number): void {
  const { box, t0, t1 } = state;
  ctx.clearRect(0, 0, width, height);
  const { step, format } = timeTicks(window, box.width);
  const x = scaleLinear().domain([t0, t1]).range([box.left, box.left + box.width]);
  drawXTicks(ctx, 0.5, multiples(t0, t1 + 1e-9 * step, step), format, x, theme);
}

/**
 * A PNG-ready picture of a plot at device resolution: an opaque background,
 * a legend line at the top, then whatever `paint` draws (the layers), moved
 * down by `top` device pixels.
 */
export function compositePlot(
  width: number,
  height: number,
  ratio: number,
  theme: Theme,
  legend: readonly { name: string; color: string }[],
  paint: (ctx: CanvasRenderingContext2D, top: number) => void,
): HTMLCanvasElement {
  const band = legend.length > 0 ? 22 : 0;
  const top = Math.round(band * ratio);
  const out = document.createElement('canvas');
  out.width = width;
  out.height = height + top;
  const ctx = out.getContext('2d');
  if (!ctx) throw new Error('this browser gave no 2D canvas context');
  ctx.fillStyle = theme.bg;
  ctx.fillRect(0, 0, out.width, out.height);
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  ctx.font = fontOf(theme, 12);
  ctx.textBaseline = 'middle';
  let x = TIME_MARGIN.left;
  for (const { name, color } of legend) {
    ctx.fillStyle = color;
    ctx.fillRect(x, band / 2 - 1.5, 14, 3);
    ctx.fillStyle = theme.muted;
    ctx.fillText(name, x + 18, band / 2);
    x += 28 + ctx.measureText(name).width;
  }
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  paint(ctx, top);
  return out;
}
