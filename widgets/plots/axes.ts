import type { AxisKind, Mapping } from './scale.ts';
import { axisLabels, ticksFor, type AxisLabels } from './ticks.ts';
import type { Context } from './canvas.ts';
import type { Theme } from './theme.ts';

/**
 * Axes drawn on a canvas from the plots' scales (scale.ts) with their ticks
 * and labels (ticks.ts). Drawing on the canvas rather than in an SVG overlay
 * keeps a PNG download identical to the screen. Units are CSS pixels; the
 * caller scales the context by the pixel ratio.
 *
 * Two layouts use them: a panel (the plane views, the spectrum, the book's
 * charts) has a frame, a grid both ways and titled axes; the time plot has
 * a scrolling time axis, drawn tile by tile, under a fixed y axis.
 */

/** The plotting area inside the axes, in CSS pixels of its canvas. */
export interface Rect {
  left: number;
  top: number;
  width: number;
  height: number;
}

/** Space around a panel's plotting area for tick labels, axis titles and the legend. */
export const MARGIN = { left: 50, right: 12, top: 24, bottom: 38 };

/** The time plot's: room left of the plot area for y tick labels, and below it for the scrolling t labels. */
export const TIME_MARGIN = { left: 56, right: 16, top: 8, bottom: 24 };

export interface AxesStyle {
  xLabel: string;
  yLabel: string;
  /** ticks wanted on each axis; fewer fit a small panel */
  xTicks?: number;
  yTicks?: number;
}

/** The centre of the device pixel at or left of v, in CSS pixels: a hairline there is one sharp device pixel. */
export function crisp(v: number, dpr: number): number {
  return (Math.floor(v * dpr) + 0.5) / dpr;
}

export function fontOf(theme: Theme, size: number, weight = 400): string {
  return `${weight} ${size}px ${theme.font}`;
}

/** Tick labels are drawn at this size (CSS px): the smallest text on a plot, and still 11 px on a phone. */
export const TICK_FONT = 11;

/** A drawn axis as a reader (or a test) can check it: its range, labels with their positions and widths. */
export interface AxisReadout {
  domain: [number, number];
  kind: AxisKind;
  /** labelled ticks: text, centre along the axis and width, CSS px */
  labels: { text: string; at: number; width: number }[];
  /** the labels are relative to this (written out), '' when absolute */
  offset: string;
  font: number;
  /** y axis: the width its labels had room for */
  room?: number;
}

/**
 * The labels of both axes of a panel, fitted to its size with the canvas's
 * own text widths (ticks.ts). An axis given a tick count in `style`
 * keeps its scale's own ticks and format instead (a chart's log axis).
 */
export function panelLabels(g: CanvasRenderingContext2D, rect: Rect, mx: Mapping, my: Mapping, theme: Theme, style: Pick<AxesStyle, 'xTicks' | 'yTicks'> = {}): { x: AxisLabels; y: AxisLabels } {
  g.save();
  g.font = fontOf(theme, TICK_FONT);
  const measure = (text: string) => g.measureText(text).width;
  const fitted = (m: Mapping, along: 'x' | 'y', length: number, count: number | undefined): AxisLabels => {
    if (count !== undefined || m.kind === 'log') {
      const own = ticksFor(m, count ?? 10);
      return { values: own.values, labels: own.labels, offset: 0, offsetText: '' };
    }
    return axisLabels(m.kind === 'symlog' ? 'symlog' : 'linear', m.scale.domain() as [number, number], { along, position: m.scale, length, measure, font: TICK_FONT }, m.c);
  };
  const x = fitted(mx, 'x', rect.width, style.xTicks);
  const y = fitted(my, 'y', rect.height, style.yTicks);
  g.restore();
  return { x, y };
}

/** Between the y labels and the y title, and the title's own height, CSS px. */
const TITLE_GAP = 6;
const TITLE_SIZE = 13;

/** The left margin a panel needs for its y labels and title: the default, or more for wide labels. */
export function leftMarginFor(g: CanvasRenderingContext2D, labels: AxisLabels, theme: Theme): number {
  g.save();
  g.font = fontOf(theme, TICK_FONT);
  const widest = Math.max(0, ...labels.labels.map((l) => (l ? g.measureText(l).width : 0)));
  g.restore();
  return Math.max(MARGIN.left, Math.ceil(5 + widest + TITLE_GAP + TITLE_SIZE));
}

