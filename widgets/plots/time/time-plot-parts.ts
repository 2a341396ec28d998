import { h as el } from '../../controls/dom.ts';
import { drawXFrame, drawXTicks, drawYAxis, fontOf, TICK_FONT, TIME_MARGIN, yLabelRoom, type Rect } from '../axes.ts';
import { multiples, timeTicks } from './time-axis.ts';
import type { Context } from '../canvas.ts';
import type { Theme } from '../theme.ts';
import { axisLabels, type AxisLabels } from '../ticks.ts';
import { scaleFor, scaleLinear, type Domain, type SignedKind } from '../scale.ts';

/** The time windows offered, in time units across the plot. */
export const WINDOWS = [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000];

export { el };

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
