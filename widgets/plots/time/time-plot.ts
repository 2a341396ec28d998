import { h as el } from '../../controls/dom.ts';
import type { Simulation } from '../../../core/index.ts';
import { pixelRatio } from '../canvas.ts';
import { PlotTable, TEXT_INTERVAL_MS } from '../plot-table.ts';
import type { SignedKind } from '../scale.ts';
import { planSeries, type SeriesPlan } from '../series.ts';
import { timePlotHeight } from '../sizes.ts';
import { rangeText, recordTable, rowsOver, show, type TableData } from '../table-data.ts';
import { readTheme, type Theme, watchTheme } from '../theme.ts';
import type { TimeRenderer, UpdateResult } from './time-renderer.ts';
import { addScrollHint, clampEnd, listenScroll, ScrubBar } from './time-scroll.ts';
import { TimeStage, WINDOWS } from './time-stage.ts';
import type { View } from '../view.ts';

export interface TimePlotOptions {
  /** legend entries shown at first, e.g. ['q', 'p']; the others start hidden (default: all; a batch: its coordinates) */
  show?: readonly string[];
  /** time units across the plot (default 10) */
  window?: number;
  /** 'symlog' (or 'log') is the paper's m_y(y) = 20 ln(1 + |y|) sgn y (default 'linear') */
  scale?: SignedKind | 'log';
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

let summaries = 0;

/**
 * The paper's scrolling graph (§5.1): every component of the state and every
 * derived series (H, I, …) against t, with a legend that hides and shows
 * series, linear or symlog y, autoscale and Refit, a choice of time window,
 * and scrolling back through the whole record. Drawing: time-renderer.ts;
 * layers: time-stage.ts; scrolling back: time-scroll.ts.
 */
export class TimePlot implements View {
  readonly element: HTMLElement;
  private readonly stage: TimeStage;
  private readonly scrub: ScrubBar;
  private readonly legendSlot: HTMLElement;
  private readonly logButton: HTMLButtonElement;
  private readonly cleanups: (() => void)[] = [];
  private simulation: Simulation | null = null;
  private plan: SeriesPlan | null = null;
  private legend: Legend | null = null;
  private visible: boolean[] = [];
  private theme: Theme | null = null;
  /** the theme was read while on the page (before that, only fallbacks are known) */
  private themeLive = false;
  /** right edge (column) of a scrolled-back window; null while following the live trace */
  private historyEnd: number | null = null;
  private lastScrub = 0;
  private readonly table: PlotTable;
  private readonly summary: HTMLElement;
  private lastSummary = -Infinity;