/** An axis title with the offset its labels are relative to: "q − 1×10⁹". */
function titled(name: string, labels: AxisLabels): string {
  if (!labels.offsetText) return name;
  return labels.offset < 0 ? `${name} + ${labels.offsetText.replace('−', '')}` : `${name} − ${labels.offsetText}`;
}

/**
 * A panel's frame, grid and labelled ticks, drawn from d3 scales onto a
 * canvas layer (one image, so that a PNG download holds the axes too).
 * Returns what it drew, for the plot's text alternative and for tests.
 */
export function drawAxes(g: CanvasRenderingContext2D, rect: Rect, mx: Mapping, my: Mapping, theme: Theme, style: AxesStyle, dpr: number): { x: AxisReadout; y: AxisReadout } {
  const { left, top, width, height } = rect;
  const right = left + width;
  const bottom = top + height;
  const { x, y } = panelLabels(g, rect, mx, my, theme, style);
  g.save();
  g.lineWidth = 1 / dpr;
  g.strokeStyle = theme.muted;
  g.globalAlpha = 0.28;
  g.beginPath();
  for (const v of x.values) {
    const px = crisp(mx.scale(v), dpr);
    g.moveTo(px, top);
    g.lineTo(px, bottom);
  }
  for (const v of y.values) {
    const py = crisp(my.scale(v), dpr);
    g.moveTo(left, py);
    g.lineTo(right, py);
  }
  g.stroke();
  g.globalAlpha = 0.8;
  g.strokeRect(crisp(left, dpr), crisp(top, dpr), Math.round(width * dpr) / dpr, Math.round(height * dpr) / dpr);
  g.globalAlpha = 1;
  g.fillStyle = theme.muted;
  g.font = fontOf(theme, TICK_FONT);
  g.textAlign = 'center';
  g.textBaseline = 'top';
  const readout = (m: Mapping, labels: AxisLabels, room?: number): AxisReadout => ({
    domain: m.scale.domain() as [number, number],
    kind: m.kind,
    labels: labels.values.flatMap((v, i) => (labels.labels[i] ? [{ text: labels.labels[i], at: m === mx ? xAt(v, labels.labels[i]) : m.scale(v), width: g.measureText(labels.labels[i]).width }] : [])),
    offset: labels.offsetText,
    font: TICK_FONT,
    room,
  });
  // a label at either end stays on the canvas rather than running off it
  const xAt = (v: number, text: string): number => {
    const half = g.measureText(text).width / 2;
    return Math.max(half + 1, Math.min(right + MARGIN.right - half - 1, mx.scale(v)));
  };
  x.values.forEach((v, i) => x.labels[i] && g.fillText(x.labels[i], xAt(v, x.labels[i]), bottom + 4));
  g.textAlign = 'right';
  g.textBaseline = 'middle';
  const room = left - 5 - TITLE_GAP - TITLE_SIZE;
  y.values.forEach((v, i) => y.labels[i] && g.fillText(y.labels[i], left - 5, my.scale(v)));
  const drawn = { x: readout(mx, x), y: readout(my, y, room) };
  const widest = Math.max(0, ...drawn.y.labels.map((l) => l.width));
  g.fillStyle = theme.fg;
  g.font = fontOf(theme, 12, 500);
  g.textAlign = 'center';
  g.textBaseline = 'bottom';
  g.fillText(titled(style.xLabel, x), left + width / 2, bottom + 36);
  // left of the widest label, never off the canvas (a caller's margin may be narrower than leftMarginFor asks)
  g.translate(Math.max(TITLE_SIZE + 1, left - Math.max(38, 5 + widest + TITLE_GAP)), top + height / 2);
  g.rotate(-Math.PI / 2);
  g.textBaseline = 'bottom';
  g.fillText(titled(style.yLabel, y), 0, 0);
  g.restore();
  return drawn;
}

/** Room the legend leaves at the right end of the top margin, CSS px: the Table button's. */
export const LEGEND_CLEAR = 60;

export interface LegendItem {
  label: string;
  color: string;
}

