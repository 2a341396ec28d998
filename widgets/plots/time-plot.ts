import '../widgets.css';
import type { Simulation } from '../core/simulation.ts';
import type { View } from '../simulator/view.ts';
import { MARGIN } from './axes.ts';
import { context2d, createSurface, pixelRatio, sizeCanvas, type Surface } from './canvas.ts';
import { resolveTheme, watchTheme, type Theme } from './colors.ts';
import { clampEnd, wheelColumns } from './history.ts';
import { Legend } from './legend.ts';
import { planSeries, type SeriesPlan } from './series.ts';
import { compositePlot, drawTimeXAxis, drawTimeYAxis, el, plotBox, WINDOWS, xBandTop, type AxesState } from './time-plot-parts.ts';
import { TimeRenderer, type UpdateResult } from './time-renderer.ts';
import type { Domain, YScaleKind } from './y-map.ts';

export interface TimePlotOptions {
  /** legend entries shown at first, e.g. ['q', 'p']; the others start hidden (default: all) */
  show?: readonly string[];
  /** time units across the plot (default 10) */
  window?: number;
  /** 'symlog' (or 'log') is the paper's m_y(y) = 20 ln(1 + |y|) sgn y (default 'linear') */
  scale?: YScaleKind | 'log';
  /** a fixed y range; the plot then does not autoscale until Refit is pressed */
  domain?: readonly [number, number];
  /** height of the plot area in CSS pixels (default 220) */
  height?: number;
  /** for a batch, the most trajectories drawn per series (default 50) */
  trajectories?: number;
  /** an accessible name for the plot */
  label?: string;
  /** draw this simulation's record at once (standalone use; a simulator widget passes its own) */
  simulation?: Simulation;
}

const FALLBACK_WIDTH = 640;

/**
 * The paper's scrolling graph (§5.1): every component of the state and every
 * derived series (H, I, …) against t. See time-renderer.ts for the drawing
 * and scroll-buffer.ts for the ring of tiles; this file is the DOM around
 * them: legend, scale and window controls, scrolling back through the record
 * by drag, wheel, keys or slider, HiDPI sizing and themes.
 */
export class TimePlot implements View {
  readonly element: HTMLElement;
  private readonly stage: HTMLElement;
  /** grid and y axis */
  private readonly frame: HTMLCanvasElement;
  /** the live trace: the ring's tile canvases, moved like the paper's sprites */
  private readonly tiles: HTMLElement;
  /** a scrolled-back window, drawn from the record */
  private readonly data: HTMLCanvasElement;
  /** the t axis band, redrawn as the window scrolls */
  private readonly xAxis: HTMLCanvasElement;
  private newTiles: HTMLCanvasElement[] = [];
  private readonly tileX = new Float64Array(3).fill(NaN);
  private yAxisKey = '';
  private xAxisKey = '';
  private readonly legendSlot: HTMLElement;
  private readonly scrub: HTMLInputElement;
  private readonly liveButton: HTMLButtonElement;
  private readonly logButton: HTMLButtonElement;
  private readonly status: HTMLElement;
  private readonly renderer: TimeRenderer;
  private readonly cleanups: (() => void)[] = [];
  private simulation: Simulation | null = null;
  private plan: SeriesPlan | null = null;
  private legend: Legend | null = null;
  private visible: boolean[] = [];
  private theme: Theme | null = null;
  private ratio = 1;
  private cssWidth = FALLBACK_WIDTH;
  private readonly cssHeight: number;
  /** right edge (column) of a scrolled-back window; null while following the live trace */
  private historyEnd: number | null = null;
  private playing = true;
  private lastScrub = 0;
  private dragX: number | null = null;
  /** the theme was read while on the page (before that, only fallbacks are known) */
  private themeLive = false;

