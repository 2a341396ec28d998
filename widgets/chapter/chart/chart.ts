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
 *
 * A cell that runs again (a generator upstream yields, an upstream cell is
 * edited) and calls chart() again gets the figure it showed, updated in
 * place (chart-reuse.ts): no new canvas, listeners or theme watch per frame.
 * A figure updated frame after frame offers Pause, and waits for Play when
 * the reader's system asks for reduced motion, as the simulators do.
 */
import { downloadText } from '../../exports/download.ts';
import { chartCsv } from './chart-data.ts';
import { ChartFigure } from './chart-figure.ts';
import { resolveChart, type ChartOptions } from './chart-options.ts';
import { PauseControl } from './chart-pause.ts';
import { FigureSlots } from './chart-reuse.ts';
import { settleChart, type SettledChart } from './chart-scale.ts';
import { button, dataView } from './chart-tools.ts';

export type { ChartAxisOptions, ChartColor, ChartCurve, ChartOptions, ChartRuleOptions, ChartSeriesOptions } from './chart-options.ts';

/** The in-place update of each figure chart() made, for the next run of the cell that made it. */
const updaters = new WeakMap<HTMLElement, (settled: SettledChart) => void>();

/** The figures each cell made in its last run, to be updated when it runs again. */
const slots = new FigureSlots<HTMLElement>();

/**
 * A chart's figure. `owner` is the running cell (the cell machinery's
 * signal for it, passed by widgets/catalogue.ts): the figure the same cell
 * made at the same place in its previous run is updated in place and
 * returned instead of a new one. Without an owner a new figure is made.
 */
export function chart(options: ChartOptions, owner?: object): HTMLElement {
  const settled = settleChart(resolveChart(options));
  const { previous, keep } = slots.take(owner);
  const update = previous && updaters.get(previous);
  if (previous && update) {
    update(settled);
    return previous;
  }
  const figure = newFigure(settled);
  keep(figure);
  return figure;
}

/**
 * A new figure showing `first`: the canvas with its legend and description
 * (chart-figure.ts), the data table and the downloads under it, and Pause
 * for updates that come frame after frame (chart-pause.ts), through which
 * the next runs of its cell update it.
 */
function newFigure(first: SettledChart): HTMLElement {
  const figure = new ChartFigure(first);
  const data = dataView(() => figure.chart);
  figure.tools.append(
    data.element,
    button('PNG', 'Download the figure as an image', () => void figure.savePng()),
    button('CSV', 'Download the data of every series as CSV', () => downloadText([chartCsv(figure.chart)], 'text/csv', `${figure.chart.name}.csv`)),
  );
  const pause = new PauseControl<SettledChart>(figure.tools, (next) => {
    figure.show(next);
    data.stale();
  });
  updaters.set(figure.element, (next) => pause.update(next));
  return figure.element;
}
