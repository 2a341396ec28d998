/**
 * chart({label, x, y, series, rules}): a chapter's figure, drawn on canvas
 * by the plot foundation, so that a cell holds only the physics it plots.
 *
 * - Series of measured points (dots or lines), families of lines, formula
 *   curves sampled across the axis, and shaded bands; linear or log axes
 *   with d3's ticks; marker lines with labels.
 * - Follows the page's theme (its CSS variables) and the column's width;
 *   axis text stays at 11 CSS pixels or more at any width.
 * - A legend in text, a description of what is drawn for those who cannot
 *   see it (the canvas's accessible description, updated with the chart), a
 *   data-table view reachable by keyboard, and PNG and CSV downloads.
 *
 * The element carries the settled chart as `.chart` (series with their
 * sampled curves, domains), for tests and for cells that read it.
 */
import { downloadBlob, downloadText, onBackground, pngBlob } from '../data/download.ts';
import { pixelRatio, sizeCanvas } from '../plots/canvas.ts';
import { readTheme, sameTheme, type Theme } from '../plots/view-theme.ts';
import { chartCsv, chartSummary, namedCurves, tableRows, TABLE_ROWS } from './chart-data.ts';
import { colorOf, drawChart, drawLegendRows, type ChartContext } from './chart-draw.ts';
import { resolveChart, type ChartOptions } from './chart-options.ts';
import { AXIS_FONT_PX, layoutChart, settleChart, type SettledChart } from './chart-scale.ts';
import { table } from './table.ts';

export type { ChartAxisOptions, ChartColor, ChartCurve, ChartOptions, ChartRuleOptions, ChartSeriesOptions } from './chart-options.ts';

/**
 * Redraws of the charts on the page when the theme changes: the reader's
 * toggle (<html data-theme>) or the system's scheme. A chart leaves the set
 * once it has left the page (its redraw returns false), so charts made
 * again and again by a cell do not pile up.
 */
const redraws = new Set<() => boolean>();
let watching = false;

function watchTheme(redraw: () => boolean): void {
  for (const r of redraws) if (!r()) redraws.delete(r);
  redraws.add(redraw);
  if (watching || typeof window === 'undefined') return;
  watching = true;
  const all = () => redraws.forEach((r) => r() || redraws.delete(r));
  window.matchMedia?.('(prefers-color-scheme: dark)').addEventListener?.('change', all);
  new MutationObserver(all).observe(document.documentElement, { attributes: true, attributeFilter: ['data-theme', 'class', 'style'] });
}

let described = 0;

function button(text: string, title: string, onClick: () => void): HTMLButtonElement {
  const b = document.createElement('button');
  b.type = 'button';
  b.className = 'pb-chart-button';
  b.textContent = text;
  b.title = title;
  b.addEventListener('click', onClick);
  return b;
}

/** The legend as text below the canvas: it wraps on a phone instead of being cut. */
function legend(chart: SettledChart): HTMLUListElement {
  const list = document.createElement('ul');
  list.className = 'pb-chart-legend';
  for (const s of chart.series) {
    if (!s.label) continue;
    const item = document.createElement('li');
    const swatch = document.createElement('span');
    swatch.className = 'pb-chart-swatch';
    swatch.dataset.kind = s.kind;
    if (s.dash.length) swatch.dataset.dashed = '';
    swatch.setAttribute('aria-hidden', 'true');
    item.append(swatch, s.label);
    list.append(item);
  }
  return list;
}

