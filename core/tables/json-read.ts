import type { ExportMeta } from './export-meta.ts';
import { JsonCursor, type JsonValue } from './json-scan.ts';
import { ParseError } from './parse-error.ts';
import { columnProblem, type Table } from './table.ts';

/** Reads one data value: a number, a non-finite word as jsonNumber writes it, or null for NaN. */
function readValue(cur: JsonCursor): number {
  const c = cur.peek();
  if (c === 'n' && cur.acceptWord('null')) return NaN;
  if (c !== '"') return cur.number();
  const at = cur.pos;
  const word = cur.string();
  if (word === 'NaN') return NaN;
  if (word === 'Infinity') return Infinity;
  if (word === '-Infinity') return -Infinity;
  return cur.fail(`${JSON.stringify(word)} is not a number`, at);
}

/** Where a part of the export was found. */
export interface Found<T> {
  value: T;
  line: number;
}

/**
 * The one reader of the book's JSON export, `{"meta": …, "columns": […],
 * "data": [[…], …]}` as json.ts writes it, or as anyone lays it out, in any
 * key order: the page's export, `simulate`'s and `merge`'s files, `spectrum`'s
 * input. It reads the parts in the order the text holds them, a row of data
 * at a time, so the text may come in pieces (JsonCursor) and a file of any
 * size reads in flat memory. A data value is a JSON number, one of the words
 * jsonNumber writes for non-finite values ("NaN", "Infinity", "-Infinity"),
 * or null for NaN. Errors are ParseErrors naming the line.
 *
 * `head()` reads up to the first row; meta and columns are there if they
 * come before the data, as they do in every file phasebook writes. `row()`
 * then gives the rows, and after the last reads the rest of the object.
 * The meta is returned as it is: each reader of it checks what it needs.
 */
export class JsonExportReader {
  meta?: Found<JsonValue>;
  columns?: Found<string[]>;
  /** the line "data" is on, once read */
  dataLine = 0;
  /** rows read so far */
  rows = 0;
  /** values in each row: the columns' count when they came first, else the first row's */
  width = -1;
  private readonly cur: JsonCursor;
  private state: 'start' | 'head' | 'data' | 'done' = 'start';
  private rowAt = 0;

  constructor(text: string, more?: () => string | undefined) {
    this.cur = new JsonCursor(text, more);
    if (this.cur.peek() === '\ufeff') this.cur.pos++; // byte-order mark
  }

  /** Reads the object's keys up to the data's first row, or to its end. */
  head(): this {
    if (this.state === 'start') {
      this.cur.expect('{', 'a JSON object "{"');
      this.state = 'head';
      if (this.cur.accept('}')) this.close();
      else this.keys();
    }
    return this;
  }

  /** The next row of data into `into`, or false once the data has ended and the rest of the object is read. */
  row(into: number[]): boolean {
    this.head();
    if (this.state !== 'data') return false;
    const cur = this.cur;
    if (this.rows > 0 ? !cur.accept(',') : cur.accept(']')) {
      if (this.rows > 0) cur.expect(']', '"," or "]" after a row');
      this.afterData();
      return false;
    }
    cur.release();
    cur.peek(); // so that rowAt is the row's own line, not the end of the previous one
    this.rowAt = cur.pos;
    cur.expect('[', 'a row "["');
    into.length = 0;
    if (!cur.accept(']')) {
      do into.push(readValue(cur));
      while (cur.accept(','));
      cur.expect(']', '"," or "]" in a row');
    }
    if (this.width < 0) this.width = into.length;
    if (into.length !== this.width) cur.fail(`data row ${this.rows} has ${into.length} values, expected ${this.width}`, this.rowAt);
    this.rows++;
    return true;
  }

  /** The line of the row last read, for a reader's own complaint about it. */
  rowLine(): number {
    return this.cur.lineAt(this.rowAt);
  }

