import type { TrajectoryRecord } from '../../../core/index.ts';
import { fit, grow, settle } from './autoscale.ts';
import type { Context, Surface, SurfaceFactory } from '../canvas.ts';
import { ColumnDecimator, pendingRange, strokeColumns } from '../decimate.ts';
import { ScrollBuffer, SLOTS, viewLeft } from './scroll-buffer.ts';
import { makeMapping, toPixel, type Domain, type Mapping, type SignedKind } from '../scale.ts';

/** What `update` did: nothing new, drew the new samples, or grew the y range and redrew everything. */
export type UpdateResult = 'none' | 'drawn' | 'rescaled';

/**
 * The DOM-free part of the time plot: series of a trajectory record against
 * t, drawn incrementally into a ScrollBuffer through a ColumnDecimator, plus
 * a full redraw of any window from the record for scrolling back. Sizes are
 * device pixels of the plot area (axes excluded).
 */
export class TimeRenderer {
  width = 0;
  height = 0;
  origin = 0;
  domain: Domain = [-1, 1];
  /** columns [0, end) of the live trace have been drawn */
  end = 0;
  /** samples seen so far, counting those the record has since dropped */
  seen = 0;
  autoscale = true;
  /** stroke width and the padding it needs around tile edges, in device pixels */
  lineWidth = 1.5;
  private pad = 4;
  private fitted = false;
  private map: Mapping = makeMapping('linear', [-1, 1], [1, 0]);
  private buffer: ScrollBuffer | null = null;
  private columns = new Int32Array(0);
  private styles: string[] = [];
  private alpha = 1;
  private live: ColumnDecimator;
  private history: ColumnDecimator;
  private historyTarget: Context | null = null;
  private historyLeft = 0;
  /** the live trace's end (column) when the range last changed, and when it was last checked for settling */
  private changedAt = 0;
  private checkedAt = 0;

  constructor(
    private readonly create: SurfaceFactory,
    public window: number,
    public kind: SignedKind = 'linear',
  ) {
    this.live = this.decimator(0, (d) => this.paintLive(d));
    this.history = this.decimator(0, (d) => this.paintHistory(d));
  }

  /** Pixels per unit of time. */
  get scaleX(): number {
    return this.width / this.window;
  }

  columnOf(t: number): number {
    return Math.floor((t - this.origin) * this.scaleX);
  }

  timeOf(column: number): number {
    return this.origin + column / this.scaleX;
  }

  /** Sets the plot area's size in device pixels and the stroke width; needs a redraw. */
  resize(width: number, height: number, lineWidth = 1.5): void {
    this.width = Math.max(1, Math.round(width));
    this.height = Math.max(1, Math.round(height));
    this.lineWidth = lineWidth;
    this.pad = Math.ceil(this.lineWidth) + 2;
    this.buffer = new ScrollBuffer(this.width, this.height, this.create);
    this.setDomain(this.domain);
  }

  /** The record columns to draw, a stroke colour for each, and their opacity; needs a redraw. */
  setSeries(columns: readonly number[], styles: readonly string[], alpha = 1): void {
    this.columns = Int32Array.from(columns);
    this.styles = [...styles];
    this.alpha = alpha;
    const n = columns.length;
    const capacity = Math.max(16, Math.min(4096, Math.floor(2 ** 17 / Math.max(1, n))));
    this.live = this.decimator(n, (d) => this.paintLive(d), capacity);
    this.history = this.decimator(n, (d) => this.paintHistory(d), capacity);
  }

  /** Sets the y range (needs a redraw); `fitted` false lets the next update fit it to the data. */
  setDomain(domain: Domain, kind = this.kind, fitted = true): void {
    this.kind = kind;
    this.domain = domain;
    this.fitted = fitted;
    const inset = Math.min(this.height / 4, this.pad);
    this.map = makeMapping(kind, domain, [this.height - inset, inset]);
  }

