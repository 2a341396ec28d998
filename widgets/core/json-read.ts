import type { ExportMeta } from './export-meta.ts';
import { JsonCursor, type JsonValue } from './json-scan.ts';
import { ParseError } from './parse-error.ts';
import { columnProblem, type Table } from './table.ts';

/** Reads one data value: a number, a non-finite word as jsonNumber writes it, or null for NaN. */
function readValue(cur: JsonCursor): number {
  const c = cur.peek();
  if (c === 'n' && cur.text.startsWith('null', cur.pos)) {
    cur.pos += 4;
    return NaN;
  }
  if (c !== '"') return cur.number();
  const at = cur.pos;
  const word = cur.string();
  if (word === 'NaN') return NaN;
  if (word === 'Infinity') return Infinity;
  if (word === '-Infinity') return -Infinity;
  return cur.fail(`${JSON.stringify(word)} is not a number`, at);
}

/**
 * Reads the data array straight into a growing Float64Array. The width is the
 * column count when columns came first (as we write them), else the first row's.
 */
function readData(cur: JsonCursor, width: number): { data: Float64Array; rows: number; width: number } {
  let data = new Float64Array(1024);
  let n = 0;
  let rows = 0;
  cur.expect('[', '"[" to open data');
  if (!cur.accept(']')) {
    do {
      cur.peek(); // so that rowAt is the row's own line, not the end of the previous one
      const rowAt = cur.pos;
      cur.expect('[', 'a row "["');
      const start = n;
      if (!cur.accept(']')) {
        do {
          if (n === data.length) {
            const grown = new Float64Array(data.length * 2);
            grown.set(data);
            data = grown;
          }
          data[n++] = readValue(cur);
        } while (cur.accept(','));
        cur.expect(']', '"," or "]" in a row');
      }
      if (width < 0) width = n - start;
      if (n - start !== width) cur.fail(`data row ${rows} has ${n - start} values, expected ${width}`, rowAt);
      rows++;
    } while (cur.accept(','));
    cur.expect(']', '"," or "]" after a row');
  }
  return { data: data.slice(0, n), rows, width };
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
 * layout). Errors are ParseErrors naming the line.
 */
export function parseJSON(text: string): { meta: ExportMeta; table: Table } {
  const cur = new JsonCursor(text);
  if (text.charCodeAt(0) === 0xfeff) cur.pos = 1; // byte-order mark
  let meta: ExportMeta | undefined;
  let columns: string[] | undefined;
  let body: { data: Float64Array; rows: number; width: number } | undefined;
  let dataLine = 1;
  cur.expect('{', 'a JSON object "{"');
  if (!cur.accept('}')) {
    do {
      cur.peek();
      const keyAt = cur.pos;
      const key = cur.string();
      cur.expect(':');
      const line = cur.lineAt(keyAt);
      if ((key === 'meta' && meta) || (key === 'columns' && columns) || (key === 'data' && body)) {
        cur.fail(`duplicate key "${key}"`, keyAt);
      }
      if (key === 'data') {
        dataLine = line;
        body = readData(cur, columns ? columns.length : -1);
        continue;
      }
      const v = cur.value();
      if (key === 'meta') meta = checkMeta(v, line);
      else if (key === 'columns') {
        if (!Array.isArray(v) || !v.every((x): x is string => typeof x === 'string')) {
          throw new ParseError('columns must be an array of strings', line);
        }
        const problem = columnProblem(v);
        if (problem !== undefined) throw new ParseError(`columns: ${problem}`, line);
        columns = v;
      }
    } while (cur.accept(','));
    cur.expect('}', '"," or "}"');
  }
  cur.end();
  if (!meta) throw new ParseError('no "meta" object', 1);
  if (!columns) throw new ParseError('no "columns" array', 1);
  if (!body) throw new ParseError('no "data" array', 1);
  if (body.rows > 0 && body.width !== columns.length) {
    throw new ParseError(`data rows have ${body.width} values but there are ${columns.length} columns`, dataLine);
  }
  return { meta, table: { columns, rows: body.rows, data: body.data } };
}