  /** Keys, until "data" opens (its rows are row()'s to read) or the object ends. */
  private keys(): void {
    const cur = this.cur;
    do {
      cur.peek();
      const keyAt = cur.pos;
      const key = cur.string();
      cur.expect(':');
      const line = cur.lineAt(keyAt);
      if ((key === 'meta' && this.meta) || (key === 'columns' && this.columns) || (key === 'data' && this.dataLine > 0)) {
        cur.fail(`duplicate key "${key}"`, keyAt);
      }
      if (key === 'data') {
        this.dataLine = line;
        cur.expect('[', '"[" to open data');
        if (this.columns) this.width = this.columns.value.length;
        this.state = 'data';
        return;
      }
      const v = cur.value();
      if (key === 'meta') this.meta = { value: v, line };
      else if (key === 'columns') {
        if (!Array.isArray(v) || !v.every((x): x is string => typeof x === 'string')) {
          throw new ParseError('columns must be an array of strings', line);
        }
        const problem = columnProblem(v);
        if (problem !== undefined) throw new ParseError(`columns: ${problem}`, line);
        this.columns = { value: v, line };
      }
    } while (cur.accept(','));
    this.cur.expect('}', '"," or "}"');
    this.close();
  }

  /** After the data's closing bracket: the keys that follow it, if any. */
  private afterData(): void {
    this.state = 'head';
    if (this.cur.accept(',')) this.keys();
    else {
      this.cur.expect('}', '"," or "}"');
      this.close();
    }
  }

  /** The object has ended: nothing may follow, and rows read before the columns must fit them. */
  private close(): void {
    this.cur.end();
    this.state = 'done';
    const { columns } = this;
    if (columns && this.rows > 0 && this.width !== columns.value.length) {
      throw new ParseError(`data rows have ${this.width} values but there are ${columns.value.length} columns`, this.dataLine);
    }
  }
}

type Kind = 'string' | 'number' | 'string[]' | 'number[]' | 'numbers';
const REQUIRED: ReadonlyArray<[string, Kind]> = [
  ['hamiltonian', 'string'], ['params', 'numbers'], ['dof', 'number'], ['dt', 'number'], ['method', 'string'],
  ['every', 'number'], ['t0', 'number'], ['initial', 'number[]'], ['version', 'string'],
];
const OPTIONAL: ReadonlyArray<[string, Kind]> = [
  ['route', 'string'], ['names', 'string[]'], ['derived', 'string[]'], ['count', 'number'], ['dropped', 'number'],
  ['rtol', 'number'], ['atol', 'number'],
];

function isKind(v: JsonValue, kind: Kind): boolean {
  if (kind === 'string' || kind === 'number') return typeof v === kind;
  if (kind === 'numbers') {
    return typeof v === 'object' && v !== null && !Array.isArray(v) && Object.values(v).every((x) => typeof x === 'number');
  }
  const item = kind === 'string[]' ? 'string' : 'number';
  return Array.isArray(v) && v.every((x) => typeof x === item);
}

/** Checks meta against ExportMeta, so callers can trust the type they get back. */
function checkMeta(v: JsonValue, line: number): ExportMeta {
  if (typeof v !== 'object' || v === null || Array.isArray(v)) throw new ParseError('meta must be an object', line);
  // A dataset of sampled or gridded states says how to make them (initialSet) instead of listing them.
  const described = typeof v.initialSet === 'object' && v.initialSet !== null;
  for (const [key, kind] of REQUIRED) {
    if (key === 'initial' && described && !(key in v)) continue;
    if (!(key in v)) throw new ParseError(`meta.${key} is missing`, line);
    if (!isKind(v[key], kind)) throw new ParseError(`meta.${key} must be ${kind === 'numbers' ? 'an object of numbers' : `a ${kind}`}`, line);
  }
  for (const [key, kind] of OPTIONAL) {
    if (key in v && !isKind(v[key], kind)) throw new ParseError(`meta.${key} must be a ${kind}`, line);
  }
  return v as ExportMeta;
}

/**
 * Parses an export written by toJSON (or by hand, in any key order and
 * layout) into memory. Errors are ParseErrors naming the line.
 */
export function parseJSON(text: string): { meta: ExportMeta; table: Table } {
  const reader = new JsonExportReader(text).head();
  let data = new Float64Array(1024);
  let n = 0;
  const row: number[] = [];
  while (reader.row(row)) {
    if (n + row.length > data.length) {
      const grown = new Float64Array(Math.max(data.length * 2, n + row.length));
      grown.set(data);
      data = grown;
    }
    for (const v of row) data[n++] = v;
  }
  if (!reader.meta) throw new ParseError('no "meta" object', 1);
  if (!reader.columns) throw new ParseError('no "columns" array', 1);
  if (reader.dataLine === 0) throw new ParseError('no "data" array', 1);
  const meta = checkMeta(reader.meta.value, reader.meta.line);
  return { meta, table: { columns: reader.columns.value, rows: reader.rows, data: data.slice(0, n) } };
}
