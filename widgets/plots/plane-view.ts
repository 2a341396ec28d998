import type { Simulation } from '../core/simulation.ts';
import { unseen, type View } from '../simulator/view.ts';
import { toPixel } from './axis-scale.ts';
import { drawAxes, drawLegend } from './draw-axes.ts';
import { includeRows, liftPens, traceRows, type Stroke } from './trace.ts';
import { ageBuckets, Fader, FADE_FRAMES, parseTrail, type TrailOption } from './trail.ts';
import { gridColumns, growPanel, makePanel, panelRect, placePanel, type Panel, type PanelSpec } from './plane-panels.ts';
import { ViewFrame, type Layer } from './view-frame.ts';
import { seriesColor } from './view-theme.ts';

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
  /** a step longer than this fraction of the panel is a jump, drawn as a break in the line; default 0.25 */
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
const BUCKETS = 12;
/** Samples with the pen down closer than this (CSS px) to the last drawn point are skipped. */
const MIN_STEP = 0.5;

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
  }

  get element(): HTMLElement {
    return this.frame.element;
  }

  draw(simulation: Simulation): void {
    const record = simulation.record;
    if (simulation !== this.simulation || record.columns !== this.columns || record.dropped + record.length < this.seen) {
      this.reset(simulation);
    }
    if (this.frame.measure()) this.relayout();
    if (this.panels.length === 0) return;
    const { from, to, total } = unseen(simulation, this.seen);
    if (from < to) {
      if (this.seen < record.dropped) for (const p of this.panels) liftPens(p.pens);
      const grew = this.measureNew(from, to);
      this.seen = total;
      const now = record.time(to - 1);
      const elapsed = Number.isFinite(this.lastTime) ? now - this.lastTime : 0;
      if (elapsed > 0) this.frameTime = this.frameTime > 0 ? 0.9 * this.frameTime + 0.1 * elapsed : elapsed;
      this.lastTime = now;
      if (grew) this.relayout();
      else this.advance(from, to, this.mode.kind === 'frames' ? 1 : elapsed);
    }
    if (this.dirty) this.compose();
  }

  reset(simulation: Simulation): void {
    this.simulation = simulation;
    this.columns = simulation.record.columns;
    this.seen = simulation.record.dropped + simulation.record.length;
    this.lastTime = simulation.record.length ? simulation.record.time(simulation.record.length - 1) : NaN;
    this.frameTime = 0;
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
    const count = Math.max(1, this.panels.length);
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

  /** Places panels, redraws the axes and the whole trail. */
  private relayout(): void {
    const { frame } = this;
    const count = this.panels.length;
    this.panels.forEach((p, i) => placePanel(p, panelRect(i, count, frame.width, frame.height)));
    const g = this.base.context;
    g.clearRect(0, 0, frame.width, frame.height);
    for (const panel of this.panels) {
      const { spec } = panel;
      drawAxes(g, panel.rect, panel.mx, panel.my, frame.theme, spec, frame.dpr);
      const items = spec.legend.map((l) => ({ label: l.label, color: this.color(l.group) }));
      drawLegend(g, panel.rect, items, frame.theme, spec.title);
    }
    this.redrawTrail();
    this.dirty = true;
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
    // A cheap redraw now and then clears the faint ghost that 8-bit fading leaves (see trail.ts).
    if (this.mode.kind !== 'full' && this.sinceRedraw > 4 * this.mode.length && this.redrawCost < 6) {
      this.redrawTrail();
    } else {
      if (alpha > 0) {
        const g = this.trail.context;
        g.save();
        g.globalCompositeOperation = 'destination-out';
        g.fillStyle = `rgba(0,0,0,${alpha})`;
        g.fillRect(0, 0, this.frame.width, this.frame.height);
        g.restore();
      }
      if (this.mode.kind !== 'none') this.traceRange(from, to, 1);
    }
    this.dirty = true;
  }

  /** Strokes rows [from, to) of every track at `opacity`, one path per panel and colour group. */
  private traceRange(from: number, to: number, opacity: number): void {
    const record = this.simulation!.record;
    const g = this.trail.context;
    const slices = record.slices(from, to);
    const { lineWidth, lineOpacity } = this.lineStyle();
    g.save();
    g.lineWidth = lineWidth;
    g.globalAlpha = opacity * lineOpacity;
    for (const panel of this.panels) {
      const { rect, pens, xs, ys } = panel;
      const stroke: Stroke = { minStep: MIN_STEP, jump: (this.definition.jump ?? 0.25) * Math.min(rect.width, rect.height) };
      g.save();
      g.beginPath();
      g.rect(rect.left, rect.top, rect.width, rect.height);
      g.clip();
      for (let i = 0; i < panel.groups.length; i++) {
        g.strokeStyle = this.color(panel.groups[i]);
        g.beginPath();
        for (let k = panel.starts[i]; k < panel.starts[i + 1]; k++) {
          for (const s of slices) traceRows(g, s.data, record.width, s.from, s.to, xs[k], ys[k], panel.mx, panel.my, pens, k, stroke);
        }
        g.stroke();
      }
      g.restore();
    }
    g.restore();
  }

  /** Base and trail layers onto the visible canvas, then a dot at each track's current state. */
  private compose(): void {
    const { frame } = this;
    frame.clear();
    frame.compose(this.base);
    frame.compose(this.trail);
    const record = this.simulation?.record;
    const radius = this.definition.dot ?? (this.trackCount() > 50 ? 1.6 : 4);
    if (record && record.length && radius > 0) this.drawDots(record.length - 1, radius);
    frame.markReady();
    this.dirty = false;
  }

  private drawDots(row: number, radius: number): void {
    const record = this.simulation!.record;
    const [slice] = record.slices(row, row + 1);
    const at = slice.from * record.width;
    const g = this.frame.context;
    g.save();
    for (const panel of this.panels) {
      const { rect, xs, ys, mx, my } = panel;
      g.save();
      g.beginPath();
      g.rect(rect.left - radius, rect.top - radius, rect.width + 2 * radius, rect.height + 2 * radius);
      g.clip();
      for (let i = 0; i < panel.groups.length; i++) {
        g.beginPath();
        for (let k = panel.starts[i]; k < panel.starts[i + 1]; k++) {
          const x = toPixel(mx, slice.data[at + xs[k]]);
          const y = toPixel(my, slice.data[at + ys[k]]);
          if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
          g.moveTo(x + radius, y);
          g.arc(x, y, radius, 0, 2 * Math.PI);
        }
        g.fillStyle = this.color(panel.groups[i]);
        g.fill();
        if (radius >= 3) {
          g.lineWidth = 1.25;
          g.strokeStyle = this.frame.theme.bg;
          g.stroke();
        }
      }
      g.restore();
    }
    g.restore();
  }

  private trackCount(): number {
    return this.panels.reduce((n, p) => n + p.xs.length, 0);
  }

  private lineStyle(): { lineWidth: number; lineOpacity: number } {
    const tracks = this.trackCount();
    return {
      lineWidth: this.definition.lineWidth ?? (tracks > 20 ? 1 : 1.5),
      lineOpacity: this.definition.lineOpacity ?? (tracks > 100 ? 0.55 : 1),
    };
  }

  private color(group: number): string {
    return this.definition.colors?.[group] ?? seriesColor(this.frame.theme, group);
  }
}
