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
import { prefersReducedMotion } from '../controls/dom.ts';
import { downloadBlob, downloadText, onBackground, pngBlob } from '../data/download.ts';
import { pixelRatio, sizeCanvas } from '../plots/canvas.ts';
import { readTheme, sameTheme, watchTheme as onThemeChange, type Theme } from '../plots/theme.ts';
import { chartCsv, chartSummary, namedCurves, tableRows, TABLE_ROWS } from './chart-data.ts';
import { colorOf, drawChart, drawLegendRows, type ChartContext } from './chart-draw.ts';
import { resolveChart, type ChartOptions } from './chart-options.ts';
import { FigureSlots, MotionSense, STILL_AFTER_MS } from './chart-reuse.ts';
import { AXIS_FONT_PX, layoutChart, settleChart, type SettledChart } from './chart-scale.ts';
import { table } from './table.ts';

export type { ChartAxisOptions, ChartColor, ChartCurve, ChartOptions, ChartRuleOptions, ChartSeriesOptions } from './chart-options.ts';

/**
 * Redraws of the charts on the page when the theme changes: the reader's
 * toggle (<html data-theme>) or the system's scheme. A chart joins the set
 * when it is first drawn on the page, and leaves it once it has left the
 * page (its redraw returns false), so charts made again and again by a
 * cell do not pile up, and one never shown never joins.
 */
const redraws = new Set<() => boolean>();

let watching = false;