/** The data-table view: a table per curve, built when the reader opens it. */
function dataView(chart: SettledChart): HTMLDetailsElement {
  const details = document.createElement('details');
  details.className = 'pb-chart-data';
  const summary = document.createElement('summary');
  summary.textContent = 'Data table';
  details.append(summary);
  details.addEventListener('toggle', () => {
    if (!details.open || details.dataset.built !== undefined) return;
    details.dataset.built = '';
    const curves = chart.series.flatMap((s, i) => namedCurves(s, i));
    // Many curves (a beam of trajectories) get fewer rows each; the CSV has every point.
    const limit = Math.max(20, Math.min(TABLE_ROWS, Math.floor(4000 / Math.max(1, curves.length))));
    for (const { name, curve } of curves) {
      const { rows, omitted } = tableRows(curve, limit);
      const note = omitted ? `: ${rows.length} of ${curve.x.length} points, evenly spaced (the CSV has all)` : '';
      details.append(table({ caption: `${name}${note}`, columns: [chart.x.label, chart.y.label], rows }));
    }
  });
  return details;
}

export function chart(options: ChartOptions): HTMLElement {
  const settled = settleChart(resolveChart(options));
  const figure = document.createElement('figure');
  figure.className = 'pb-chart';
  figure.dataset.widget = 'chart';
  figure.dataset.label = settled.label;
  const canvas = document.createElement('canvas');
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', settled.label);
  canvas.dataset.fontPx = String(AXIS_FONT_PX);
  const description = document.createElement('p');
  // Read by screen readers only; the class that hides it is the plots' (widgets.css).
  description.className = 'pb-chart-description pb-visually-hidden';
  description.id = `pb-chart-description-${++described}`;
  description.textContent = chartSummary(settled);
  canvas.setAttribute('aria-describedby', description.id);
  const key = legend(settled);
  const tools = document.createElement('div');
  tools.className = 'pb-chart-tools';
  figure.append(canvas, key, description, tools);
  Object.defineProperty(figure, 'chart', { value: settled, enumerable: false });

  let theme: Theme | null = null;
  let drawnWidth = 0;
  let seen = false;
  /** Draws at the figure's width in the page's theme, unless both are as last drawn; false once the chart has left the page. */
  const draw = (): boolean => {
    if (figure.isConnected) seen = true;
    else return !seen;
    const width = Math.floor(figure.clientWidth);
    if (!(width > 0)) return true;
    const next = readTheme(figure);
    if (width === drawnWidth && theme && sameTheme(theme, next)) return true;
    theme = next;
    drawnWidth = width;
    const dpr = pixelRatio();
    const { height } = layoutChart(settled, width);
    sizeCanvas(canvas, width, height, dpr);
    const g = canvas.getContext('2d') as ChartContext | null;
    if (!g) return true;
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.clearRect(0, 0, width, height);
    drawChart(g, settled, width, theme, dpr);
    figure.dataset.ready = '';
    const swatches = key.querySelectorAll<HTMLElement>('.pb-chart-swatch');
    settled.series.filter((s) => s.label).forEach((s, i) => swatches[i]?.style.setProperty('--pb-swatch', colorOf(s, theme as Theme)));
    return true;
  };
  watchTheme(draw);
  if (typeof ResizeObserver !== 'undefined') {
    const resized = new ResizeObserver(() => draw() || resized.disconnect());
    resized.observe(figure);
  }

  /** The canvas with its legend under it, on the theme's background, as a PNG. */
  const savePng = async () => {
    const t = theme ?? readTheme(figure);
    const dpr = pixelRatio();
    const width = drawnWidth || 640;
    const measure = document.createElement('canvas').getContext('2d') as ChartContext | null;
    const extra = drawLegendRows(measure, settled, width, 0, t);
    const out = document.createElement('canvas');
    const h = canvas.height / dpr;
    sizeCanvas(out, width, h + extra, dpr);
    const g = out.getContext('2d') as ChartContext | null;
    if (!g) return;
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.drawImage(canvas, 0, 0, width, h);
    drawLegendRows(g, settled, width, h, t);
    downloadBlob(await pngBlob(onBackground(out, t.bg)), `${settled.name}.png`);
  };
  tools.append(
    dataView(settled),
    button('PNG', 'Download the figure as an image', () => void savePng()),
    button('CSV', 'Download the data of every series as CSV', () => downloadText([chartCsv(settled)], 'text/csv', `${settled.name}.csv`)),
  );
  return figure;
}