  constructor(private readonly options: TimePlotOptions = {}) {
    if (options.scale !== undefined && !['linear', 'log', 'symlog'].includes(options.scale)) {
      throw new Error(`timePlot: scale must be 'linear' or 'symlog', not ${JSON.stringify(options.scale)}`);
    }
    const kind: SignedKind = options.scale === 'log' || options.scale === 'symlog' ? 'symlog' : 'linear';
    const window = options.window ?? 10;
    if (!(window > 0) || !Number.isFinite(window)) throw new Error(`timePlot: window must be a positive number of time units, not ${window}`);
    const label = options.label ?? 'Time plot';
    this.stage = new TimeStage(timePlotHeight(options.height), window, kind, label);
    if (options.domain) {
      const [lo, hi] = options.domain;
      if (!(lo < hi)) throw new Error(`timePlot: domain must be [low, high] with low < high, not [${lo}, ${hi}]`);
      this.renderer.autoscale = false;
      this.renderer.setDomain([lo, hi]);
    }
    // One line that scrolls sideways on a phone (the build reserves one line for it); focusable, so the
    // keyboard can scroll to its note, which is text, not a button.
    this.legendSlot = el('div', 'pb-legend-slot', { tabindex: '0', role: 'group', 'aria-label': 'Legend: series shown, and a note' });
    this.logButton = el('button', 'pb-button pb-small', { type: 'button', 'aria-pressed': String(kind === 'symlog'), title: 'Symmetric log scale: 20 ln(1 + |y|) sgn y' }, 'log y');
    const refit = el('button', 'pb-button pb-small', { type: 'button', title: 'Fit the y range to what is shown' }, 'Refit');
    const windows = el('select', 'pb-select', { 'aria-label': 'Time window' });
    for (const w of [...new Set([...WINDOWS, window])].sort((a, b) => a - b)) windows.append(new Option(`${w} t`, String(w), false, w === window));
    this.table = new PlotTable('time plot', () => this.tableData());
    const bar = el('div', 'pb-plot-bar', {}, this.legendSlot, el('span', 'pb-spacer'), this.logButton, refit, windows);
    this.scrub = new ScrubBar((t) => this.scrollTo(this.renderer.columnOf(t) + 1), () => this.goLive());
    // under the plot, beside Live: the bar above is full on a phone
    this.scrub.element.append(this.table.button);
    // The text alternative: what is plotted, its ranges and the latest values, rewritten a few times a second (not live: it would chatter).
    this.summary = el('p', 'pb-visually-hidden', { id: `pb-time-summary-${++summaries}` });
    this.stage.element.setAttribute('aria-describedby', `${addScrollHint(this.stage.element)} ${this.summary.id}`);
    this.element = el('figure', 'pb-plot pb-time-plot', { 'data-widget': 'time-plot', 'aria-label': label }, bar, this.stage.element, this.summary, this.scrub.element, this.table.element);
    Object.defineProperty(this.element, 'axes', { get: () => [this.stage.axes(this.historyEnd ?? this.renderer.end, this.currentTheme())], configurable: true });

    this.logButton.addEventListener('click', () => this.setKind(this.renderer.kind === 'symlog' ? 'linear' : 'symlog'));
    refit.addEventListener('click', () => this.refit());
    windows.addEventListener('change', () => this.setWindow(Number(windows.value)));
    listenScroll(this.stage.element, {
      end: () => this.historyEnd ?? this.renderer.end,
      width: () => this.renderer.width,
      ratio: () => this.stage.ratio,
      scrollTo: (end) => this.scrollTo(end),
      goLive: () => this.goLive(),
    });
    this.layout(FALLBACK_WIDTH);
    if (typeof ResizeObserver !== 'undefined') {
      const observer = new ResizeObserver(() => {
        const width = this.stage.element.clientWidth;
        if (width > 0 && (width !== this.stage.cssWidth || pixelRatio() !== this.stage.ratio)) this.layout(width);
      });
      observer.observe(this.stage.element);
      this.cleanups.push(() => observer.disconnect());
    }
    this.cleanups.push(watchTheme(() => this.retheme()));
    if (options.simulation) this.reset(options.simulation);
  }

