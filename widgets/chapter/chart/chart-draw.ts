/**
 * Paints a settled chart (chart-scale.ts) onto a canvas with the plot
 * foundation: its axes, grid and tick labels (plots/axes.ts), its theme
 * (plots/theme.ts), then the series clipped to the plot, then the
 * marker lines with their labels. Text is drawn at 11 CSS pixels or more and
 * the canvas is sized to its box, never scaled, so it reads at any width.
 */
import type { Context } from '../../plots/canvas.ts';
import { crisp, drawAxes, fontOf, type Rect } from '../../plots/axes.ts';
import { seriesColor, type Theme } from '../../plots/theme.ts';
import type { ResolvedSeries } from './chart-options.ts';
import { axisMapping, drawable, layoutChart, tickCount, type SettledChart } from './chart-scale.ts';

/** The canvas colour of a series. */
export function colorOf(s: Pick<ResolvedSeries, 'color'>, theme: Theme): string {
  return s.color === 'text' ? theme.fg : s.color === 'muted' ? theme.muted : seriesColor(theme, s.color);
}

/** What drawing needs beyond a Context: clipping and dashes, which the foundation's Context leaves out. */
export type ChartContext = Context & Pick<CanvasRenderingContext2D, 'clip' | 'setLineDash' | 'strokeText' | 'closePath'>;

/** Adds the drawable stretches of a curve to the current path; a point that cannot be drawn breaks the line. */
function tracePath(g: ChartContext, xs: Float64Array, ys: Float64Array, px: (v: number) => number, py: (v: number) => number, xLog: boolean, yLog: boolean, join: boolean): void {
  let pen = join;
  for (let k = 0; k < xs.length; k++) {
    if (!drawable(xs[k], ys[k], xLog, yLog)) {
      pen = false;
      continue;
    }
    const a = px(xs[k]);
    const b = py(ys[k]);
    if (pen) g.lineTo(a, b);
    else g.moveTo(a, b);
    pen = true;
  }
}