  constructor(private readonly options: TimePlotOptions = {}) {
    const kind: YScaleKind = options.scale === 'log' || options.scale === 'symlog' ? 'symlog' : 'linear';
    if (options.scale !== undefined && !['linear', 'log', 'symlog'].includes(options.scale)) {
      throw new Error(`timePlot: scale must be 'linear' or 'symlog', not ${JSON.stringify(options.scale)}`);
    }
    const window = options.window ?? 10;
    if (!(window > 0) || !Number.isFinite(window)) throw new Error(`timePlot: window must be a positive number of time units, not ${window}`);
    this.cssHeight = (options.height ?? 220) + MARGIN.top + MARGIN.bottom;
    this.renderer = new TimeRenderer((w, h) => this.makeTile(w, h), window, kind);
    if (options.domain) {
      const [lo, hi] = options.domain;
      if (!(lo < hi)) throw new Error(`timePlot: domain must be [low, high] with low < high, not [${lo}, ${hi}]`);
      this.renderer.autoscale = false;
      this.renderer.setDomain([lo, hi]);
    }
    const label = options.label ?? 'Time plot';
    this.frame = el('canvas', 'pb-frame', { 'aria-hidden': 'true' });
    this.tiles = el('div', 'pb-tiles', { 'aria-hidden': 'true' });
    this.data = el('canvas', 'pb-data-layer', { 'aria-hidden': 'true' });
    this.data.hidden = true;
    this.xAxis = el('canvas', 'pb-xaxis', { 'aria-hidden': 'true' });
    for (const layer of [this.tiles, this.data]) {
      layer.style.left = `${MARGIN.left}px`;
      layer.style.top = `${MARGIN.top}px`;
    }
    this.stage = el('div', 'pb-stage', { tabindex: '0', role: 'group', 'aria-roledescription': 'plot', 'aria-label': `${label}: drag, or use the arrow keys, to scroll back in time` }, this.frame, this.tiles, this.data, this.xAxis);
    this.stage.style.height = `${this.cssHeight}px`;
    this.legendSlot = el('div', 'pb-legend-slot');
    this.logButton = el('button', 'pb-button pb-small', { type: 'button', 'aria-pressed': String(kind === 'symlog'), title: 'Symmetric log scale: 20 ln(1 + |y|) sgn y' }, 'log y');
    const refit = el('button', 'pb-button pb-small', { type: 'button', title: 'Fit the y range to what is shown' }, 'Refit');
    const windows = el('select', 'pb-select', { 'aria-label': 'Time window' });
    for (const w of [...new Set([...WINDOWS, window])].sort((a, b) => a - b)) windows.append(new Option(`${w} t`, String(w), false, w === window));
    const bar = el('div', 'pb-plot-bar', {}, this.legendSlot, el('span', 'pb-spacer'), this.logButton, refit, windows);
    this.scrub = el('input', 'pb-scrub', { type: 'range', min: '0', max: '1', step: 'any', value: '1', 'aria-label': 'Scroll back through the recorded history' });
    this.liveButton = el('button', 'pb-button pb-small', { type: 'button', disabled: '', title: 'Follow the simulation again' }, 'Live');
    this.status = el('span', 'pb-scrub-status', { 'aria-live': 'off' });
    const scrubRow = el('div', 'pb-scrub-row', {}, this.scrub, this.liveButton, this.status);
    this.element = el('figure', 'pb-plot pb-time-plot', { 'data-widget': 'time-plot', 'aria-label': label }, bar, this.stage, scrubRow);

    this.logButton.addEventListener('click', () => this.setKind(this.renderer.kind === 'symlog' ? 'linear' : 'symlog'));
    refit.addEventListener('click', () => this.refit());
    windows.addEventListener('change', () => this.setWindow(Number(windows.value)));
    this.scrub.addEventListener('input', () => this.scrubTo(Number(this.scrub.value)));
    this.liveButton.addEventListener('click', () => this.goLive());
    this.listenPointer();
    this.layout(FALLBACK_WIDTH);
    if (typeof ResizeObserver !== 'undefined') {
      const observer = new ResizeObserver(() => {
        const width = this.stage.clientWidth;
        if (width > 0 && (width !== this.cssWidth || pixelRatio() !== this.ratio)) this.layout(width);
      });
      observer.observe(this.stage);
      this.cleanups.push(() => observer.disconnect());
    }
    this.cleanups.push(watchTheme(() => this.retheme()));
    if (options.simulation) this.reset(options.simulation);
  }

  draw(simulation: Simulation): void {
    if (simulation !== this.simulation) return this.reset(simulation);
    this.present(this.renderer.update(simulation.record));
  }

  reset(simulation: Simulation): void {
    const columns = simulation.record.columns;
    if (!this.simulation || this.simulation.record.columns.join() !== columns.join()) this.plan = this.makePlan(simulation);
    this.simulation = simulation;
    this.historyEnd = null;
    this.renderer.reset(simulation.t0);
    this.applySeries();
    this.present(this.renderer.update(simulation.record), true);
  }