  private get renderer(): TimeRenderer {
    return this.stage.renderer;
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

  canvases(): { name: string; canvas: HTMLCanvasElement }[] {
    const theme = this.currentTheme();
    const legend = (this.plan?.groups ?? []).flatMap((g, i) => (this.visible[i] ? [{ name: g.name, color: this.color(i) }] : []));
    return [{ name: 'time plot', canvas: this.stage.composite(theme, legend, this.historyEnd === null) }];
  }

  dispose(): void {
    this.cleanups.forEach((f) => f());
    this.cleanups.length = 0;
    this.simulation = null;
  }

  private currentTheme(): Theme {
    return (this.theme ??= readTheme(this.element));
  }

  private color(group: number): string {
    const { series } = this.currentTheme();
    return series[group % series.length];
  }

  /**
   * The legend and series of a simulation's record. A batch shows only its
   * coordinates at first (each entry is many lines); the rest is a click away.
   */
  private makePlan(simulation: Simulation): SeriesPlan {
    const { record, count, model } = simulation;
    const plan = planSeries(record, this.options.trajectories ?? 50);
    if (this.options.show) planSeries(record, 1, this.options.show); // throws a one-line error naming an unknown series
    const show = this.options.show ?? (count > 1 ? model.names.slice(0, model.dof) : undefined);
    this.visible = plan.groups.map((g) => !show || show.includes(g.name));
    const note = count > plan.drawn ? `${plan.drawn} of ${count} trajectories drawn` : count > 1 ? `${count} trajectories` : undefined;
    const entries = plan.groups.map((g, i) => ({ name: g.name, color: this.color(i), visible: this.visible[i] }));
    this.legend = new Legend(entries, (i, v) => {
      this.visible[i] = v;
      this.applySeries();
      this.refit();
    }, note);
    this.legendSlot.replaceChildren(this.legend.element);
    return plan;
  }

  /** Hands the renderer the visible series with their colours, and redraws. */
  private applySeries(): void {
    if (!this.plan) return;
    const columns: number[] = [];
    const styles: string[] = [];
    this.plan.groups.forEach((g, i) => {
      if (!this.visible[i]) return;
      for (const c of g.columns) {
        columns.push(c);
        styles.push(this.color(i));
      }
    });
    const batch = (this.simulation?.count ?? 1) > 1;
    this.renderer.lineWidth = this.lineWidth();
    this.renderer.setSeries(columns, styles, batch ? (this.plan.drawn > 20 ? 0.45 : 0.75) : 1);
    this.redraw();
  }

  /** Stroke width in device pixels: 1.5 CSS pixels, thinner for the many lines of a batch. */
  private lineWidth(): number {
    return ((this.simulation?.count ?? 1) > 1 ? 1 : 1.5) * this.stage.ratio;
  }

  private layout(cssWidth: number): void {
    if (this.element.isConnected && !this.themeLive) {
      this.themeLive = true;
      this.theme = null;
    }
    this.stage.ratio = pixelRatio();
    this.stage.layout(cssWidth, this.stage.ratio, this.lineWidth());
    this.historyEnd = null;
    if (this.themeLive) this.retheme();
    else this.redraw();
  }

  private redraw(): void {
    if (!this.simulation) return;
    this.stage.invalidate();
    this.renderer.redraw(this.simulation.record);
    this.present('rescaled', true);
  }

  /** Shows the live trace or the scrolled-back window, and keeps the slider in step. */
  private present(result: UpdateResult, force = false): void {
    const simulation = this.simulation;
    if (!simulation) return;
    const live = this.historyEnd === null;
    if (live && (result !== 'none' || force)) this.stage.showLive(this.currentTheme());
    else if (!live && (result === 'rescaled' || force)) {
      this.historyEnd = this.clamp(this.historyEnd!);
      this.stage.showHistory(simulation.record, this.historyEnd, this.currentTheme());
    }
    if (!this.element.hasAttribute('data-ready')) this.element.setAttribute('data-ready', '');
    const now = performance.now();
    if (force || !live || now - this.lastScrub > 250) {
      this.lastScrub = now;
      this.updateScrub();
    }
    if (force || now - this.lastSummary >= TEXT_INTERVAL_MS) {
      this.lastSummary = now;
      this.describe();
      this.table.refresh(true);
    }
  }

  /** The visible series' record columns, with their names. */
  private shownColumns(): { name: string; index: number }[] {
    const columns = this.simulation?.record.columns ?? [];
    return (this.plan?.groups ?? []).flatMap((g, i) => (this.visible[i] ? g.columns.map((c) => ({ name: columns[c], index: c })) : []));
  }

  /** The time window on show, [t0, t1]. */
  private shownTimes(): [number, number] {
    const r = this.renderer;
    const end = this.historyEnd ?? r.end;
    return [r.timeOf(end - r.width), r.timeOf(end)];
  }

  /** Rewrites the text alternative: the series, the t window, the y range and the values at its right edge. */
  private describe(): void {
    const record = this.simulation?.record;
    const shown = this.shownColumns();
    const names = (this.plan?.groups ?? []).filter((_, i) => this.visible[i]).map((g) => g.name);
    const [t0, t1] = this.shownTimes();
    const r = this.renderer;
    const scale = r.kind === 'symlog' ? 'symmetric log scale' : 'linear scale';
    let now = '';
    if (record && record.length) {
      const [, end] = record.range(-Infinity, t1);
      const row = Math.max(0, end - 1);
      const listed = shown.slice(0, 4).map((c) => `${c.name} = ${show(record.get(row, c.index))}`);
      if (shown.length > 4) listed.push(`and ${shown.length - 4} more`);
      now = listed.length ? ` At t = ${show(record.time(row))}: ${listed.join(', ')}.` : '';
    }
    const what = names.length ? `${names.join(', ')} against t` : 'no series shown';
    const text = `${what}, t from ${show(Math.max(t0, record?.length ? record.time(0) : t0))} to ${show(t1)}; y ${rangeText(r.domain)}, ${scale}.${now}`;
    if (this.summary.textContent !== text) this.summary.textContent = text;
  }

  /** The data-table view: the visible series at evenly spaced times across the window on show. */
  private tableData(): TableData | null {
    const record = this.simulation?.record;
    const shown = this.shownColumns();
    if (!record || record.length === 0 || shown.length === 0) return null;
    const [t0, t1] = this.shownTimes();
    const rows = rowsOver(record, t0, t1);
    return recordTable(record, shown, rows, `${this.options.label ?? 'Time plot'}: values at ${rows.length} times across the window shown`);
  }

  /** A window's right edge kept within the record. */
  private clamp(end: number): number {
    const record = this.simulation?.record;
    const r = this.renderer;
    const first = record && record.length > 0 ? r.columnOf(record.time(0)) : 0;
    return clampEnd(end, first, r.end, r.width);
  }

  /** Scrolls to the window ending at column `end`; at the live end, follows the trace again. */
  private scrollTo(end: number): void {
    if (!this.simulation) return;
    const clamped = this.clamp(end);
    if (clamped >= this.renderer.end) return this.goLive();
    this.historyEnd = clamped;
    this.present('none', true);
  }

  private goLive(): void {
    this.historyEnd = null;
    this.present('none', true);
  }

  private updateScrub(): void {
    const record = this.simulation?.record;
    if (!record || record.length === 0) return;
    const r = this.renderer;
    const end = this.historyEnd ?? r.end;
    const t1 = r.timeOf(end);
    const first = record.time(0);
    const lo = r.timeOf(this.clamp(-Infinity));
    this.scrub.show(lo, r.timeOf(r.end), Math.max(first, t1 - r.window), t1, first, record.time(record.length - 1), this.historyEnd === null);
  }

  private setKind(kind: SignedKind): void {
    this.renderer.setDomain(this.renderer.domain, kind);
    this.logButton.setAttribute('aria-pressed', String(kind === 'symlog'));
    this.refit();
  }

  /** Fits the y range to what is shown now (live window or scrolled-back window); autoscale resumes. */
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
    if (t !== null) this.scrollTo(r.columnOf(t) + 1);
  }

