import type { Context } from './canvas.ts';
import type { Ticks } from './ticks.ts';

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

/** Labels closer than this (CSS pixels) to a kept one are dropped. */
export const MIN_LABEL_GAP = 13;

/**
 * The ticks whose labels do not crowd each other: 0 is kept first, then the
 * largest magnitudes, each only if it is at least `gap` pixels from every
 * tick already kept. A symlog axis bunches ±1, ±10 around 0; this thins them.
 */
export function spacedTicks(values: readonly number[], position: (v: number) => number, gap = MIN_LABEL_GAP): number[] {
  const order = [...values].sort((a, b) => (a === 0 ? -1 : b === 0 ? 1 : Math.abs(b) - Math.abs(a)));
  const kept: { v: number; at: number }[] = [];
  for (const v of order) {
    const at = position(v);
    if (kept.every((k) => Math.abs(k.at - at) >= gap)) kept.push({ v, at });
  }
  return kept.map((k) => k.v).sort((a, b) => a - b);
}

/** Horizontal grid lines and left tick labels for y ticks at `position(v)`. */
export function drawYAxis(ctx: Context, box: Box, ticks: Ticks, position: (v: number) => number, style: AxisStyle): void {
  ctx.font = style.font;
  ctx.textAlign = 'right';
  ctx.textBaseline = 'middle';
  ctx.lineWidth = 1;
  for (const v of spacedTicks(ticks.values, position)) {
    const y = Math.round(position(v)) + 0.5;
    if (y < box.y - 0.5 || y > box.y + box.height + 0.5) continue;
    ctx.strokeStyle = v === 0 ? style.axis : style.grid;
    ctx.globalAlpha = v === 0 ? 0.45 : 1;
    ctx.beginPath();
    ctx.moveTo(box.x, y);
    ctx.lineTo(box.x + box.width, y);
    ctx.stroke();
    ctx.globalAlpha = 1;
    ctx.fillStyle = style.text;
    ctx.fillText(ticks.format(v), box.x - 6, y, box.x - 8); // squeezed rather than cut when too wide
  }
  frameLine(ctx, style, box.x + 0.5, box.y, box.x + 0.5, box.y + box.height);
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
