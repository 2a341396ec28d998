import type { Simulation } from '../../../core/index.ts';
import { unseen, type View } from '../view.ts';
import type { Mapping } from '../scale.ts';
import { drawAxes, drawLegend, leftMarginFor, MARGIN, panelLabels, type AxisReadout } from '../axes.ts';
import { defaultLook, drawDots, fadeLayer, rescaleImage, strokeRows, type LineStyle } from './plane-draw.ts';
import { includeRows, liftPens } from '../trace.ts';
import { ageBuckets, Fader, FADE_FRAMES, parseTrail, type TrailOption } from './trail.ts';
import { growPanel, makePanel, panelRect, placePanel, settlePanel, type Panel, type PanelSpec } from './plane-panels.ts';
import { gridColumns } from '../sizes.ts';
import { ViewFrame, type Layer } from '../view-frame.ts';
import { seriesColor } from '../theme.ts';
import { PlotTable, TEXT_INTERVAL_MS } from '../plot-table.ts';
import { latestValues, rangeText, recordTable, rowsOver, show, TABLE_ROWS, type TableData } from '../table-data.ts';

/** Options every plane plot (trajectory, phase portrait) shares. */
export interface PlaneStyle {
  /** 'fade' (the default of a trajectory), 'full', 'none', or the trail's length in time units */
  trail?: TrailOption;
  /** colours per colour group (body, pair), overriding the theme's series */
  colors?: readonly string[];
  /** line width in CSS px; default 1.5, or 1 for a batch */
  lineWidth?: number;
  /** the line's opacity; default 1, or less for a large batch so that density shows */
  lineOpacity?: number;
  /** radius of the current-state dot in CSS px; 0 for none */
  dot?: number;
  /** a step between samples longer than this fraction of the shown extent (in x or y) is a jump, drawn as a break in the line; default 0.25 */
  jump?: number;
  /** canvas height in CSS px, or a function of the width */
  height?: number | ((width: number) => number);
}

export interface PlaneDefinition extends PlaneStyle {
  kind: string;
  label: string;
  /** the panels for a simulation; throws a message to show when the simulation does not fit */
  resolve(simulation: Simulation): PanelSpec[];
  /** height of a panel for a given panel width */
  panelHeight(width: number): number;
}

/** Age buckets a fading trail is redrawn in. */
const BUCKETS = 24;
/** A trail redraw slower than this (ms of drawing calls) is avoided where a cheaper way exists. */
const EXPENSIVE_REDRAW_MS = 6;
/** Frames without growth after which an auto extent left loose by growing is tightened. */
const SETTLE_FRAMES = 45;

/**
 * The engine of the plane plots: tracks of record columns drawn as lines,
 * incrementally, into an offscreen trail layer that fades; axes on a base
 * layer redrawn only on layout; dots at the current state. When an auto
 * extent grows, or the size or theme changes, the trail is redrawn from the
 * record with each age bucket at its faded opacity.
 */
export class PlaneView implements View {
  readonly frame: ViewFrame;
  private readonly base: Layer;
  private readonly trail: Layer;
  /** a copy of the trail while it is rescaled, made when first needed */
  private scratch: Layer | null = null;
  private readonly mode;
  private panels: Panel[] = [];
  private simulation: Simulation | null = null;
  private columns: readonly string[] = [];
  private seen = 0;
  private lastTime = NaN;
  /** sim time per drawn frame (moving average), to turn a 'fade' trail's frames into time */
  private frameTime = 0;
  private fader: Fader;
  /** trail units since the trail was last redrawn from the record */
  private sinceRedraw = 0;
  private redrawCost = 0;
  private dirty = true;
  /** frames drawn since an extent last grew */
  private quiet = 0;
  /** each panel's axes as last drawn */
  axes: { x: AxisReadout; y: AxisReadout }[] = [];
  private readonly table: PlotTable;
  /** when the text alternative was last written */
  private described = -Infinity;

