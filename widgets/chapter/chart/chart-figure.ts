/**
 * A chart's figure on the page: the canvas, its description for those who
 * cannot see it, the legend as text, and a row for the tools; drawn at the
 * column's width in the page's theme, again when either changes, and only
 * then (chart.ts makes it, and updates it in place when its cell runs again).
 */
import { downloadBlob, onBackground, pngBlob } from '../../exports/download.ts';
import { pixelRatio, scaledContext } from '../../plots/canvas.ts';
import { readTheme, sameTheme, watchTheme as onThemeChange, type Theme } from '../../plots/theme.ts';
import { chartSummary } from './chart-data.ts';
import { colorOf, drawChart, drawLegendRows, type ChartContext } from './chart-draw.ts';
import { AXIS_FONT_PX, layoutChart, type SettledChart } from './chart-scale.ts';

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

export class ChartFigure {
  readonly element: HTMLElement;
  /** the row under the legend where the figure's tools go */
  readonly tools: HTMLDivElement;
  readonly #canvas: HTMLCanvasElement;
  readonly #description: HTMLParagraphElement;
  /** The chart drawn (or about to be). */
  #settled: SettledChart;
  #key: HTMLUListElement;
  #keyOf: string;
  /** The theme and width last drawn in. */
  #theme: Theme | null = null;
  #drawnWidth = 0;
  /** The chart changed since it was last drawn. */
  #dirty = true;
  /** Whether the figure is in the theme's set (it joins when first drawn on the page). */
  #watched = false;
  /** Whether the figure's size is observed: from its making, until it is found off the page. */
  #observed = false;
  readonly #resized: ResizeObserver | null;
  /**
   * Whether the figure is near the view (or that cannot be known). A chart
   * a generator updates every frame is drawn only there: scrolled away, each
   * update is described and kept, and the last one drawn when the figure
   * comes back, instead of a layout and a canvas drawn sixty times a second
   * for nobody (a tenth of a phone's main thread on the introduction).
   */
  #nearView = true;
  readonly #seen: IntersectionObserver | null;
  /** a frame asked for to draw a chart shown while the figure was off the page */
  #frame = 0;

