/**
 * `--initial-file FILE`: one initial state per trajectory, as
 * - CSV (RFC 4180, quoted fields too): a row per trajectory, with a header
 *   naming the state's components in any order, or no header and the
 *   components in the state's order;
 * - NPY: an array of shape (M, 2n), or (2n,) for one, of any float or int dtype;
 * - JSON: an array of rows, each an array in the state's order or an object
 *   by name.
 * The format is told by the name's extension (.csv, .npy, .json), or else
 * by the content. Every value must be a finite number. CSV and JSON are read
 * by the core's readers (csv-read.ts, json-scan.ts), whose errors name the
 * line, with the file's name before it.
 */
import { readFileSync } from 'node:fs';
import { basename } from 'node:path';
import { csvNumber, csvRecords, InputError, ParseError, parseJsonValue, type CsvRecord } from '../../core/index.ts';
import { numericDtype, parseNpyHeader } from '../formats/npy.ts';
import { resolveName } from './ranges.ts';

/** The states, trajectory after trajectory, in the order of `names`. */
export function readInitialFile(path: string, names: readonly string[]): number[] {
  let bytes: Buffer;
  try {
    bytes = readFileSync(path);
  } catch (error) {
    const code = (error as NodeJS.ErrnoException).code;
    const why = code === 'ENOENT' ? 'no such file' : code === 'EISDIR' ? 'it is a directory' : code === 'EACCES' ? 'permission denied' : (code ?? (error as Error).message);
    throw new InputError(`cannot read --initial-file ${path}: ${why}`);
  }
  const what = `--initial-file ${basename(path)}`;
  const isNpy = /\.npy$/i.test(path) || (bytes[0] === 0x93 && bytes.subarray(1, 6).toString('latin1') === 'NUMPY');
  const values = isNpy ? fromNpy(bytes, names, what) : fromText(bytes, names, what, path);
  if (values.length === 0) throw new InputError(`${what} holds no initial states`);
  return values;
}

function fromNpy(bytes: Buffer, names: readonly string[], what: string): number[] {
  const header = parseNpyHeader(bytes, what);
  const dtype = numericDtype(header.descr);
  if (!dtype) throw new InputError(`${what} has dtype ${header.descr}; initial states must be floats or integers`);
  const dim = names.length;
  const { shape } = header;
  const rows = shape.length === 1 ? 1 : shape[0];
  if (!((shape.length === 1 && shape[0] === dim) || (shape.length === 2 && shape[1] === dim))) {
    throw new InputError(`${what} has shape (${shape.join(', ')}); it needs (M, ${dim}) for the state ${names.join(', ')}`);
  }
  const need = header.dataOffset + rows * dim * dtype.size;
  if (bytes.length < need) throw new InputError(`${what} is cut short: ${bytes.length} bytes of the ${need} its header announces`);
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const out = new Array<number>(rows * dim);
  for (let i = 0; i < rows; i++) {
    for (let c = 0; c < dim; c++) {
      const element = header.fortranOrder ? c * rows + i : i * dim + c;
      const v = dtype.read(view, header.dataOffset + element * dtype.size);
      if (!Number.isFinite(v)) throw new InputError(`${what}: row ${i + 1}, ${names[c]} is ${v}, not a finite number`);
      out[i * dim + c] = v;
    }
  }
  return out;
}

function fromText(bytes: Buffer, names: readonly string[], what: string, path: string): number[] {
  if (bytes.includes(0)) throw new InputError(`${what} is not text; give CSV, JSON or NPY`);
  const text = bytes.toString('utf8').replace(/^\uFEFF/, '');
  const json = /\.json$/i.test(path) || /^\s*[[{]/.test(text);
  return json ? fromJson(text, names, what) : fromCsv(text, names, what);
}

function finite(value: unknown, what: string, row: number, name: string): number {
  const v = typeof value === 'string' && value.trim() !== '' ? Number(value) : value;
  if (typeof v !== 'number' || !Number.isFinite(v)) throw new InputError(`${what}: row ${row}, ${name} is ${JSON.stringify(value) ?? String(value)}, not a finite number`);
  return v;
}

function fromJson(text: string, names: readonly string[], what: string): number[] {
  const data = inFile(what, () => parseJsonValue(text));
  if (!Array.isArray(data)) throw new InputError(`${what} must hold an array of initial states (one per trajectory)`);
  // A single state written as one array of numbers.
  const rows = data.length > 0 && data.every((v) => typeof v === 'number') ? [data] : data;
  const dim = names.length;
  const out: number[] = [];
  rows.forEach((row: unknown, i: number) => {
    if (Array.isArray(row)) {
      if (row.length !== dim) throw new InputError(`${what}: row ${i + 1} has ${row.length} values; the state ${names.join(', ')} needs ${dim}`);
      row.forEach((v, c) => out.push(finite(v, what, i + 1, names[c])));
    } else if (row !== null && typeof row === 'object') {
      const keyed = byName(Object.keys(row), names, what);
      keyed.forEach((key, c) => out.push(finite((row as Record<string, unknown>)[key], what, i + 1, names[c])));
    } else throw new InputError(`${what}: row ${i + 1} is neither an array nor an object`);
  });
  return out;
}

/** What `read` returns, or its ParseError said of the file `what`. */
function inFile<T>(what: string, read: () => T): T {
  try {
    return read();
  } catch (error) {
    throw error instanceof ParseError && error.source === undefined ? error.withSource(what) : error;
  }
}

/** The key for each state name, from the keys given; any other key, or one missing, is an error. */
function byName(keys: readonly string[], names: readonly string[], what: string): string[] {
  const found = new Map<string, string>();
  for (const key of keys) {
    const name = resolveName(key.trim(), names);
    if (!name) throw new InputError(`${what} has a column ${JSON.stringify(key)}, which is not a component of the state (${names.join(', ')})`);
    if (found.has(name)) throw new InputError(`${what} gives ${name} twice`);
    found.set(name, key);
  }
  const absent = names.filter((n) => !found.has(n));
  if (absent.length) throw new InputError(`${what} has no column for ${absent.join(', ')}; the state is ${names.join(', ')}`);
  return names.map((n) => found.get(n)!);
}

function fromCsv(text: string, names: readonly string[], what: string): number[] {
  const records: CsvRecord[] = inFile(what, () => Array.from(csvRecords(text)));
  if (records.length === 0) throw new InputError(`${what} is empty`);
  const first = records[0].fields.map((s) => s.trim());
  // A first record that is not all finite numbers names the columns.
  const headed = first.some((f) => !Number.isFinite(csvNumber(f) ?? NaN));
  const dim = names.length;
  let order = names.map((_, c) => c);
  if (headed) {
    if (first.length !== dim) {
      throw new InputError(`${what} has the columns ${first.join(', ')}; the state needs exactly ${names.join(', ')}`);
    }
    const keys = byName(first, names, what);
    order = keys.map((key) => first.indexOf(key));
  }
  const out: number[] = [];
  for (const { fields, line } of headed ? records.slice(1) : records) {
    if (fields.length !== dim) throw new ParseError(`${fields.length} values, where the state ${names.join(', ')} needs ${dim}`, line, what);
    for (let c = 0; c < dim; c++) {
      const field = fields[order[c]].trim();
      const v = csvNumber(field);
      if (v === undefined || !Number.isFinite(v)) throw new ParseError(`${names[c]} is ${JSON.stringify(field)}, not a finite number`, line, what);
      out.push(v);
    }
  }
  return out;
}