  setPlaying(playing: boolean): void {
    this.playing = playing;
  }

  canvases(): { name: string; canvas: HTMLCanvasElement }[] {
    const theme = this.theme ?? resolveTheme(this.element);
    const legend = (this.plan?.groups ?? []).flatMap((g, i) => (this.visible[i] ? [{ name: g.name, color: theme.series[i % theme.series.length] }] : []));
    const box = plotBox(this.cssWidth, this.cssHeight);
    const r = this.ratio;
    const canvas = compositePlot(this.frame.width, this.frame.height, r, theme, legend, (ctx, top) => {
      ctx.drawImage(this.frame, 0, top);
      const x = Math.round(box.x * r);
      const y = top + Math.round(box.y * r);
      ctx.save();
      ctx.beginPath();
      ctx.rect(x, y, this.data.width, this.data.height);
      ctx.clip();
      if (this.historyEnd === null) this.renderer.composite(ctx, x, y);
      else ctx.drawImage(this.data, x, y);
      ctx.restore();
      ctx.drawImage(this.xAxis, 0, top + Math.round(xBandTop(box) * r));
    });
    return [{ name: 'time plot', canvas }];
  }

  dispose(): void {
    this.cleanups.forEach((f) => f());
    this.cleanups.length = 0;
    this.simulation = null;
  }

  /**
   * The legend and series of a simulation's record. A batch shows only its
   * coordinates at first (each entry is many lines); the rest is a click away.
   */
  private makePlan(simulation: Simulation): SeriesPlan {
    const { columns } = simulation.record;
    const { count, model } = simulation;
    const plan = planSeries(columns, this.options.trajectories ?? 50, undefined);
    const show = this.options.show ?? (count > 1 ? model.names.slice(0, model.dof) : undefined);
    if (this.options.show) planSeries(columns, 1, this.options.show); // throws a one-line error naming an unknown series
    this.visible = plan.groups.map((g) => !show || show.includes(g.name));
    const note = count > plan.drawn ? `${plan.drawn} of ${count} trajectories drawn` : count > 1 ? `${count} trajectories` : undefined;
    this.theme ??= resolveTheme(this.element);
    const theme = this.theme;
    this.legend = new Legend(plan.groups.map((g, i) => ({ name: g.name, color: theme.series[i % theme.series.length], visible: this.visible[i] })), (i, v) => {
      this.visible[i] = v;
      this.applySeries();
      this.refit();
    }, note);
    this.legendSlot.replaceChildren(this.legend.element);
    return plan;
  }

  /** Hands the renderer the visible series with their colours; redraws. */
  private applySeries(): void {
    if (!this.plan) return;
    const theme = (this.theme ??= resolveTheme(this.element));
    const columns: number[] = [];
    const styles: string[] = [];
    this.plan.groups.forEach((g, i) => {
      if (!this.visible[i]) return;
      for (const c of g.columns) {
        columns.push(c);
        styles.push(theme.series[i % theme.series.length]);
      }
    });
    const batch = (this.simulation?.count ?? 1) > 1;
    this.renderer.setSeries(columns, styles, batch ? (this.plan.drawn > 20 ? 0.45 : 0.75) : 1);
    this.redraw();
  }

  private layout(cssWidth: number): void {
    if (this.element.isConnected && !this.themeLive) {
      this.themeLive = true;
      this.theme = resolveTheme(this.element);
    }
    this.cssWidth = cssWidth;
    this.ratio = pixelRatio();
    const box = plotBox(cssWidth, this.cssHeight);
    sizeCanvas(this.frame, cssWidth, this.cssHeight, this.ratio);
    sizeCanvas(this.data, box.width, box.height, this.ratio);
    sizeCanvas(this.xAxis, cssWidth, this.cssHeight - xBandTop(box), this.ratio);
    this.xAxis.style.top = `${xBandTop(box)}px`;
    this.tiles.style.width = `${box.width}px`;
    this.tiles.style.height = `${box.height}px`;
    const batch = (this.simulation?.count ?? 1) > 1;
    this.renderer.resize(this.data.width, this.data.height, this.ratio * (batch ? 0.7 : 1));
    this.tiles.replaceChildren(...this.newTiles);
    this.newTiles = [];
    this.tileX.fill(NaN);
    this.yAxisKey = this.xAxisKey = '';
    this.historyEnd = null;
    if (this.themeLive) this.retheme();
    else this.redraw();
  }