  constructor(first: SettledChart) {
    this.#settled = first;
    this.element = document.createElement('figure');
    this.element.className = 'pb-chart';
    this.element.dataset.widget = 'chart';
    this.#canvas = document.createElement('canvas');
    this.#canvas.setAttribute('role', 'img');
    this.#canvas.dataset.fontPx = String(AXIS_FONT_PX);
    this.#description = document.createElement('p');
    // Read by screen readers only; the class that hides it is the plots' (widgets.css).
    this.#description.className = 'pb-chart-description pb-visually-hidden';
    this.#description.id = `pb-chart-description-${++described}`;
    this.#canvas.setAttribute('aria-describedby', this.#description.id);
    this.#key = legend(first);
    this.#keyOf = legendKey(first);
    this.tools = document.createElement('div');
    this.tools.className = 'pb-chart-tools';
    this.element.append(this.#canvas, this.#key, this.#description, this.tools);
    Object.defineProperty(this.element, 'chart', { get: () => this.#settled, enumerable: false });
    this.#describe();
    // Draws when the figure is laid out or resized; lets go once it has left the page (an update takes it up again).
    this.#resized = typeof ResizeObserver === 'undefined' ? null : new ResizeObserver(() => this.#onResize());
    this.#seen =
      typeof IntersectionObserver === 'undefined'
        ? null
        : new IntersectionObserver((entries) => this.#onSeen(entries[entries.length - 1].isIntersecting), { rootMargin: '200px 0px' });
    this.#observe();
  }

  /** The chart now shown. */
  get chart(): SettledChart {
    return this.#settled;
  }

  /** Shows `next` now: described at once, drawn now if on the page, else at the next frame. */
  show(next: SettledChart): void {
    this.#settled = next;
    this.#dirty = true;
    this.#describe();
    this.#observe();
    if (this.element.isConnected) return this.#nearView ? this.draw() : undefined;
    // Not on the page at this moment (a cell moving it into new markup): draw once it is back.
    this.#frame ||= requestAnimationFrame(() => {
      this.#frame = 0;
      this.draw();
    });
  }

  /** Draws at the figure's width in the page's theme, unless the chart, the width and the theme are as last drawn. */
  draw(): void {
    if (!this.element.isConnected) return;
    if (!this.#watched) {
      this.#watched = true;
      watchTheme(this.#onTheme);
    }
    const width = Math.floor(this.element.clientWidth);
    if (!(width > 0)) return;
    const theme = readTheme(this.element);
    if (!this.#dirty && width === this.#drawnWidth && this.#theme && sameTheme(this.#theme, theme)) return;
    this.#theme = theme;
    this.#drawnWidth = width;
    this.#dirty = false;
    this.#paint(width, theme);
  }

  /** The canvas with its legend under it, on the theme's background, as a PNG download. */
  async savePng(): Promise<void> {
    // The canvas may hold an older chart than the one shown in words, if updates came while it was away.
    this.draw();
    const t = this.#theme ?? readTheme(this.element);
    const dpr = pixelRatio();
    const width = this.#drawnWidth || 640;
    // The legend is text on the page; in an image it is drawn under the canvas, in rows measured first.
    const measure = document.createElement('canvas').getContext('2d') as ChartContext | null;
    const extra = drawLegendRows(measure, this.#settled, width, 0, t);
    const out = document.createElement('canvas');
    const h = this.#canvas.height / dpr;
    const g = scaledContext(out, width, h + extra, dpr) as ChartContext | null;
    if (!g) return;
    g.drawImage(this.#canvas, 0, 0, width, h);
    drawLegendRows(g, this.#settled, width, h, t);
    downloadBlob(await pngBlob(onBackground(out, t.bg)), `${this.#settled.name}.png`);
  }

  /** The chart on the canvas, and the legend's swatches in the colours drawn. */
  #paint(width: number, theme: Theme): void {
    const dpr = pixelRatio();
    const { height } = layoutChart(this.#settled, width);
    const g = scaledContext(this.#canvas, width, height, dpr) as ChartContext | null;
    if (!g) return;
    g.clearRect(0, 0, width, height);
    drawChart(g, this.#settled, width, theme, dpr);
    this.element.dataset.ready = '';
    const swatches = this.#key.querySelectorAll<HTMLElement>('.pb-chart-swatch');
    this.#settled.series.filter((s) => s.label).forEach((s, i) => swatches[i]?.style.setProperty('--pb-swatch', colorOf(s, theme)));
  }

  /** The name, the description and the legend of the chart now drawn; the legend is built again only when its entries change. */
  #describe(): void {
    const settled = this.#settled;
    this.element.dataset.label = settled.label;
    this.#canvas.setAttribute('aria-label', settled.label);
    this.#description.textContent = chartSummary(settled);
    const next = legendKey(settled);
    if (next === this.#keyOf) return;
    this.#keyOf = next;
    const fresh = legend(settled);
    this.#key.replaceWith(fresh);
    this.#key = fresh;
  }

  /** The theme's redraw: false once the figure has left the page, which takes it out of the set. */
  readonly #onTheme = (): boolean => {
    if (!this.element.isConnected) return (this.#watched = false);
    this.draw();
    return true;
  };

  #onResize(): void {
    if (this.element.isConnected) return this.draw();
    this.#resized?.disconnect();
    this.#seen?.disconnect();
    this.#observed = false;
  }

  /** The figure came near the view or left it: back near it, the chart shown is drawn if it changed meanwhile. */
  #onSeen(near: boolean): void {
    this.#nearView = near;
    if (near) this.draw();
  }

  #observe(): void {
    if (!this.#resized || this.#observed) return;
    this.#observed = true;
    this.#resized.observe(this.element);
    this.#seen?.observe(this.element);
  }
}
