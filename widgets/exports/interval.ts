import type { TrajectoryRecord } from '../../core/index.ts';

/** Rows [from, to) of a record chosen by a time interval, with the times they actually span. */
export interface Selection {
  from: number;
  to: number;
  rows: number;
  /** time of the first and last selected row */
  first: number;
  last: number;
}

/**
 * The rows with t0 ≤ t ≤ t1 (the paper's downloadHistory(t0, t1), §6.1); a
 * missing bound means the start or the end of what is recorded. Returns a
 * one-line reason instead when the interval is reversed or holds no sample.
 */
export function selectRows(record: TrajectoryRecord, t0: number | null, t1: number | null): Selection | { error: string } {
  if (record.length === 0) return { error: 'nothing is recorded yet' };
  const start = record.time(0);
  const end = record.time(record.length - 1);
  const lo = t0 ?? start;
  const hi = t1 ?? end;
  if (Number.isNaN(lo) || Number.isNaN(hi)) return { error: 'the interval bounds must be numbers' };
  if (lo > hi) return { error: `t0 = ${lo} is after t1 = ${hi}` };
  const [from, to] = record.range(lo, hi);
  if (to <= from) return { error: `no samples with ${lo} ≤ t ≤ ${hi}; the record holds t from ${start} to ${end}` };
  return { from, to, rows: to - from, first: record.time(from), last: record.time(to - 1) };
}

/** A file name for an export of times [first, last]: phasebook-t0-30.csv. */
export function exportName(first: number, last: number, extension: string): string {
  const t = (x: number): string => String(Number(x.toPrecision(6))).replace('-', 'm');
  return `phasebook-t${t(first)}-${t(last)}.${extension}`;
}