  constructor(private readonly definition: PlaneDefinition) {
    const { height } = definition;
    this.frame = new ViewFrame({
      kind: definition.kind,
      label: definition.label,
      height: (width) => (typeof height === 'number' ? height : height ? height(width) : this.naturalHeight(width)),
    });
    this.base = this.frame.layer();
    this.trail = this.frame.layer();
    this.mode = parseTrail(definition.trail);
    this.fader = new Fader(this.mode.length);
    this.frame.onChange = () => {
      if (!this.simulation) return;
      this.relayout();
      this.compose();
    };
    this.table = this.frame.addTable(definition.kind === 'trajectory' ? 'trajectory' : 'phase portrait', () => this.tableData());
    Object.defineProperty(this.frame.element, 'axes', { get: () => this.axes, configurable: true });
  }

  get element(): HTMLElement {
    return this.frame.element;
  }

  draw(simulation: Simulation): void {
    const record = simulation.record;
    if (simulation !== this.simulation || record.columns !== this.columns || record.dropped + record.length < this.seen) {
      this.reset(simulation);
    }
    // a new size or pixel ratio redraws everything from the record, new rows included
    const redrawn = this.frame.measure();
    if (redrawn) this.relayout();
    if (this.panels.length === 0) {
      if (this.dirty) this.compose();
      return;
    }
    const { from, to, total } = unseen(simulation, this.seen);
    if (from < to) {
      if (this.seen < record.dropped) for (const p of this.panels) liftPens(p.pens);
      const grew = this.measureNew(from, to);
      this.seen = total;
      const now = record.time(to - 1);
      const elapsed = Number.isFinite(this.lastTime) ? now - this.lastTime : 0;
      if (elapsed > 0) this.frameTime = this.frameTime > 0 ? 0.9 * this.frameTime + 0.1 * elapsed : elapsed;
      this.lastTime = now;
      this.quiet = grew ? 0 : this.quiet + 1;
      const step = this.mode.kind === 'frames' ? 1 : elapsed;
      if (grew) {
        if (this.relayout(true)) this.advance(from, to, step);
      } else if (redrawn) {
        this.dirty = true;
      } else if (this.quiet === SETTLE_FRAMES && this.holdsTrail() && this.panels.map(settlePanel).some(Boolean)) this.relayout();
      else this.advance(from, to, step);
    }
    if (this.dirty) this.compose();
  }

  reset(simulation: Simulation): void {
    this.simulation = simulation;
    this.columns = simulation.record.columns;
    this.seen = simulation.record.dropped + simulation.record.length;
    this.lastTime = simulation.record.length ? simulation.record.time(simulation.record.length - 1) : NaN;
    this.frameTime = 0;
    this.quiet = 0;
    try {
      this.panels = this.definition.resolve(simulation).map(makePanel);
      this.frame.say(null);
    } catch (error) {
      this.panels = [];
      this.frame.say(error instanceof Error ? error.message : String(error));
    }
    if (simulation.record.length) this.measureNew(0, simulation.record.length);
    this.frame.measure(true);
    this.relayout();
  }

  canvases(): { name: string; canvas: HTMLCanvasElement }[] {
    return [{ name: this.definition.kind, canvas: this.frame.canvas }];
  }

  dispose(): void {
    this.frame.dispose();
    this.panels = [];
    this.simulation = null;
  }

  private naturalHeight(width: number): number {
    if (this.panels.length === 0) return 120; // room for the message saying why there is nothing to draw
    const count = this.panels.length;
    const columns = gridColumns(count, width);
    return Math.ceil(count / columns) * this.definition.panelHeight(width / columns);
  }

  /** Collects the extent of rows [from, to) per panel and grows auto extents; returns whether any grew. */
  private measureNew(from: number, to: number): boolean {
    const record = this.simulation!.record;
    let grew = false;
    for (const panel of this.panels) {
      const e = panel.fresh;
      e.x0 = e.y0 = Infinity;
      e.x1 = e.y1 = -Infinity;
      for (const s of record.slices(from, to)) {
        for (let k = 0; k < panel.xs.length; k++) includeRows(e, s.data, record.width, s.from, s.to, panel.xs[k], panel.ys[k]);
      }
      if (growPanel(panel)) grew = true;
    }
    return grew;
  }