function watchTheme(redraw: () => boolean): void {
  for (const r of redraws) if (!r()) redraws.delete(r);
  redraws.add(redraw);
  if (watching) return;
  watching = true;
  // One watch of the page for every chart on it, for as long as the page lives.
  onThemeChange(() => redraws.forEach((r) => r() || redraws.delete(r)));
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

/** What a chart's series look like in the legend: when it is unchanged, an update keeps the legend. */
const legendKey = (chart: SettledChart) => JSON.stringify(chart.series.map((s) => [s.label, s.kind, s.dash.length > 0]));

/**
 * The data-table view: a table per curve, built when the reader opens it
 * from the chart as it is then (`current`). `stale()` says the chart
 * changed: an open view is built again, at most once a second, so that a
 * chart updated on every frame does not rebuild its tables on every frame.
 */
function dataView(current: () => SettledChart): { element: HTMLDetailsElement; stale: () => void } {
  const details = document.createElement('details');
  details.className = 'pb-chart-data';
  const summary = document.createElement('summary');
  summary.textContent = 'Data table';
  details.append(summary);
  let builtAt = -Infinity;
  let later: ReturnType<typeof setTimeout> | undefined;
  const build = () => {
    later = undefined;
    builtAt = performance.now();
    details.dataset.built = '';
    const chart = current();
    details.replaceChildren(summary);
    const curves = chart.series.flatMap((s, i) => namedCurves(s, i));
    // Many curves (a beam of trajectories) get fewer rows each; the CSV has every point.
    const limit = Math.max(20, Math.min(TABLE_ROWS, Math.floor(4000 / Math.max(1, curves.length))));
    for (const { name, curve } of curves) {
      const { rows, omitted } = tableRows(curve, limit);
      const note = omitted ? `: ${rows.length} of ${curve.x.length} points, evenly spaced (the CSV has all)` : '';
      details.append(table({ caption: `${name}${note}`, columns: [chart.x.label, chart.y.label], rows }));
    }
  };
  details.addEventListener('toggle', () => {
    if (details.open && details.dataset.built === undefined) build();
  });
  const stale = () => {
    if (details.dataset.built === undefined) return;
    if (!details.open) {
      delete details.dataset.built;
      return;
    }
    later ??= setTimeout(build, Math.max(0, builtAt + 1000 - performance.now()));
  };
  return { element: details, stale };
}

/** The in-place update of each figure chart() made, for the next run of the cell that made it. */
const updaters = new WeakMap<HTMLElement, (settled: SettledChart) => void>();

/** The figures each cell made in its last run, to be updated when it runs again. */
const slots = new FigureSlots<HTMLElement>();

/**
 * A chart's figure. `owner` is the running cell (the cell machinery's
 * signal for it, passed by widgets/library.ts): the figure the same cell
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

function newFigure(first: SettledChart): HTMLElement {
  /** The chart drawn; while paused, `pending` holds the latest one. */
  let settled = first;
  let pending: SettledChart | null = null;
  const figure = document.createElement('figure');
  figure.className = 'pb-chart';
  figure.dataset.widget = 'chart';
  const canvas = document.createElement('canvas');
  canvas.setAttribute('role', 'img');
  canvas.dataset.fontPx = String(AXIS_FONT_PX);
  const description = document.createElement('p');
  // Read by screen readers only; the class that hides it is the plots' (widgets.css).
  description.className = 'pb-chart-description pb-visually-hidden';
  description.id = `pb-chart-description-${++described}`;
  canvas.setAttribute('aria-describedby', description.id);
  let key = legend(settled);
  let keyOf = legendKey(settled);
  const tools = document.createElement('div');
  tools.className = 'pb-chart-tools';
  figure.append(canvas, key, description, tools);
  Object.defineProperty(figure, 'chart', { get: () => settled, enumerable: false });
  /** The name, the description and the legend of the chart now drawn. */
  const describe = () => {
    figure.dataset.label = settled.label;
    canvas.setAttribute('aria-label', settled.label);
    description.textContent = chartSummary(settled);
    const next = legendKey(settled);
    if (next === keyOf) return;
    keyOf = next;
    const fresh = legend(settled);
    key.replaceWith(fresh);
    key = fresh;
  };
  describe();

  let theme: Theme | null = null;
  let drawnWidth = 0;
  /** The chart changed since it was last drawn. */
  let dirty = true;
  /** Whether the figure is in the theme's set (it joins when first drawn on the page). */
  let watched = false;
  /** The theme's redraw: false once the figure has left the page, which takes it out of the set. */
  const onTheme = (): boolean => {
    if (!figure.isConnected) return (watched = false);
    draw();
    return true;
  };
  /** Draws at the figure's width in the page's theme, unless the chart, the width and the theme are as last drawn. */
  const draw = (): void => {
    if (!figure.isConnected) return;
    if (!watched) {
      watched = true;
      watchTheme(onTheme);
    }
    const width = Math.floor(figure.clientWidth);
    if (!(width > 0)) return;
    const next = readTheme(figure);
    if (!dirty && width === drawnWidth && theme && sameTheme(theme, next)) return;
    theme = next;
    drawnWidth = width;
    dirty = false;
    const dpr = pixelRatio();
    const { height } = layoutChart(settled, width);
    sizeCanvas(canvas, width, height, dpr);
    const g = canvas.getContext('2d') as ChartContext | null;
    if (!g) return;
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.clearRect(0, 0, width, height);
    drawChart(g, settled, width, theme, dpr);
    figure.dataset.ready = '';
    const swatches = key.querySelectorAll<HTMLElement>('.pb-chart-swatch');
    settled.series.filter((s) => s.label).forEach((s, i) => swatches[i]?.style.setProperty('--pb-swatch', colorOf(s, theme as Theme)));
  };
  // Draws when the figure is laid out or resized; lets go once it has left the page (an update takes it up again).
  let observed = false;
  const resized = typeof ResizeObserver === 'undefined' ? null : new ResizeObserver(() => {
    if (figure.isConnected) return draw();
    resized?.disconnect();
    observed = false;
  });
  const observe = () => {
    if (!resized || observed) return;
    observed = true;
    resized.observe(figure);
  };
  observe();

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
  const data = dataView(() => settled);
  tools.append(
    data.element,
    button('PNG', 'Download the figure as an image', () => void savePng()),
    button('CSV', 'Download the data of every series as CSV', () => downloadText([chartCsv(settled)], 'text/csv', `${settled.name}.csv`)),
  );

  /** Shows `next` now: described at once, drawn now if on the page, else at the next frame. */
  let frame = 0;
  const show = (next: SettledChart) => {
    settled = next;
    dirty = true;
    describe();
    data.stale();
    observe();
    if (figure.isConnected) return draw();
    // Not on the page at this moment (a cell moving it into new markup): draw once it is back.
    frame ||= requestAnimationFrame(() => {
      frame = 0;
      draw();
    });
  };

  // Motion: Pause (and Play) while the chart is updated frame after frame, and while it is paused.
  const motion = new MotionSense();
  const calm = new MotionSense(1);
  motion.update(performance.now());
  calm.update(performance.now());
  let paused = false;
  const toggle = button('Pause', 'Pause or resume the animation', () => {
    paused = !paused;
    toggle.textContent = paused ? 'Play' : 'Pause';
    if (!paused && pending) show(pending);
    pending = null;
    settle();
  });
  toggle.dataset.motion = '';
  const offered = () => toggle.parentNode !== null;
  let stillTimer: ReturnType<typeof setTimeout> | undefined;
  /** Takes the button away once the chart is still and running (and the reader is not on the button). */
  const settle = () => {
    clearTimeout(stillTimer);
    stillTimer = setTimeout(() => {
      if (!paused && !motion.moving(performance.now()) && document.activeElement !== toggle) toggle.remove();
    }, STILL_AFTER_MS);
  };

  updaters.set(figure, (next) => {
    const now = performance.now();
    const moving = motion.update(now);
    // A reader who asks for reduced motion sees the picture held from the first frame-on-frame update, until Play.
    const hold = calm.update(now) && prefersReducedMotion() && !offered();
    if ((moving || hold) && !offered()) {
      tools.prepend(toggle);
      if (hold) {
        paused = true;
        toggle.textContent = 'Play';
      }
    }
    if (offered()) settle();
    if (paused) pending = next;
    else show(next);
  });
  return figure;
}
