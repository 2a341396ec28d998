import { ParseError } from './parse-error.ts';
import { columnProblem, type Table } from './table.ts';

/**
 * The one CSV reader: of exports (`phasebook spectrum`, the tests), of
 * initial states (`--initial-file`), of anything a spreadsheet, pandas or
 * numpy wrote.
 *
 * **Records** are RFC 4180's: fields separated by commas, records by LF or
 * CRLF, and a field in double quotes may hold commas, line breaks and
 * doubled quotes (`""` for one). Spreadsheets and pandas quote a header
 * (`"q","p"`), or every field, as readily as not. A quote inside an unquoted
 * field, or text after a closing quote, is refused rather than guessed at.
 * A byte-order mark is skipped, blank lines at the end are not records, and
 * every record knows the line it starts on, so that an error can name it.
 *
 * **Numbers** (`csvNumber`, after spaces around the field are dropped):
 * - decimals with an optional sign, point and exponent: `[+-]?(d+[.d*]|.d+)([eE][+-]?d+)?`,
 *   which covers JS's shortest round trip (`String(x)`: `1e+21`, `5e-324`,
 *   `-0` as roundTripNumber writes it), Python's repr, numpy.savetxt,
 *   C's `%g`, `%e` and `%f`, and R;
 * - `NaN` and `Infinity` in any case, with an optional sign, and `inf` for
 *   Infinity (numpy and C write `nan`, `inf`, `-inf`; glibc writes `-nan`):
 *   a trajectory that blew up is worth reading back; the sign of a NaN is lost.
 * Nothing else: not an empty field, hexadecimal, a decimal comma, `NA`, or
 * `1_000`, each of which `Number()` would read as something or zero.
 */

/** One record: its fields, unquoted, and the 1-based line it starts on. */
export interface CsvRecord {
  fields: string[];
  line: number;
}

const DECIMAL = /^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$/;
const NOT_A_NUMBER = /^[+-]?nan$/i;
const INFINITE = /^([+-]?)inf(?:inity)?$/i;

/** The number a field spells, by the grammar above, or undefined. Spaces around it are the caller's to drop. */
export function csvNumber(field: string): number | undefined {
  if (DECIMAL.test(field)) return Number(field);
  if (NOT_A_NUMBER.test(field)) return NaN;
  const inf = INFINITE.exec(field);
  if (inf !== null) return inf[1] === '-' ? -Infinity : Infinity;
  return undefined;
}

const isBlank = (fields: readonly string[]) => fields.every((f) => f.trim() === '');

/** Newlines in text[from, to). */
function newlines(text: string, from: number, to: number): number {
  let n = 0;
  for (let i = text.indexOf('\n', from); i !== -1 && i < to; i = text.indexOf('\n', i + 1)) n++;
  return n;
}

/**
 * A record with quoted fields, from `at` (its first character), which may
 * run over several lines. Returns its fields and where the next record starts.
 */
function quotedRecord(text: string, at: number, line: number): { fields: string[]; next: number; lines: number } {
  const fields: string[] = [];
  let lines = 0;
  for (;;) {
    let i = at;
    while (text[i] === ' ' || text[i] === '\t') i++;
    if (text[i] === '"') {
      // Spaces before and after a quoted field (`q, "p" `) are padding, as they are around unquoted ones.
      const opened = line + lines;
      let value = '';
      let j = i + 1;
      for (;;) {
        const quote = text.indexOf('"', j);
        if (quote < 0) throw new ParseError('a quoted field opens here and is never closed', opened);
        value += text.slice(j, quote);
        lines += newlines(text, j, quote);
        if (text[quote + 1] !== '"') {
          j = quote + 1;
          break;
        }
        value += '"';
        j = quote + 2;
      }
      while (text[j] === ' ' || text[j] === '\t') j++;
      const c = text[j];
      if (j < text.length && c !== ',' && c !== '\n' && !(c === '\r' && text[j + 1] === '\n')) {
        throw new ParseError('text after a closing quote', line + lines);
      }
      fields.push(value);
      at = j;
    } else {
      let j = at;
      while (j < text.length && text[j] !== ',' && text[j] !== '\n') {
        if (text[j] === '"') throw new ParseError('a quote inside a field: a field with quotes must be quoted whole ("a ""b""")', line + lines);
        j++;
      }
      fields.push(text.slice(at, text[j] === '\n' && text[j - 1] === '\r' ? j - 1 : j));
      at = j;
    }
    if (at >= text.length) return { fields, next: at, lines };
    if (text[at] === ',') {
      at++;
      continue;
    }
    return { fields, next: at + (text[at] === '\r' ? 2 : 1), lines: lines + 1 };
  }
}

/** The records of CSV text, one by one; throws a ParseError naming the line of bad quoting. */
export function* csvRecords(text: string): Generator<CsvRecord> {
  let at = text.charCodeAt(0) === 0xfeff ? 1 : 0;
  let line = 1;
  let quoteAt = text.indexOf('"', at);
  // Blank records are held back until a record follows them: at the end they are no records at all.
  const blanks: CsvRecord[] = [];
  while (at < text.length) {
    let end = text.indexOf('\n', at);
    if (end < 0) end = text.length;
    let record: CsvRecord;
    let blank: boolean;
    if (quoteAt < 0 || quoteAt >= end) {
      // The common case, a line without quotes: a plain split.
      const body = text.slice(at, text[end - 1] === '\r' && end < text.length ? end - 1 : end);
      record = { fields: body.split(','), line };
      blank = isBlank(record.fields);
      at = end + 1;
      line++;
    } else {
      const { fields, next, lines } = quotedRecord(text, at, line);
      record = { fields, line };
      // A quoted field, even an empty one, was written on purpose: its record is not blank.
      blank = false;
      at = next;
      line += lines;
      quoteAt = text.indexOf('"', at);
    }
    if (blank) {
      blanks.push(record);
      continue;
    }
    yield* blanks.splice(0);
    yield record;
  }
}

/**
 * A table as the exporters write it (csv.ts): a header naming the columns,
 * then rows of numbers. Every deviation is a ParseError that names the line,
 * because these files are often edited by hand before
 * `phasebook spectrum --input` reads them.
 */
export function parseCSV(text: string): Table {
  const records = csvRecords(text);
  const head = records.next();
  if (head.done) throw new ParseError('empty input: expected a header line', 1);
  const columns = head.value.fields.map((s) => s.trim());
  const problem = columnProblem(columns);
  if (problem !== undefined) throw new ParseError(`header: ${problem}`, head.value.line);
  const width = columns.length;
  let data = new Float64Array(1024);
  let n = 0;
  for (const { fields, line } of records) {
    if (fields.length !== width) {
      const what = isBlank(fields) ? 'blank line' : `${fields.length} values`;
      throw new ParseError(`expected ${width} values (${columns.join(',')}), found ${what}`, line);
    }
    if (n + width > data.length) {
      const grown = new Float64Array(Math.max(data.length * 2, n + width));
      grown.set(data);
      data = grown;
    }
    for (let j = 0; j < width; j++) {
      const field = fields[j].trim();
      const x = csvNumber(field);
      if (x === undefined) throw new ParseError(`column ${columns[j]}: ${JSON.stringify(field)} is not a number`, line);
      data[n++] = x;
    }
  }
  return { columns, rows: n / width, data: data.slice(0, n) };
}
