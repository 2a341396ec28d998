import { columnProblem, type Table } from './table.ts';

/**
 * CSV export of sampled trajectories (the reader is csv-read.ts).
 *
 * Numbers are written with JS's shortest round-trip formatting (`String(x)`),
 * so every double reads back bit-identical (NaN payloads aside), except that
 * -0 is written as `-0` because `String(-0)` is "0". Non-finite values are
 * written as `NaN`, `Infinity` and `-Infinity` rather than refused: a
 * trajectory that blew up is worth exporting, and the words read back exactly.
 *
 * Column names may not contain commas, quotes or line breaks, so no field is
 * ever quoted: the file is as plain as CSV gets, for any reader.
 */

/**
 * A number for a file that must read back as the same double: JS's shortest
 * round trip, with -0 kept. Every exporter writes its numbers through it.
 */
export function roundTripNumber(x: number): string {
  return x === 0 && 1 / x < 0 ? '-0' : String(x);
}

/** The header line, with its `\n`. Throws on names that would need quoting. */
export function csvHeader(columns: readonly string[]): string {
  const problem = columnProblem(columns);
  if (problem !== undefined) throw new Error(`csvHeader: ${problem}`);
  for (const name of columns) {
    if (/[,"\r\n]/.test(name) || name.trim() !== name) {
      throw new Error(`csvHeader: column name ${JSON.stringify(name)} cannot be written without quoting`);
    }
  }
  return columns.join(',') + '\n';
}

/**
 * Rows [from, to) of row-major `data` as lines, each ending in `\n`, so the
 * CLI can write millions of rows without one giant string. Blocks of a few
 * thousand rows keep the cost near that of formatting the numbers; one
 * 100 MB string costs about twice as much again.
 */
export function csvRows(data: ArrayLike<number>, width: number, from: number, to: number): string {
  if (from < 0 || to < from || to * width > data.length) {
    throw new RangeError(`csvRows: rows [${from}, ${to}) of width ${width} do not fit in ${data.length} values`);
  }
  let out = '';
  for (let i = from; i < to; i++) {
    const at = i * width;
    let line = roundTripNumber(data[at]);
    for (let j = 1; j < width; j++) line += ',' + roundTripNumber(data[at + j]);
    out += line + '\n';
  }
  return out;
}

/** The whole table as CSV text; equal to header plus all rows. */
export function toCSV(table: Table): string {
  return csvHeader(table.columns) + csvRows(table.data, table.columns.length, 0, table.rows);
}
