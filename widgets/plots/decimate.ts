import type { Context } from './canvas.ts';
import type { PathSink } from './trace.ts';

/**
 * Min/max decimation by pixel column: however many samples fall into one
 * device-pixel column, each series is drawn there as one vertical stroke
 * from its smallest to its largest value, joined to the neighbouring columns
 * through its first and last value. The picture is the same as drawing every
 * sample (a line's extent within a column is all a column can show), and the
 * drawing work per frame is bounded by columns × series, not samples.
 *
 * Samples go in as column(c) once per sample, then value(s, y) for every
 * series s with y already in pixels. Completed columns queue up and are
 * handed to `sink` when the queue is full and at end(); the sink strokes them
 * (strokeColumns) and the decimator then forgets them, keeping only each
 * series' last point so the next batch joins on. All storage is allocated
 * up front: nothing is allocated per sample.
 */
export class ColumnDecimator {
  /** pending (completed) columns */
  count = 0;
  /** absolute column index of pending column i */
  readonly columns: Float64Array;
  /** where pending column i is drawn across: its first sample's pixel, or the column's centre */
  readonly at: Float64Array;
  /** per pending column i and series s, at i·series + s: NaN `first` marks a gap */
  readonly first: Float64Array;
  readonly min: Float64Array;
  readonly max: Float64Array;
  readonly last: Float64Array;
  /** each series' last drawn point, where the next stroke starts; NaN y lifts the pen */
  readonly penX: Float64Array;
  readonly penY: Float64Array;

  private current = NaN;
  private currentAt = NaN;
  private readonly cFirst: Float64Array;
  private readonly cMin: Float64Array;
  private readonly cMax: Float64Array;
  private readonly cLast: Float64Array;

  constructor(
    readonly series: number,
    readonly capacity: number,
    private readonly sink: (decimator: ColumnDecimator) => void,
    /** pixel values are clamped to ±limit so a wild value cannot make the canvas choke */
    private readonly limit = 1e5,
  ) {
    const n = series * capacity;
    this.columns = new Float64Array(capacity);
    this.at = new Float64Array(capacity);
    this.first = new Float64Array(n);
    this.min = new Float64Array(n);
    this.max = new Float64Array(n);
    this.last = new Float64Array(n);
    this.penX = new Float64Array(series).fill(NaN);
    this.penY = new Float64Array(series).fill(NaN);
    this.cFirst = new Float64Array(series).fill(NaN);
    this.cMin = new Float64Array(series);
    this.cMax = new Float64Array(series);
    this.cLast = new Float64Array(series);
  }

  /**
   * Starts the next sample, in pixel column c (non-decreasing from sample to
   * sample); a new column is drawn at `x`, by default its centre.
   */
  column(c: number, x = c + 0.5): void {
    if (c === this.current) return;
    if (this.current === this.current) this.commit();
    this.current = c;
    this.currentAt = x;
  }

  /** Adds series s's value at the current sample, in pixels; non-finite values leave a gap. */
  value(s: number, y: number): void {
    if (y - y !== 0) return;
    const limit = this.limit;
    const v = y < -limit ? -limit : y > limit ? limit : y;
    if (this.cFirst[s] !== this.cFirst[s]) {
      this.cFirst[s] = v;
      this.cMin[s] = v;
      this.cMax[s] = v;
    } else if (v < this.cMin[s]) this.cMin[s] = v;
    else if (v > this.cMax[s]) this.cMax[s] = v;
    this.cLast[s] = v;
  }

  /** Completes the current column (even if more samples may land in it later) and flushes the queue. */
  end(): void {
    this.close();
    if (this.count > 0) this.flush();
  }

  /** Completes the current column without flushing: the pending columns are then all there is to draw. */
  close(): void {
    if (this.current === this.current) this.commit();
    this.current = NaN;
  }

  /** Lifts every pen: the next samples do not join onto what was drawn before. */
  penUp(): void {
    this.penY.fill(NaN);
  }

