import type { Context } from './canvas.ts';
import type { AxisLabels } from './tick-labels.ts';

/**
 * Axes drawn on a canvas from d3 scales: tick positions come from the
 * scale, values and labels from ticks.ts. Drawing on the canvas rather than
 * in an SVG overlay keeps a PNG download identical to the screen. Units are
 * CSS pixels; the caller scales the context by the pixel ratio.
 */

/** The plot area inside the axes, in CSS pixels. */
export interface Box {
  x: number;
  y: number;
  width: number;
  height: number;
}

export interface AxisStyle {
  text: string;
  axis: string;
  grid: string;
  font: string;
}

/** Room left of the plot area for y tick labels, and below it for t labels. */
export const MARGIN = { left: 56, right: 16, top: 8, bottom: 24 };

/**
 * Horizontal grid lines at every tick and left labels where given, for
 * ticks at y = `position(v)`; labels relative to an offset get it written
 * once, in the corner under them.
 */
export function drawYAxis(ctx: Context, box: Box, ticks: AxisLabels, position: (v: number) => number, style: AxisStyle): void {
  ctx.font = style.font;
  ctx.textAlign = 'right';
  ctx.textBaseline = 'middle';
  ctx.lineWidth = 1;
  ticks.values.forEach((v, i) => {
    const y = Math.round(position(v)) + 0.5;
    if (y < box.y - 0.5 || y > box.y + box.height + 0.5) return;
    const zero = v === 0 && ticks.offset === 0;
    ctx.strokeStyle = zero ? style.axis : style.grid;
    ctx.globalAlpha = zero ? 0.45 : 1;
    ctx.beginPath();
    ctx.moveTo(box.x, y);
    ctx.lineTo(box.x + box.width, y);
    ctx.stroke();
    ctx.globalAlpha = 1;
    ctx.fillStyle = style.text;
    // squeezed rather than cut if a label is still too wide (tick-labels.ts picks labels that fit)
    if (ticks.labels[i]) ctx.fillText(ticks.labels[i], box.x - 6, y, box.x - 8);
  });
  if (ticks.offsetText) {
    ctx.textBaseline = 'top';
    ctx.fillText(`+${ticks.offsetText}`.replace('+−', '−'), box.x - 6, box.y + box.height + 6, box.x - 8);
  }
  frameLine(ctx, style, box.x + 0.5, box.y, box.x + 0.5, box.y + box.height);
}

/** The room for a y label beside a plot area at x = `left`: from the axis to the canvas edge, less padding. */
export function yLabelRoom(left: number): number {
  return left - 8;
}

/**
 * Tick marks and labels of a horizontal axis whose line is at y = `top`, for
 * ticks at x = `position(v)`; labels may run past the ends (the canvas clips).
 */
export function drawXTicks(ctx: Context, top: number, values: readonly number[], format: (v: number) => string, position: (v: number) => number, style: AxisStyle): void {
  ctx.font = style.font;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'top';
  ctx.lineWidth = 1;
  ctx.strokeStyle = style.axis;
  ctx.fillStyle = style.text;
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
export function drawXFrame(ctx: Context, box: Box, style: AxisStyle, name: string): void {
  const bottom = box.y + box.height;
  frameLine(ctx, style, box.x, bottom + 0.5, box.x + box.width, bottom + 0.5);
  ctx.font = style.font;
  ctx.fillStyle = style.text;
  ctx.textAlign = 'left';
  ctx.textBaseline = 'middle';
  ctx.fillText(name, box.x + box.width + 4, bottom);
}

function frameLine(ctx: Context, style: AxisStyle, x0: number, y0: number, x1: number, y1: number): void {
  ctx.strokeStyle = style.axis;
  ctx.globalAlpha = 0.6;
  ctx.beginPath();
  ctx.moveTo(x0, y0);
  ctx.lineTo(x1, y1);
  ctx.stroke();
  ctx.globalAlpha = 1;
}