  /** The pixel range the domain maps onto, as fractions of the height: for drawing the axis in CSS pixels. */
  get inset(): number {
    return Math.min(this.height / 4, this.pad) / this.height;
  }

  /** Forgets what was drawn; the trace restarts at column 0 = time `origin`. */
  reset(origin: number): void {
    this.origin = origin;
    this.end = 0;
    this.seen = 0;
    this.changedAt = this.checkedAt = 0;
    this.fitted = !this.autoscale;
    this.buffer?.reset();
    this.live.reset();
  }

  /** Draws what is new in the record since the last call (or everything, after the y range grew). */
  update(record: TrajectoryRecord): UpdateResult {
    const total = record.dropped + record.length;
    if (total < this.seen) this.reset(this.origin);
    if (total === this.seen || !this.buffer) return 'none';
    let from = Math.max(0, this.seen - record.dropped);
    const to = record.length;
    this.seen = total;
    if (from >= to) return 'none';
    if (this.autoscale) {
      const [lo, hi] = this.extent(record, from, to);
      const next = this.fitted ? grow(this.domain, lo, hi, this.kind) : lo <= hi ? fit(lo, hi, this.kind) : null;
      if (next) {
        this.setDomain(next);
        this.redraw(record);
        this.changedAt = this.end;
        return 'rescaled';
      }
      if (this.settleRange(record)) return 'rescaled';
    }
    this.end = Math.max(this.end, this.columnOf(record.time(to - 1)) + 1);
    const cut = this.end - this.width - this.pad;
    if (this.columnOf(record.time(from)) < cut) {
      // Rows that scrolled out of view before they were drawn: start one row early so the line joins.
      from = Math.max(from, record.range(this.timeOf(cut), Infinity)[0] - 1);
      this.live.penUp();
    }
    this.feed(record, from, to, this.live);
    return 'drawn';
  }

  /**
   * After half a window without growth, fits the range again to the data
   * in view if growth left it much too loose (checked every eighth of a
   * window): a running plot hugs its data, while one that keeps growing is
   * never shrunk between growths. Returns whether it refitted (and redrew).
   */
  private settleRange(record: TrajectoryRecord): boolean {
    if (this.end - this.changedAt < this.width / 2 || this.end - this.checkedAt < this.width / 8) return false;
    this.checkedAt = this.end;
    const [from] = record.range(this.timeOf(this.end - this.width), Infinity);
    const [lo, hi] = this.extent(record, from, record.length);
    const next = settle(this.domain, lo, hi, this.kind);
    if (!next) return false;
    this.setDomain(next);
    this.redraw(record);
    this.changedAt = this.end;
    return true;
  }

  /** Redraws the live window from the record, after a change of size, series or range. */
  redraw(record: TrajectoryRecord): void {
    if (!this.buffer) return;
    this.buffer.reset();
    this.live.reset();
    this.seen = record.dropped + record.length;
    if (record.length === 0) return;
    this.end = this.columnOf(record.time(record.length - 1)) + 1;
    const from = record.range(this.timeOf(this.end - this.width - this.pad), Infinity)[0];
    this.feed(record, Math.max(0, from - 1), record.length, this.live);
  }

  /** Blits the live window onto `target` at (x, y); for PNGs and tests (the page moves the tiles instead). */
  composite(target: Context, x = 0, y = 0): void {
    this.buffer?.composite(target, this.end, x, y);
  }

  /** Calls `place(slot, x)` for each ring slot with its x in the live view (NaN: not visible). */
  place(place: (slot: number, surface: Surface, x: number) => void): void {
    const buffer = this.buffer;
    if (!buffer) return;
    for (let slot = 0; slot < SLOTS; slot++) place(slot, buffer.surface(slot), buffer.placement(slot, this.end));
  }

  /** The first column of the live window. */
  get left(): number {
    return viewLeft(this.end, this.width);
  }