  /** A tile of the scroll ring: a canvas the page moves rather than repaints. */
  private makeTile(width: number, height: number): Surface {
    const canvas = createSurface(width, height) as HTMLCanvasElement;
    canvas.style.width = `${width / this.ratio}px`;
    canvas.style.height = `${height / this.ratio}px`;
    canvas.style.visibility = 'hidden';
    this.newTiles.push(canvas);
    return canvas;
  }

  private redraw(): void {
    if (!this.simulation) return;
    this.renderer.redraw(this.simulation.record);
    this.present('rescaled', true);
  }

  /** Shows the live trace or the scrolled-back window, with its axes. */
  private present(result: UpdateResult, force = false): void {
    const simulation = this.simulation;
    if (!simulation) return;
    const live = this.historyEnd === null;
    this.tiles.style.visibility = live ? '' : 'hidden';
    this.data.hidden = live;
    if (live) {
      if (result !== 'none' || force) {
        this.placeTiles();
        this.drawAxes(this.renderer.left);
      }
    } else if (result === 'rescaled' || force) this.renderHistory();
    if (!this.element.hasAttribute('data-ready')) this.element.setAttribute('data-ready', '');
    const now = typeof performance === 'undefined' ? 0 : performance.now();
    if (force || !live || now - this.lastScrub > 250) {
      this.lastScrub = now;
      this.updateScrub();
    }
  }

  /** Moves each tile canvas to its place in the live view (a transform: no repaint of its pixels). */
  private placeTiles(): void {
    this.renderer.place((slot, surface, x) => {
      if (Object.is(this.tileX[slot], x)) return;
      this.tileX[slot] = x;
      const style = (surface as HTMLCanvasElement).style;
      if (x !== x) style.visibility = 'hidden';
      else {
        style.visibility = '';
        style.transform = `translateX(${x / this.ratio}px)`;
      }
    });
  }

  /** Redraws the y axis when the range changed and the t axis when the window moved. */
  private drawAxes(left: number): void {
    const r = this.renderer;
    const theme = (this.theme ??= resolveTheme(this.element));
    const state: AxesState = { box: plotBox(this.cssWidth, this.cssHeight), kind: r.kind, domain: r.domain, inset: r.inset, t0: r.timeOf(left), t1: r.timeOf(left + r.width) };
    const yKey = `${r.kind} ${r.domain[0]} ${r.domain[1]} ${this.cssWidth} ${this.ratio} ${theme.text}`;
    if (yKey !== this.yAxisKey) {
      this.yAxisKey = yKey;
      const ctx = context2d(this.frame);
      ctx.setTransform(this.ratio, 0, 0, this.ratio, 0, 0);
      drawTimeYAxis(ctx, state, theme, this.cssWidth, this.cssHeight);
    }
    const xKey = `${left} ${r.width} ${r.window} ${yKey}`;
    if (xKey !== this.xAxisKey) {
      this.xAxisKey = xKey;
      const ctx = context2d(this.xAxis);
      ctx.setTransform(this.ratio, 0, 0, this.ratio, 0, -xBandTop(state.box) * this.ratio);
      drawTimeXAxis(ctx, state, theme, this.cssWidth);
    }
  }

  private renderHistory(): void {
    const simulation = this.simulation;
    if (!simulation || this.historyEnd === null) return;
    const r = this.renderer;
    const first = simulation.record.length > 0 ? r.columnOf(simulation.record.time(0)) : 0;
    this.historyEnd = clampEnd(this.historyEnd, first, r.end, r.width);
    const ctx = context2d(this.data);
    ctx.clearRect(0, 0, this.data.width, this.data.height);
    r.renderWindow(ctx, simulation.record, this.historyEnd);
    this.drawAxes(this.historyEnd - r.width);
  }

  /** Scrolls to the window ending at column `end`; at the live end, follows the trace again. */
  private scrollTo(end: number): void {
    const simulation = this.simulation;
    if (!simulation) return;
    const r = this.renderer;
    const first = simulation.record.length > 0 ? r.columnOf(simulation.record.time(0)) : 0;
    const clamped = clampEnd(end, first, r.end, r.width);
    if (clamped >= r.end) return this.goLive();
    this.historyEnd = clamped;
    this.liveButton.disabled = false;
    this.present('none', true);
  }