/** Draws the chart at `width` CSS pixels; returns the layout used, for pointer or export code. */
export function drawChart(g: ChartContext, chart: SettledChart, width: number, theme: Theme, dpr: number): { rect: Rect; height: number } {
  const { rect, height } = layoutChart(chart, width);
  const mx = axisMapping(chart.x, chart.xDomain, [rect.left, rect.left + rect.width]);
  const my = axisMapping(chart.y, chart.yDomain, [rect.top + rect.height, rect.top]);
  drawAxes(g as CanvasRenderingContext2D, rect, mx, my, theme, {
    xLabel: chart.x.label,
    yLabel: chart.y.label,
    // A linear axis leaves the count to the foundation, which fits its labels to the space; a log axis or given ticks keep their own.
    xTicks: chart.x.scale === 'log' || chart.x.ticks ? tickCount(chart.x, chart.xDomain, rect.width, 80) : undefined,
    yTicks: chart.y.scale === 'log' || chart.y.ticks ? tickCount(chart.y, chart.yDomain, rect.height, 28) : undefined,
  }, dpr);
  const xLog = chart.x.scale === 'log';
  const yLog = chart.y.scale === 'log';
  const px = (v: number) => mx.scale(v);
  const py = (v: number) => my.scale(v);

  g.save();
  g.beginPath();
  g.rect(rect.left, rect.top, rect.width, rect.height);
  g.clip();
  g.lineJoin = 'round';
  g.lineCap = 'round';
  for (const s of chart.series) {
    const color = colorOf(s, theme);
    g.strokeStyle = color;
    g.fillStyle = color;
    g.lineWidth = s.width;
    g.setLineDash(s.dash);
    if (s.kind === 'band') {
      const [lower, upper] = s.curves;
      g.globalAlpha = 0.2 * s.opacity;
      g.beginPath();
      tracePath(g, upper.x, upper.y, px, py, xLog, yLog, false);
      tracePath(g, lower.x.slice().reverse(), lower.y.slice().reverse(), px, py, xLog, yLog, true);
      g.closePath();
      g.fill();
    } else if (s.kind === 'line') {
      g.globalAlpha = s.opacity;
      for (const c of s.curves) {
        g.beginPath();
        tracePath(g, c.x, c.y, px, py, xLog, yLog, false);
        g.stroke();
      }
    } else {
      g.globalAlpha = s.opacity;
      g.beginPath();
      for (const c of s.curves) {
        for (let k = 0; k < c.x.length; k++) {
          if (!drawable(c.x[k], c.y[k], xLog, yLog)) continue;
          const a = px(c.x[k]);
          const b = py(c.y[k]);
          g.moveTo(a + s.radius, b);
          g.arc(a, b, s.radius, 0, 2 * Math.PI);
        }
      }
      g.fill();
    }
  }
  g.setLineDash([]);
  g.restore();

  // Marker lines, then their labels on a halo of the background so they read over the data.
  g.save();
  g.font = fontOf(theme, 12);
  for (const r of chart.rules) {
    const vertical = r.x !== undefined;
    const at = vertical ? px(r.x as number) : py(r.y as number);
    const inside = vertical ? at >= rect.left && at <= rect.left + rect.width : at >= rect.top && at <= rect.top + rect.height;
    if (!Number.isFinite(at) || !inside) continue;
    g.strokeStyle = theme.fg;
    g.globalAlpha = r.faint ? 0.4 : 0.8;
    g.lineWidth = 1.2;
    g.setLineDash([4, 3]);
    g.beginPath();
    if (vertical) {
      g.moveTo(crisp(at, dpr), rect.top);
      g.lineTo(crisp(at, dpr), rect.top + rect.height);
    } else {
      g.moveTo(rect.left, crisp(at, dpr));
      g.lineTo(rect.left + rect.width, crisp(at, dpr));
    }
    g.stroke();
    g.setLineDash([]);
    if (!r.label) continue;
    const w = g.measureText(r.label).width;
    let tx: number;
    let ty: number;
    if (vertical) {
      const leftOfLine = at - 5 - w >= rect.left;
      g.textAlign = leftOfLine ? 'right' : 'left';
      g.textBaseline = 'top';
      tx = leftOfLine ? at - 5 : at + 5;
      ty = rect.top + 4;
    } else {
      g.textAlign = 'right';
      g.textBaseline = 'bottom';
      tx = rect.left + rect.width - 6;
      ty = at - 3 - 14 >= rect.top ? at - 3 : at + 17;
    }
    g.globalAlpha = 1;
    g.lineWidth = 3;
    g.strokeStyle = theme.bg;
    g.strokeText(r.label, tx, ty);
    g.fillStyle = theme.fg;
    g.fillText(r.label, tx, ty);
  }
  g.restore();
  return { rect, height };
}

/** The legend, for a PNG that carries its own key: rows of swatch and label, wrapped to `width`. Returns the height used. */
export function drawLegendRows(g: ChartContext | null, chart: SettledChart, width: number, top: number, theme: Theme): number {
  const items = chart.series.filter((s) => s.label);
  if (!items.length) return 0;
  const left = 16;
  const rowHeight = 20;
  let x = left;
  let y = top + rowHeight / 2;
  const font = fontOf(theme, 12);
  for (const s of items) {
    const label = s.label as string;
    const w = 28 + (g ? (g.font = font, g.measureText(label).width) : label.length * 7);
    if (x > left && x + w > width - 8) {
      x = left;
      y += rowHeight;
    }
    if (g) {
      const color = colorOf(s, theme);
      g.save();
      g.strokeStyle = color;
      g.fillStyle = color;
      g.lineWidth = 2;
      g.setLineDash(s.dash);
      if (s.kind === 'dots') {
        g.beginPath();
        g.arc(x + 9, y, 3.5, 0, 2 * Math.PI);
        g.fill();
      } else if (s.kind === 'band') {
        g.globalAlpha = 0.3;
        g.fillRect(x, y - 5, 20, 10);
      } else {
        g.beginPath();
        g.moveTo(x, y);
        g.lineTo(x + 20, y);
        g.stroke();
      }
      g.restore();
      g.fillStyle = theme.fg;
      g.font = font;
      g.textAlign = 'left';
      g.textBaseline = 'middle';
      g.fillText(label, x + 26, y);
    }
    x += w + 16;
  }
  return y + rowHeight / 2 - top + 6;
}
