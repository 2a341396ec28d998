import { roundTripNumber } from './csv.ts';
import type { ExportMeta } from './export-meta.ts';
import { columnProblem, type Table } from './table.ts';

/**
 * JSON export of sampled trajectories: `{"meta": …, "columns": […], "data": [[…], …]}`
 * with one row per line, so a diff or `head` of an export stays readable and
 * the reader can name the line of a bad row.
 *
 * Data numbers are written like CSV fields (shortest round trip, `-0` kept).
 * JSON has no NaN or Infinity, and JSON.stringify would turn them into a
 * lossy `null`, so they are written as the strings "NaN", "Infinity" and
 * "-Infinity": the file stays valid JSON, round-trips exactly, and `Number()`
 * of the string is still the value. The reader also takes `null` as NaN.
 * `meta` goes through JSON.stringify as is, so non-finite numbers in it
 * become null and -0 becomes 0.
 */

/** One data value as written in a JSON export. */
export function jsonNumber(x: number): string {
  return Number.isFinite(x) ? roundTripNumber(x) : `"${x}"`;
}

/** Everything up to and including the opening bracket of `data`. */
export function jsonHead(meta: ExportMeta, columns: readonly string[]): string {
  const problem = columnProblem(columns);
  if (problem !== undefined) throw new Error(`jsonHead: ${problem}`);
  return `{"meta":${JSON.stringify(meta)},\n"columns":${JSON.stringify(columns)},\n"data":[`;
}

/**
 * Rows [from, to) of row-major `data`, each on its own line. `first` says
 * whether these are the first rows written after jsonHead (no leading comma);
 * an empty block writes nothing, so keep `first` true until a block was
 * non-empty.
 */
export function jsonRows(data: ArrayLike<number>, width: number, from: number, to: number, first: boolean): string {
  if (from < 0 || to < from || to * width > data.length) {
    throw new RangeError(`jsonRows: rows [${from}, ${to}) of width ${width} do not fit in ${data.length} values`);
  }
  let out = '';
  for (let i = from; i < to; i++) {
    const at = i * width;
    let line = (first && i === from ? '\n[' : ',\n[') + jsonNumber(data[at]);
    for (let j = 1; j < width; j++) line += ',' + jsonNumber(data[at + j]);
    out += line + ']';
  }
  return out;
}

/** Closes what jsonHead opened. */
export function jsonTail(): string {
  return '\n]}\n';
}

/** The whole export as one string; identical to head + rows + tail. */
export function toJSON(table: Table, meta: ExportMeta): string {
  return jsonHead(meta, table.columns) + jsonRows(table.data, table.columns.length, 0, table.rows, true) + jsonTail();
}
