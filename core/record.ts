import { columnProblem, type Table } from './tables/table.ts';

export type { Table } from './tables/table.ts';
export { bytesFor, capacityFor } from './capacity.ts';

/** Throws unless `i` is an integer in [0, n); `what` names it in the message. */
function checkIndex(i: number, n: number, what: string): void {
  if (!Number.isInteger(i) || i < 0 || i >= n) throw new RangeError(`TrajectoryRecord: ${what} ${i} is outside [0, ${n})`);
}

/** One quantity a record holds (q0, p0, H …), with its column for each trajectory: trajectory j's is `columns[j]`. */
export interface RecordSeries {
  readonly name: string;
  readonly columns: readonly number[];
}

/**
 * What a record's columns hold: `columns` are the names written in export
 * headers (t, then q0, p0 … or, for a batch, q0[0], p0[0] … q0[1] …), and
 * `series` says which columns belong to which quantity and trajectory, so
 * that nothing needs to read the structure back out of the names.
 */
export interface RecordLayout {
  readonly columns: readonly string[];
  readonly series: readonly RecordSeries[];
  /** trajectories in the record: 1, or the batch's size */
  readonly trajectories: number;
}

/**
 * The layout of `count` trajectories of the state `names` and the derived
 * series `derived`: t; each trajectory's state in turn; then each
 * trajectory's derived values. One trajectory's columns are named plainly,
 * a batch's `name[j]`.
 */
export function recordLayout(names: readonly string[], derived: readonly string[], count = 1): RecordLayout {
  const columns = ['t'];
  const series: RecordSeries[] = [];
  const block = (group: readonly string[]) => {
    const first = columns.length;
    for (let j = 0; j < count; j++) columns.push(...group.map((n) => (count === 1 ? n : `${n}[${j}]`)));
    group.forEach((name, k) => series.push({ name, columns: Array.from({ length: count }, (_, j) => first + j * group.length + k) }));
  };
  block(names);
  block(derived);
  return { columns, series, trajectories: count };
}

/** The layout of a record whose columns are all its own series, one trajectory: what a table read back from a file is. */
function plainLayout(columns: readonly string[]): RecordLayout {
  return { columns, series: columns.slice(1).map((name, i) => ({ name, columns: [i + 1] })), trajectories: 1 };
}

/**
 * The samples of one running trajectory, kept in a fixed-size ring so that a
 * simulation left running for hours uses bounded memory: once full, each new
 * row overwrites the oldest and `dropped` counts the loss, so exports and
 * widgets can say that the record no longer starts at t0.
 *
 * Rows are indexed in time order: row 0 is the oldest row still held.
 */
export class TrajectoryRecord implements RecordLayout {
  readonly columns: readonly string[];
  readonly series: readonly RecordSeries[];
  readonly trajectories: number;
  readonly width: number;
  readonly capacity: number;
  /** Rows overwritten since creation or the last clear(). */
  dropped = 0;

  private readonly buf: Float64Array;
  /** Ring slot of row 0. */
  private head = 0;
  private count = 0;

  constructor(layout: readonly string[] | RecordLayout, capacity: number) {
    const { columns, series, trajectories } = Array.isArray(layout) ? plainLayout(layout as readonly string[]) : (layout as RecordLayout);
    if (!Number.isInteger(capacity) || capacity < 1) {
      throw new Error(`TrajectoryRecord: capacity must be a positive integer number of rows, got ${capacity}`);
    }
    const problem = columnProblem(columns);
    if (problem !== undefined) throw new Error(`TrajectoryRecord: ${problem}`);
    if (columns[0] !== 't') throw new Error(`TrajectoryRecord: column 0 must be "t", got "${columns[0]}"`);
    this.columns = Object.freeze([...columns]);
    this.series = Object.freeze(series.map((s) => Object.freeze({ name: s.name, columns: Object.freeze([...s.columns]) })));
    this.trajectories = trajectories;
    this.width = columns.length;
    this.capacity = capacity;
    this.buf = new Float64Array(capacity * this.width);
  }

  get length(): number {
    return this.count;
  }

