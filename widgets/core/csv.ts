import { ParseError } from './parse-error.ts';
import { columnProblem, type Table } from './table.ts';

/**
 * CSV export and import of sampled trajectories.
 *
 * Numbers are written with JS's shortest round-trip formatting (`String(x)`),
 * so every double reads back bit-identical (NaN payloads aside), except that
 * -0 is written as `-0` because `String(-0)` is "0". Non-finite values are
 * written as `NaN`, `Infinity` and `-Infinity` rather than refused: a
 * trajectory that blew up is worth exporting, and the words read back exactly.
 * The reader also accepts `nan`/`inf`/`-inf` in any case, as NumPy writes them.
 *
 * Column names may not contain commas, quotes or line breaks, so no field is
 * ever quoted and the reader can stay a plain split.
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

const DECIMAL = /^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$/;
const INFINITE = /^([+-]?)inf(?:inity)?$/i;

/** Reads one field, or returns undefined if it is not a number. */
function parseField(field: string): number | undefined {
  if (DECIMAL.test(field)) return Number(field);
  if (/^nan$/i.test(field)) return NaN;
  const inf = INFINITE.exec(field);
  if (inf !== null) return inf[1] === '-' ? -Infinity : Infinity;
  return undefined;
}

/**
 * Parses CSV as written by toCSV, tolerating `\r\n` line ends, spaces around
 * fields and trailing blank lines. Any other deviation is a ParseError that
 * names the line, because these files are often edited by hand before
 * `phasebook spectrum --input` reads them.
 */
export function parseCSV(text: string): Table {
  const lines = text.split('\n');
  let end = lines.length;
  while (end > 0 && lines[end - 1].trim() === '') end--;
  if (end === 0) throw new ParseError('empty input: expected a header line', 1);
  const start = lines[0].charCodeAt(0) === 0xfeff ? 1 : 0; // byte-order mark
  const columns = lines[0].slice(start).split(',').map((s) => s.trim());
  const problem = columnProblem(columns);
  if (problem !== undefined) throw new ParseError(`header: ${problem}`, 1);
  for (const name of columns) {
    if (name.includes('"')) throw new ParseError(`header: quoted column names are not supported`, 1);
  }
  const width = columns.length;
  const rows = end - 1;
  const data = new Float64Array(rows * width);
  for (let i = 0; i < rows; i++) {
    const line = lines[i + 1];
    const fields = line.split(',');
    if (fields.length !== width) {
      const what = line.trim() === '' ? 'blank line' : `${fields.length} values`;
      throw new ParseError(`expected ${width} values (${columns.join(',')}), found ${what}`, i + 2);
    }
    for (let j = 0; j < width; j++) {
      const field = fields[j].trim();
      const x = parseField(field);
      if (x === undefined) {
        throw new ParseError(`column ${columns[j]}: ${JSON.stringify(field)} is not a number`, i + 2);
      }
      data[i * width + j] = x;
    }
  }
  return { columns, rows, data };
}