  /**
   * Places panels and redraws the axes and the whole trail: from the record
   * when it still holds the trail, otherwise (with `rescale`, after an
   * extent grew) by scaling the old trail image, so that a record too short
   * for the trail does not erase it. Returns whether it rescaled, in which
   * case the newest rows are still to be drawn.
   */
  private relayout(rescale = false): boolean {
    const { frame } = this;
    const count = this.panels.length;
    const before = this.panels.map((p) => ({ mx: p.mx, my: p.my }));
    const g = this.base.context;
    this.panels.forEach((p, i) => {
      placePanel(p, panelRect(i, count, frame.width, frame.height));
      // y labels wider than the default margin (large or tiny numbers) get the room they need
      const margin = leftMarginFor(g, panelLabels(g, p.rect, p.mx, p.my, frame.theme).y, frame.theme);
      if (margin > MARGIN.left) placePanel(p, panelRect(i, count, frame.width, frame.height, margin));
    });
    g.clearRect(0, 0, frame.width, frame.height);
    this.axes = this.panels.map((panel) => {
      const { spec } = panel;
      const drawn = drawAxes(g, panel.rect, panel.mx, panel.my, frame.theme, spec, frame.dpr);
      const items = spec.legend.map((l) => ({ label: l.label, color: this.color(l.group) }));
      drawLegend(g, panel.rect, items, frame.theme, spec.title);
      return drawn;
    });
    const linear = this.panels.every((p) => p.mx.kind === 'linear' && p.my.kind === 'linear');
    // Rescale the old image, rather than redraw from the record, when the record no longer holds the
    // trail, or when a fading trail is costly to redraw (a large batch): a growing extent must not stall
    // a frame, and a faded image's rescaling blur soon fades away (a full trail keeps the exact redraw).
    const costly = this.mode.kind !== 'full' && this.redrawCost >= EXPENSIVE_REDRAW_MS;
    const rescaled = rescale && linear && (!this.holdsTrail() || costly);
    if (rescaled) this.rescaleTrail(before);
    else this.redrawTrail();
    this.dirty = true;
    return rescaled;
  }

  /** Whether the record still reaches back to the oldest part of the trail. */
  private holdsTrail(): boolean {
    const record = this.simulation?.record;
    if (!record || record.dropped === 0 || this.mode.kind === 'none') return true;
    if (this.mode.kind === 'full') return false;
    const length = this.mode.kind === 'frames' ? FADE_FRAMES * this.frameTime : this.mode.length;
    return record.length > 0 && record.time(0) <= record.time(record.length - 1) - length;
  }

  /** Redraws the trail image under each panel's new mapping (linear axes), and moves the pens with it. */
  private rescaleTrail(before: readonly { mx: Mapping; my: Mapping }[]): void {
    const { frame, trail } = this;
    const copy = (this.scratch ??= frame.layer());
    const c = copy.context;
    c.save();
    c.setTransform(1, 0, 0, 1, 0, 0);
    c.clearRect(0, 0, copy.canvas.width, copy.canvas.height);
    c.drawImage(trail.canvas, 0, 0);
    c.restore();
    rescaleImage(trail.context, copy.canvas, this.panels, before, frame.width, frame.height, frame.dpr);
  }

  /** Redraws the trail layer from the record, oldest age bucket first. */
  private redrawTrail(): void {
    const started = performance.now();
    const g = this.trail.context;
    g.clearRect(0, 0, this.frame.width, this.frame.height);
    for (const p of this.panels) liftPens(p.pens);
    this.fader.clear();
    this.sinceRedraw = 0;
    const record = this.simulation?.record;
    if (!record || record.length === 0 || this.mode.kind === 'none') return;
    const length = this.mode.kind === 'frames' ? (this.frameTime > 0 ? FADE_FRAMES * this.frameTime : Infinity) : this.mode.length;
    const now = record.time(record.length - 1);
    let from = record.range(now - length, now)[0];
    for (const bucket of ageBuckets(record.time(0), now, length, BUCKETS)) {
      const to = bucket.t1 >= now ? record.length : record.range(bucket.t1, Infinity)[0];
      if (to > from) this.traceRange(from, to, bucket.opacity);
      from = Math.max(from, to);
    }
    this.redrawCost = performance.now() - started;
  }