  /** Forgets everything, pending columns and pens included. */
  reset(): void {
    this.count = 0;
    this.current = NaN;
    this.cFirst.fill(NaN);
    this.penUp();
  }

  private commit(): void {
    if (this.count === this.capacity) this.flush();
    const { series: n } = this;
    const at = this.count * n;
    this.columns[this.count] = this.current;
    this.at[this.count] = this.currentAt;
    for (let s = 0; s < n; s++) {
      this.first[at + s] = this.cFirst[s];
      this.min[at + s] = this.cMin[s];
      this.max[at + s] = this.cMax[s];
      this.last[at + s] = this.cLast[s];
    }
    this.cFirst.fill(NaN);
    this.count++;
  }

  private flush(): void {
    this.sink(this);
    const { series: n, count } = this;
    const x = this.columns[count - 1];
    const at = (count - 1) * n;
    for (let s = 0; s < n; s++) {
      this.penX[s] = x;
      this.penY[s] = this.first[at + s] === this.first[at + s] ? this.last[at + s] : NaN;
    }
    this.count = 0;
  }
}

/** Indices [i0, i1) of the pending columns c with c0 ≤ c < c1 (pending columns increase). */
export function pendingRange(d: ColumnDecimator, c0: number, c1: number): [number, number] {
  const search = (c: number): number => {
    let lo = 0;
    let hi = d.count;
    while (lo < hi) {
      const mid = (lo + hi) >>> 1;
      if (d.columns[mid] < c) lo = mid + 1;
      else hi = mid;
    }
    return lo;
  };
  return [search(c0), search(c1)];
}

/**
 * Traces series s of pending columns [i0, i1) into `sink`, each column at
 * `at[i] − shift`, joined onto (joinX, joinY) unless joinY is NaN: its first
 * value, its range and its last value, the same picture as every sample. A
 * subpath that is still a single point gets a 1-pixel dash when it ends, so
 * that it shows. Returns the segments drawn.
 */
export function traceColumns(sink: PathSink, d: ColumnDecimator, s: number, shift: number, joinX: number, joinY: number, i0 = 0, i1 = d.count): number {
  const { series: n, at, first, min, max, last } = d;
  let down = joinY === joinY;
  let segments = 0;
  let lone = false;
  let lx = 0;
  let ly = 0;
  const line = (x: number, y: number) => {
    sink.lineTo(x, y);
    segments++;
  };
  if (down) sink.moveTo(joinX, joinY);
  for (let i = i0; i < i1; i++) {
    const k = i * n + s;
    const f = first[k];
    if (f !== f) {
      if (lone) line(lx + 1, ly);
      lone = down = false;
      continue;
    }
    const x = at[i] - shift;
    const lo = min[k];
    const hi = max[k];
    const l = last[k];
    if (down) line(x, f);
    else sink.moveTo(x, f);
    lone = !down && !(lo < hi);
    lx = x;
    ly = f;
    if (lo < hi) {
      if (lo !== f) line(x, lo);
      line(x, hi);
      if (l !== hi) line(x, l);
    }
    down = true;
  }
  if (lone) line(lx + 1, ly);
  return segments;
}

/**
 * Strokes series s of pending columns [i0, i1) as one path, shifted left by
 * `offset` columns, at pixel centres, joined onto the column before i0 (or
 * the pen). The caller sets the style.
 */
export function strokeColumns(ctx: Context, d: ColumnDecimator, s: number, offset: number, i0 = 0, i1 = d.count): void {
  const { series: n, columns, first, last } = d;
  const before = (i0 - 1) * n + s;
  const penX = i0 > 0 ? columns[i0 - 1] : d.penX[s];
  const penY = i0 > 0 ? (first[before] === first[before] ? last[before] : NaN) : d.penY[s];
  ctx.beginPath();
  traceColumns(ctx, d, s, offset, penX - offset + 0.5, penY, i0, i1);
  ctx.stroke();
}
