import type { TrajectoryRecord } from '../../core/index.ts';
import { readoutNumber } from '../controls/format.ts';

/**
 * What a plot shows, as text: the rows of its data-table view and the
 * sentence of its text alternative. No DOM here, so both are unit-tested;
 * plot-table.ts puts the table on the page.
 */
export interface TableData {
  caption: string;
  head: string[];
  rows: string[][];
}

/** Rows a table shows at most: enough to read a period or a trend, few enough to read out. */
export const TABLE_ROWS = 11;
/** Series columns a table shows at most (a batch has many); the caption says when some are left out. */
export const TABLE_SERIES = 8;

/** A number as the tables and text alternatives write it: four significant digits, a true minus. */
export function show(v: number): string {
  return readoutNumber(v, 4);
}

/**
 * Record rows evenly spaced in time over [t0, t1], at most `count`, latest
 * last: each is the last row at or before its time.
 */
export function rowsOver(record: TrajectoryRecord, t0: number, t1: number, count = TABLE_ROWS): number[] {
  if (record.length === 0) return [];
  const first = record.time(0);
  const last = record.time(record.length - 1);
  const from = Math.max(first, t0);
  const to = Math.min(last, t1);
  if (!(to >= from)) return [record.length - 1];
  const rows: number[] = [];
  for (let k = count - 1; k >= 0; k--) {
    const t = count > 1 ? to - ((to - from) * k) / (count - 1) : to;
    const [, end] = record.range(-Infinity, t);
    const row = Math.max(0, Math.min(record.length - 1, end - 1));
    if (rows[rows.length - 1] !== row) rows.push(row);
  }
  return rows;
}

/** A table of record columns (by index, with their heading) at the given rows, t first. */
export function recordTable(record: TrajectoryRecord, columns: readonly { name: string; index: number }[], rows: readonly number[], caption: string): TableData {
  const shown = columns.slice(0, TABLE_SERIES);
  const more = columns.length - shown.length;
  return {
    caption: more > 0 ? `${caption} (the first ${shown.length} of ${columns.length} series)` : caption,
    head: ['t', ...shown.map((c) => c.name)],
    rows: rows.map((r) => [show(record.time(r)), ...shown.map((c) => show(record.get(r, c.index)))]),
  };
}

/** "q = 0.5310, p = −0.8430": the latest values of some columns. */
export function latestValues(record: TrajectoryRecord, columns: readonly { name: string; index: number }[], most = 4): string {
  if (record.length === 0) return '';
  const row = record.length - 1;
  const listed = columns.slice(0, most).map((c) => `${c.name} = ${show(record.get(row, c.index))}`);
  if (columns.length > most) listed.push(`and ${columns.length - most} more`);
  return listed.join(', ');
}

/** "from −1.2 to 1.2": an axis range in words. */
export function rangeText(domain: readonly [number, number]): string {
  const [a, b] = domain[0] <= domain[1] ? domain : [domain[1], domain[0]];
  return `from ${show(a)} to ${show(b)}`;
}