  /** Draws the window of columns [end − width, end) straight from the record onto `target`. */
  renderWindow(target: Context, record: TrajectoryRecord, end: number): void {
    target.clearRect(0, 0, this.width, this.height);
    if (record.length === 0) return;
    const left = end - this.width;
    const [from, to] = record.range(this.timeOf(left - this.pad), this.timeOf(end + this.pad));
    this.historyTarget = target;
    this.historyLeft = left;
    this.history.reset();
    this.feed(record, Math.max(0, from - 1), Math.min(record.length, to + 1), this.history);
    this.historyTarget = null;
  }

  /** Fits the y range to the drawn series over rows with t in [t0, t1]. */
  fitWindow(record: TrajectoryRecord, t0: number, t1: number): void {
    const [from, to] = record.range(t0, t1);
    const [lo, hi] = this.extent(record, from, to);
    this.setDomain(fit(lo, hi, this.kind));
  }

  /** Smallest and largest finite value of the drawn series over rows [from, to). */
  private extent(record: TrajectoryRecord, from: number, to: number): [number, number] {
    let lo = Infinity;
    let hi = -Infinity;
    const { columns } = this;
    const n = columns.length;
    const width = record.width;
    for (const s of from < to ? record.slices(from, to) : []) {
      const data = s.data;
      for (let r = s.from; r < s.to; r++) {
        const at = r * width;
        for (let k = 0; k < n; k++) {
          const v = data[at + columns[k]];
          if (v - v !== 0) continue; // NaN or ±Infinity
          if (v < lo) lo = v;
          if (v > hi) hi = v;
        }
      }
    }
    return [lo, hi];
  }

  /** Feeds rows [from, to) through a decimator and flushes it. No allocation per row. */
  private feed(record: TrajectoryRecord, from: number, to: number, d: ColumnDecimator): void {
    const { columns, map, origin } = this;
    const n = columns.length;
    const width = record.width;
    const scaleX = this.scaleX;
    for (const s of from < to ? record.slices(from, to) : []) {
      const data = s.data;
      for (let r = s.from; r < s.to; r++) {
        const at = r * width;
        d.column(Math.floor((data[at] - origin) * scaleX));
        for (let k = 0; k < n; k++) d.value(k, toPixel(map, data[at + columns[k]]));
      }
    }
    d.end();
  }

  private decimator(n: number, sink: (d: ColumnDecimator) => void, capacity = 16): ColumnDecimator {
    return new ColumnDecimator(n, capacity, sink);
  }

  /** Strokes the pending columns into each tile they touch: only the columns within the tile and its padding. */
  private paintLive(d: ColumnDecimator): void {
    const start = d.penX[0] === d.penX[0] ? Math.min(d.penX[0], d.columns[0]) : d.columns[0];
    const { pad, width } = this;
    this.buffer?.paint(start, d.columns[d.count - 1], pad, (ctx, offset) => {
      const [i0, i1] = pendingRange(d, offset - pad, offset + width + pad);
      // one more on each side, so the segments crossing the tile's edges are drawn
      if (i0 < d.count) this.stroke(ctx, d, offset, i0, Math.min(d.count, i1 + 1));
    });
  }

  private paintHistory(d: ColumnDecimator): void {
    if (this.historyTarget) this.stroke(this.historyTarget, d, this.historyLeft);
  }

  private stroke(ctx: Context, d: ColumnDecimator, offset: number, i0 = 0, i1 = d.count): void {
    ctx.lineWidth = this.lineWidth;
    ctx.lineJoin = 'round';
    // Butt caps: each frame's strokes start where the last ones ended, and round
    // caps would overlap there, leaving darker dots on translucent batch lines.
    ctx.lineCap = 'butt';
    ctx.globalAlpha = this.alpha;
    for (let k = 0; k < d.series; k++) {
      ctx.strokeStyle = this.styles[k];
      strokeColumns(ctx, d, k, offset, i0, i1);
    }
    ctx.globalAlpha = 1;
  }
}
