import { ticksFor, type Mapping } from './axis-scale.ts';
import type { Theme } from './view-theme.ts';

/** The plotting area of a panel, in CSS pixels of its canvas. */
export interface Rect {
  left: number;
  top: number;
  width: number;
  height: number;
}

/** Space around a panel's plotting area for tick labels, axis titles and the legend. */
export const MARGIN = { left: 50, right: 12, top: 24, bottom: 38 };

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

/**
 * A panel's frame, grid and labelled ticks, drawn from d3 scales onto a
 * canvas layer (one image, so that a PNG download holds the axes too).
 */
export function drawAxes(g: CanvasRenderingContext2D, rect: Rect, mx: Mapping, my: Mapping, theme: Theme, style: AxesStyle, dpr: number): void {
  const { left, top, width, height } = rect;
  const right = left + width;
  const bottom = top + height;
  const x = ticksFor(mx, style.xTicks ?? Math.max(2, Math.round(width / 80)));
  const y = ticksFor(my, style.yTicks ?? Math.max(2, Math.round(height / 50)));
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
  g.font = fontOf(theme, 11);
  g.textAlign = 'center';
  g.textBaseline = 'top';
  x.values.forEach((v, i) => g.fillText(x.labels[i], mx.scale(v), bottom + 4));
  g.textAlign = 'right';
  g.textBaseline = 'middle';
  y.values.forEach((v, i) => g.fillText(y.labels[i], left - 5, my.scale(v)));
  g.fillStyle = theme.fg;
  g.font = fontOf(theme, 12, 500);
  g.textAlign = 'center';
  g.textBaseline = 'bottom';
  g.fillText(style.xLabel, left + width / 2, bottom + 36);
  g.translate(left - 38, top + height / 2);
  g.rotate(-Math.PI / 2);
  g.textBaseline = 'bottom';
  g.fillText(style.yLabel, 0, 0);
  g.restore();
}

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
  const end = rect.left + rect.width;
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