  private retheme(): void {
    this.theme = readTheme(this.element);
    this.plan?.groups.forEach((_, i) => this.legend?.recolor(i, this.color(i)));
    this.applySeries();
  }
}

/** A time plot View: the scrolling graph of every state component and derived series against t. */
export function timePlot(options: TimePlotOptions = {}): TimePlot {
  return new TimePlot(options);
}

/**
 * A legend of toggle buttons, one per series: a colour swatch and the name.
 * Clicking (or Enter/Space on) an entry hides or shows its series; the
 * pressed state is exposed as aria-pressed.
 */
export interface LegendEntry {
  name: string;
  color: string;
  visible: boolean;
}

export class Legend {
  readonly element: HTMLElement;
  private readonly buttons: HTMLButtonElement[] = [];

  constructor(
    entries: readonly LegendEntry[],
    private readonly onToggle: (index: number, visible: boolean) => void,
    note?: string,
  ) {
    this.element = document.createElement('div');
    this.element.className = 'pb-legend';
    this.element.setAttribute('role', 'group');
    this.element.setAttribute('aria-label', 'Series (click to hide or show)');
    entries.forEach((entry, i) => {
      const button = document.createElement('button');
      button.type = 'button';
      button.className = 'pb-legend-entry';
      const swatch = document.createElement('span');
      swatch.className = 'pb-swatch';
      swatch.setAttribute('aria-hidden', 'true');
      const label = document.createElement('span');
      label.textContent = entry.name;
      button.append(swatch, label);
      button.title = `Hide or show ${entry.name}`;
      button.addEventListener('click', () => {
        const visible = button.getAttribute('aria-pressed') !== 'true';
        this.set(i, visible);
        this.onToggle(i, visible);
      });
      this.buttons.push(button);
      this.element.append(button);
      this.recolor(i, entry.color);
      this.set(i, entry.visible);
    });
    if (note) {
      const span = document.createElement('span');
      span.className = 'pb-legend-note';
      span.textContent = note;
      this.element.append(span);
    }
  }

  set(index: number, visible: boolean): void {
    this.buttons[index]?.setAttribute('aria-pressed', String(visible));
  }

  recolor(index: number, color: string): void {
    const swatch = this.buttons[index]?.querySelector<HTMLElement>('.pb-swatch');
    if (swatch) swatch.style.background = color;
  }
}