  /** Claims the slot for a new row, evicting the oldest when full; returns its buffer offset. */
  private claim(): number {
    if (this.count < this.capacity) return this.slot(this.count++);
    const at = this.head * this.width;
    if (++this.head === this.capacity) this.head = 0;
    this.dropped++;
    return at;
  }

  /** Buffer offset of row i, unchecked. */
  private slot(i: number): number {
    const s = this.head + i;
    return (s < this.capacity ? s : s - this.capacity) * this.width;
  }

  push(values: ArrayLike<number>, offset = 0): void {
    const w = this.width;
    if (!(offset >= 0) || values.length - offset < w) {
      throw new RangeError(`TrajectoryRecord.push: need ${w} values from offset ${offset}, have ${values.length - offset}`);
    }
    const at = this.claim();
    for (let j = 0; j < w; j++) this.buf[at + j] = values[offset + j];
  }

  time(i: number): number {
    checkIndex(i, this.count, 'row');
    return this.buf[this.slot(i)];
  }

  get(i: number, column: number): number {
    checkIndex(i, this.count, 'row');
    checkIndex(column, this.width, 'column');
    return this.buf[this.slot(i) + column];
  }

  columnIndex(name: string): number {
    return this.columns.indexOf(name);
  }

  private checkRange(from: number, to: number): void {
    if (!Number.isInteger(from) || !Number.isInteger(to) || from < 0 || to < from || to > this.count) {
      throw new RangeError(`TrajectoryRecord: rows [${from}, ${to}) are not within [0, ${this.count})`);
    }
  }

  /**
   * One column of rows [from, to) in time order. When `out` is given the
   * values go to out[0 … to-from) and `out` itself is returned, so a plot can
   * reuse one buffer every frame.
   */
  column(column: number | string, out?: Float64Array, from = 0, to = this.count): Float64Array {
    const c = typeof column === 'string' ? this.columnIndex(column) : column;
    if (c === -1) throw new RangeError(`TrajectoryRecord.column: no column named "${column}"`);
    checkIndex(c, this.width, 'column');
    this.checkRange(from, to);
    const n = to - from;
    const dest = out ?? new Float64Array(n);
    if (dest.length < n) throw new RangeError(`TrajectoryRecord.column: out holds ${dest.length} values, need ${n}`);
    for (let k = 0; k < n; k++) dest[k] = this.buf[this.slot(from + k) + c];
    return dest;
  }

  /** [from, to) such that exactly rows from … to-1 have t0 <= t <= t1; t must increase. */
  range(t0: number, t1: number): [number, number] {
    const from = this.search(0, (t) => t >= t0);
    return [from, this.search(from, (t) => t > t1)];
  }

  /** The first row at or after `lo` whose time is `past`, for a predicate monotone in t. */
  private search(lo: number, past: (t: number) => boolean): number {
    let hi = this.count;
    while (lo < hi) {
      const mid = (lo + hi) >>> 1;
      if (past(this.buf[this.slot(mid)])) hi = mid;
      else lo = mid + 1;
    }
    return lo;
  }

  /**
   * Rows [from, to) as at most two runs of row indices into the live storage,
   * in time order, so exporters can stream the ring without copying it. The
   * data changes with the next push.
   */
  slices(from = 0, to = this.count): Array<{ data: Float64Array; from: number; to: number }> {
    this.checkRange(from, to);
    if (from === to) return [];
    const start = this.slot(from) / this.width;
    const end = start + (to - from);
    if (end <= this.capacity) return [{ data: this.buf, from: start, to: end }];
    return [
      { data: this.buf, from: start, to: this.capacity },
      { data: this.buf, from: 0, to: end - this.capacity },
    ];
  }

  /** A detached, contiguous copy of rows [from, to). */
  table(from = 0, to = this.count): Table {
    this.checkRange(from, to);
    const w = this.width;
    const data = new Float64Array((to - from) * w);
    let at = 0;
    for (const s of this.slices(from, to)) {
      data.set(s.data.subarray(s.from * w, s.to * w), at);
      at += (s.to - s.from) * w;
    }
    return { columns: this.columns, rows: to - from, data };
  }

  /** Forgets all rows and the dropped count; the storage is kept for reuse. */
  clear(): void {
    this.head = 0;
    this.count = 0;
    this.dropped = 0;
  }
}
