import { scaleLinear } from 'd3-scale';
import { h as el } from '../controls/dom.ts';
import { drawXAxis, drawYAxis, MARGIN, type Box } from './axes.ts';
import type { Context } from './canvas.ts';
import type { Theme } from './colors.ts';
import { axisTicks } from './ticks.ts';
import { yScale, type Domain, type YScaleKind } from './y-map.ts';

/** The time windows offered, in time units across the plot. */
export const WINDOWS = [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000];

export { el };

/** The plot area inside a stage of `width × height` CSS pixels. */
export function plotBox(width: number, height: number): Box {
  return {
    x: MARGIN.left,
    y: MARGIN.top,
    width: Math.max(1, width - MARGIN.left - MARGIN.right),
    height: Math.max(1, height - MARGIN.top - MARGIN.bottom),
  };
}

export interface AxesState {
  box: Box;
  kind: YScaleKind;
  domain: Domain;
  /** fraction of the plot height kept free at top and bottom */
  inset: number;
  t0: number;
  t1: number;
}

/** Draws both axes and the grid of a time plot on its frame canvas (context scaled to CSS pixels). */
export function drawTimeAxes(ctx: Context, state: AxesState, theme: Theme, width: number, height: number): void {
  const { box, kind, domain, inset, t0, t1 } = state;
  ctx.clearRect(0, 0, width, height);
  const y = yScale(kind, domain, [box.y + box.height * (1 - inset), box.y + box.height * inset]);
  drawYAxis(ctx, box, axisTicks(kind, domain, Math.max(2, Math.floor(box.height / 36))), y, theme);
  const x = scaleLinear().domain([t0, t1]).range([box.x, box.x + box.width]);
  drawXAxis(ctx, box, axisTicks('linear', [t0, t1], Math.max(2, Math.floor(box.width / 90))), x, theme);
}

/**
 * A PNG-ready copy of a plot: opaque background, a legend line at the top,
 * then the frame (axes) and data canvases, all at device resolution.
 */
export function compositePlot(
  frame: HTMLCanvasElement,
  data: HTMLCanvasElement,
  ratio: number,
  theme: Theme,
  legend: readonly { name: string; color: string }[],
): HTMLCanvasElement {
  const band = legend.length > 0 ? 22 : 0;
  const out = document.createElement('canvas');
  out.width = frame.width;
  out.height = frame.height + Math.round(band * ratio);
  const ctx = out.getContext('2d');
  if (!ctx) return frame;
  ctx.fillStyle = theme.background;
  ctx.fillRect(0, 0, out.width, out.height);
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  ctx.font = theme.font.replace(/^\d+px/, '12px');
  ctx.textBaseline = 'middle';
  let x = MARGIN.left;
  for (const { name, color } of legend) {
    ctx.fillStyle = color;
    ctx.fillRect(x, band / 2 - 1.5, 14, 3);
    ctx.fillStyle = theme.text;
    ctx.fillText(name, x + 18, band / 2);
    x += 28 + ctx.measureText(name).width;
  }
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  const top = Math.round(band * ratio);
  ctx.drawImage(frame, 0, top);
  ctx.drawImage(data, Math.round(MARGIN.left * ratio), top + Math.round(MARGIN.top * ratio));
  return out;
}