  /** Fades the trail for the elapsed time and draws rows [from, to) onto it. */
  private advance(from: number, to: number, elapsed: number): void {
    const alpha = this.fader.advance(elapsed);
    this.sinceRedraw += elapsed;
    // A redraw every trail length or four, if cheap, clears the faint ghost that 8-bit fading leaves (see trail.ts).
    const cleanEvery = this.redrawCost < 2 ? 1 : this.redrawCost < EXPENSIVE_REDRAW_MS ? 4 : Infinity;
    if (this.mode.kind !== 'full' && this.sinceRedraw > cleanEvery * this.mode.length) {
      this.redrawTrail();
    } else {
      if (alpha > 0) fadeLayer(this.trail.context, alpha, this.frame.width, this.frame.height);
      if (this.mode.kind !== 'none') this.traceRange(from, to, 1);
    }
    this.dirty = true;
  }

  /** Strokes rows [from, to) of every track onto the trail at `opacity`. */
  private traceRange(from: number, to: number, opacity: number): void {
    strokeRows(this.trail.context, this.simulation!.record, this.panels, from, to, opacity, this.lineStyle());
  }

  /** Base and trail layers onto the visible canvas, then a dot at each track's current state. */
  private compose(): void {
    const { frame } = this;
    frame.clear();
    frame.compose(this.base);
    frame.compose(this.trail);
    const record = this.simulation?.record;
    const radius = this.definition.dot ?? defaultLook(this.trackCount()).radius;
    if (record && record.length && radius > 0) {
      drawDots(frame.context, record, record.length - 1, this.panels, radius, this.color, frame.theme.bg);
    }
    frame.markReady();
    this.dirty = false;
    const now = performance.now();
    if (now - this.described >= TEXT_INTERVAL_MS) {
      this.described = now;
      frame.describe(this.summary());
      this.table.refresh(true);
    }
  }

  /** The record's columns each panel draws, named as the record names them, for text. */
  private panelColumns(panel: Panel): { name: string; index: number }[] {
    const columns = this.simulation?.record.columns ?? [];
    const out: { name: string; index: number }[] = [];
    for (let k = 0; k < panel.xs.length; k++) out.push({ name: columns[panel.xs[k]], index: panel.xs[k] }, { name: columns[panel.ys[k]], index: panel.ys[k] });
    return out;
  }

  /** The text alternative: what each panel plots, its ranges, and where the motion is now. */
  private summary(): string {
    const record = this.simulation?.record;
    const parts = this.panels.map((panel, i) => {
      const { spec } = panel;
      const axes = this.axes[i];
      const ranges = axes ? `; ${spec.xLabel} ${rangeText(axes.x.domain)}, ${spec.yLabel} ${rangeText(axes.y.domain)}` : '';
      const now = record ? latestValues(record, this.panelColumns(panel)) : '';
      const tracks = panel.xs.length > 1 ? ` (${panel.xs.length} tracks)` : '';
      return `${spec.yLabel} against ${spec.xLabel}${tracks}${ranges}${now ? `; now ${now}` : ''}`;
    });
    const t = record && record.length ? `, t = ${show(record.time(record.length - 1))}` : '';
    return `${this.definition.label}${t}: ${parts.join('. ') || 'nothing drawn'}`;
  }

  /** The data-table view: the drawn columns at evenly spaced times over the record. */
  private tableData(): TableData | null {
    const record = this.simulation?.record;
    if (!record || record.length === 0 || this.panels.length === 0) return null;
    const seen = new Set<number>();
    const columns = this.panels.flatMap((p) => this.panelColumns(p)).filter((c) => !seen.has(c.index) && seen.add(c.index));
    const t0 = record.time(0);
    const t1 = record.time(record.length - 1);
    return recordTable(record, columns, rowsOver(record, t0, t1), `${this.definition.label}: values at ${TABLE_ROWS} times from t = ${show(t0)} to ${show(t1)}`);
  }

  private trackCount(): number {
    return this.panels.reduce((n, p) => n + p.xs.length, 0);
  }

  private lineStyle(): LineStyle {
    const look = defaultLook(this.trackCount());
    return {
      lineWidth: this.definition.lineWidth ?? look.lineWidth,
      lineOpacity: this.definition.lineOpacity ?? look.lineOpacity,
      jump: this.definition.jump ?? 0.25,
      color: this.color,
    };
  }

  private readonly color = (group: number): string => this.definition.colors?.[group] ?? seriesColor(this.frame.theme, group);
}