  private goLive(): void {
    this.historyEnd = null;
    this.liveButton.disabled = true;
    this.present('none', true);
  }

  private scrubTo(time: number): void {
    this.scrollTo(this.renderer.columnOf(time) + 1);
  }

  private updateScrub(): void {
    const simulation = this.simulation;
    if (!simulation || simulation.record.length === 0) return;
    const r = this.renderer;
    const record = simulation.record;
    const first = r.columnOf(record.time(0));
    const lo = r.timeOf(clampEnd(-Infinity, first, r.end, r.width));
    const hi = r.timeOf(r.end);
    const end = this.historyEnd ?? r.end;
    this.scrub.min = String(lo);
    this.scrub.max = String(hi);
    this.scrub.value = String(r.timeOf(end));
    this.scrub.disabled = hi - lo <= 0;
    const t1 = r.timeOf(end);
    const t0 = Math.max(record.time(0), t1 - r.window);
    const text = `t ${fmt(t0)} – ${fmt(t1)}${this.historyEnd === null ? '' : ` of ${fmt(record.time(0))} – ${fmt(record.time(record.length - 1))}`}`;
    this.scrub.setAttribute('aria-valuetext', text);
    this.status.textContent = this.historyEnd === null ? '' : text;
  }

  private setKind(kind: YScaleKind): void {
    this.renderer.setDomain(this.renderer.domain, kind);
    this.logButton.setAttribute('aria-pressed', String(kind === 'symlog'));
    this.refit();
  }

  /** Fits the y range to what is shown now (live window or scrolled-back window). */
  private refit(): void {
    const simulation = this.simulation;
    if (!simulation) return;
    const r = this.renderer;
    const end = this.historyEnd ?? r.end;
    r.fitWindow(simulation.record, r.timeOf(end - r.width), r.timeOf(end));
    r.autoscale = true;
    this.redraw();
  }

  private setWindow(window: number): void {
    const r = this.renderer;
    const t = this.historyEnd === null ? null : r.timeOf(this.historyEnd);
    r.window = window;
    this.redraw();
    if (t !== null) this.scrubTo(t);
  }

  private retheme(): void {
    this.theme = resolveTheme(this.element);
    this.yAxisKey = this.xAxisKey = '';
    this.plan?.groups.forEach((_, i) => this.legend?.recolor(i, this.theme!.series[i % this.theme!.series.length]));
    this.applySeries();
  }

  private listenPointer(): void {
    const stage = this.stage;
    const onWheel = (e: WheelEvent): void => {
      const columns = wheelColumns(e, !this.playing, this.renderer.width, this.ratio);
      if (columns === 0) return;
      e.preventDefault();
      this.scrollTo((this.historyEnd ?? this.renderer.end) + columns);
    };
    stage.addEventListener('wheel', onWheel, { passive: false });
    stage.addEventListener('pointerdown', (e) => {
      if (e.button !== 0) return;
      this.dragX = e.clientX;
      stage.setPointerCapture?.(e.pointerId);
      stage.classList.add('pb-dragging');
    });
    stage.addEventListener('pointermove', (e) => {
      if (this.dragX === null) return;
      const dx = (e.clientX - this.dragX) * this.ratio;
      if (Math.abs(dx) < 1) return;
      this.dragX = e.clientX;
      this.scrollTo((this.historyEnd ?? this.renderer.end) - dx);
    });
    const release = (): void => {
      this.dragX = null;
      stage.classList.remove('pb-dragging');
    };
    stage.addEventListener('pointerup', release);
    stage.addEventListener('pointercancel', release);
    stage.addEventListener('keydown', (e) => {
      const r = this.renderer;
      const end = this.historyEnd ?? r.end;
      const step = { ArrowLeft: -0.1, ArrowRight: 0.1, PageUp: -1, PageDown: 1 }[e.key];
      if (step !== undefined) this.scrollTo(end + step * r.width);
      else if (e.key === 'Home') this.scrollTo(-Infinity);
      else if (e.key === 'End') this.goLive();
      else return;
      e.preventDefault();
    });
  }
}

function fmt(t: number): string {
  return Math.abs(t) >= 1000 ? t.toFixed(0) : t.toPrecision(4).replace(/\.?0+$/, '');
}

/** A time plot View: the scrolling graph of every state component and derived series against t. */
export function timePlot(options: TimePlotOptions = {}): TimePlot {
  return new TimePlot(options);
}

export type { Domain };