/** Coloured swatches with labels along the top margin of a panel, clipped to its width. */
export function drawLegend(g: CanvasRenderingContext2D, rect: Rect, items: readonly LegendItem[], theme: Theme, title?: string): void {
  g.save();
  g.font = fontOf(theme, 11.5);
  g.textBaseline = 'middle';
  g.textAlign = 'left';
  const y = rect.top - 11;
  let x = rect.left;
  // the stage's top right corner holds the Table button (view-frame.ts)
  const end = rect.left + rect.width - LEGEND_CLEAR;
  if (title) {
    g.fillStyle = theme.fg;
    g.font = fontOf(theme, 12, 600);
    g.fillText(title, x, y);
    x += g.measureText(title).width + 12;
    g.font = fontOf(theme, 11.5);
  }
  for (const item of items) {
    const w = g.measureText(item.label).width;
    if (x + 16 + w > end) break;
    g.fillStyle = item.color;
    g.beginPath();
    g.arc(x + 4, y, 4, 0, 2 * Math.PI);
    g.fill();
    g.fillStyle = theme.fg;
    g.fillText(item.label, x + 12, y);
    x += 12 + w + 14;
  }
  g.restore();
}

/**
 * Horizontal grid lines at every tick and left labels where given, for
 * ticks at y = `position(v)`; labels relative to an offset get it written
 * once, in the corner under them.
 */
export function drawYAxis(ctx: Context, box: Rect, ticks: AxisLabels, position: (v: number) => number, theme: Theme): void {
  ctx.font = fontOf(theme, TICK_FONT);
  ctx.textAlign = 'right';
  ctx.textBaseline = 'middle';
  ctx.lineWidth = 1;
  ticks.values.forEach((v, i) => {
    const y = Math.round(position(v)) + 0.5;
    if (y < box.top - 0.5 || y > box.top + box.height + 0.5) return;
    const zero = v === 0 && ticks.offset === 0;
    ctx.strokeStyle = zero ? theme.axis : theme.grid;
    ctx.globalAlpha = zero ? 0.45 : 1;
    ctx.beginPath();
    ctx.moveTo(box.left, y);
    ctx.lineTo(box.left + box.width, y);
    ctx.stroke();
    ctx.globalAlpha = 1;
    ctx.fillStyle = theme.muted;
    // squeezed rather than cut if a label is still too wide (ticks.ts picks labels that fit)
    if (ticks.labels[i]) ctx.fillText(ticks.labels[i], box.left - 6, y, box.left - 8);
  });
  if (ticks.offsetText) {
    ctx.textBaseline = 'top';
    ctx.fillText(`+${ticks.offsetText}`.replace('+−', '−'), box.left - 6, box.top + box.height + 6, box.left - 8);
  }
  frameLine(ctx, theme, box.left + 0.5, box.top, box.left + 0.5, box.top + box.height);
}

/** The room for a y label beside a plot area at x = `left`: from the axis to the canvas edge, less padding. */
export function yLabelRoom(left: number): number {
  return left - 8;
}

/**
 * Tick marks and labels of a horizontal axis whose line is at y = `top`, for
 * ticks at x = `position(v)`; labels may run past the ends (the canvas clips).
 */
export function drawXTicks(ctx: Context, top: number, values: readonly number[], format: (v: number) => string, position: (v: number) => number, theme: Theme): void {
  ctx.font = fontOf(theme, TICK_FONT);
  ctx.textAlign = 'center';
  ctx.textBaseline = 'top';
  ctx.lineWidth = 1;
  ctx.strokeStyle = theme.axis;
  ctx.fillStyle = theme.muted;
  ctx.globalAlpha = 0.8;
  ctx.beginPath();
  for (const v of values) {
    const x = Math.round(position(v)) + 0.5;
    ctx.moveTo(x, top);
    ctx.lineTo(x, top + 4);
  }
  ctx.stroke();
  ctx.globalAlpha = 1;
  for (const v of values) ctx.fillText(format(v), Math.round(position(v)) + 0.5, top + 6);
}

/** The bottom axis line of a plot area and the axis name just beyond its right end. */
export function drawXFrame(ctx: Context, box: Rect, theme: Theme, name: string): void {
  const bottom = box.top + box.height;
  frameLine(ctx, theme, box.left, bottom + 0.5, box.left + box.width, bottom + 0.5);
  ctx.font = fontOf(theme, TICK_FONT);
  ctx.fillStyle = theme.muted;
  ctx.textAlign = 'left';
  ctx.textBaseline = 'middle';
  ctx.fillText(name, box.left + box.width + 4, bottom);
}

function frameLine(ctx: Context, theme: Theme, x0: number, y0: number, x1: number, y1: number): void {
  ctx.strokeStyle = theme.axis;
  ctx.globalAlpha = 0.6;
  ctx.beginPath();
  ctx.moveTo(x0, y0);
  ctx.lineTo(x1, y1);
  ctx.stroke();
  ctx.globalAlpha = 1;
}
