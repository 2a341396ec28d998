/**
 * Reading back a dataset file this CLI wrote, as JSON, NPZ or Parquet: its
 * meta, and its numbers as the blocks they were written from, a chunk of
 * rows at a time so that any size reads in flat memory. Merge re-writes
 * them; reproduce compares them with a fresh run. CSV carries no meta, so it
 * can be neither checked nor reproduced.
 *
 * A file is data from whoever made it. Its meta's shape is checked before it
 * is used, every block it yields is checked against that shape (a row with a
 * value missing once went into a merge as "undefined"), and every message
 * names the file: a parser's own error (hyparquet's "thrift unhandled type")
 * is said as the file's damage.
 */
import { closeSync, openSync, readSync } from 'node:fs';
import { parquetMetadataAsync, parquetRead } from 'hyparquet';
import { InputError } from '../../core/index.ts';
import { namingFile } from '../file-errors.ts';
import type { DatasetMeta } from '../dataset-meta.ts';
import type { Block, DatasetShape } from './dataset-shape.ts';
import { parseNpyHeader } from './npy.ts';
import { readAt, zipEntries, type ZipEntry } from './zip-reader.ts';

export interface DatasetFile {
  path: string;
  format: 'json' | 'npz' | 'parquet';
  meta: DatasetMeta;
  shape: DatasetShape;
  /** the sample times (an NPZ has them apart from its rows) */
  times?: Float64Array;
  /** the file's blocks in the order it holds them, at most about `values` numbers each */
  blocks(values: number): AsyncGenerator<Block>;
  close(): void;
}

const MAGIC_ZIP = 0x04034b50;

/** Opens `path`, telling its format by its first bytes. */
export async function openDataset(path: string): Promise<DatasetFile> {
  let fd: number;
  try {
    fd = openSync(path, 'r');
  } catch (error) {
    const code = (error as NodeJS.ErrnoException).code;
    throw new InputError(`cannot read ${path}: ${code === 'ENOENT' ? 'no such file' : code === 'EISDIR' ? 'it is a directory' : (code ?? (error as Error).message)}`);
  }
  try {
    return checked(await openFormat(path, fd));
  } catch (error) {
    closeSync(fd);
    throw namingFile(error, path, true);
  }
}

async function openFormat(path: string, fd: number): Promise<DatasetFile> {
  const head = readAt(fd, 0, 4);
  if (head.length === 4 && head.readUInt32LE(0) === MAGIC_ZIP) return openNpz(path, fd);
  if (head.toString('latin1') === 'PAR1') return await openParquet(path, fd);
  if (head.toString('latin1').trimStart().startsWith('{')) return openJson(path, fd);
  throw new InputError(`${path} is not a dataset with its meta: give the JSON, NPZ or Parquet file of a phasebook run (CSV keeps no meta)`);
}

const isWhole = (v: unknown, least = 0): v is number => typeof v === 'number' && Number.isSafeInteger(v) && v >= least;
const isNames = (v: unknown): v is string[] => Array.isArray(v) && v.every((s) => typeof s === 'string');

/** The meta, checked for what reading the file relies on: its rows' columns and how many there are. */
function checkMeta(meta: unknown, path: string): DatasetMeta {
  const m = meta as Record<string, unknown> | undefined;
  if (!m || typeof m !== 'object' || !isWhole(m.samples) || !isNames(m.columns) || !isWhole(m.count) || !m.initialSet) {
    throw new InputError(`${path} was not written by a phasebook run with a dataset's meta (no samples, columns or initialSet in it)`);
  }
  const bad = (why: string) => new InputError(`${path}: its meta ${why}`);
  const names = m.names;
  if (!isNames(names) || names.length === 0 || names.length % 2 !== 0) throw bad('lists no state names');
  const columns = m.columns;
  if (columns[0] !== 't' || names.some((name, i) => columns[1 + i] !== name)) throw bad(`gives columns (${columns.join(', ')}) that are not t and the state ${names.join(', ')}`);
  if (!isWhole(m.trajectories) || m.trajectories < m.count) throw bad(`counts ${String(m.trajectories)} trajectories in the set, fewer than the ${m.count} it holds`);
  const shard = m.shard as Record<string, unknown> | undefined;
  if (shard !== undefined && (typeof shard !== 'object' || shard === null || !isWhole(shard.first) || !isWhole(shard.index, 1) || !isWhole(shard.of, 1))) {
    throw bad('describes its shard wrongly');
  }
  if (shard !== undefined && (shard.first as number) + m.count > m.trajectories) throw bad('holds trajectories past the end of its set');
  return m as unknown as DatasetMeta;
}

/** The meta's JSON text, parsed; `where` says where in the file it is. */
function parseMeta(text: string, path: string, where: string): DatasetMeta {
  let meta: unknown;
  try {
    meta = JSON.parse(text);
  } catch (error) {
    throw new InputError(`${path}: the meta ${where} is not JSON (${(error as Error).message})`);
  }
  return checkMeta(meta, path);
}

function shapeOf(meta: DatasetMeta): DatasetShape {
  return { columns: meta.columns, names: meta.names ?? [], count: meta.count, first: meta.shard?.first ?? 0, total: meta.trajectories, samples: meta.samples };
}

/**
 * The file with its blocks checked against its shape as they come: each
 * block exactly as many numbers as its rows, the trajectories in order with
 * every sample once, nothing after the last; a reading error names the file.
 */
function checked(file: DatasetFile): DatasetFile {
  const { shape, path } = file;
  const width = shape.columns.length;
  const bad = (why: string) => new InputError(`${path}: ${why}`);
  const wide = file.format === 'parquet' && file.meta.layout === 'wide';
  async function* blocks(values: number): AsyncGenerator<Block> {
    const end = shape.first + shape.count;
    let trajectory = shape.first;
    let row = 0;
    try {
      for await (const block of file.blocks(values)) {
        const { first, count, rowFrom, rowTo, data } = block;
        if (!data || data.length !== count * (rowTo - rowFrom) * width) throw bad(`a block of rows ${rowFrom}–${rowTo} does not hold ${width} values a row`);
        if (wide) {
          if (first !== shape.first || count !== shape.count || rowFrom !== row || rowTo > shape.samples) throw bad(`its rows after ${row} are not the next of its ${shape.samples} samples`);
          row = rowTo;
        } else {
          const whole = count > 1;
          if (first !== trajectory || first + count > end || rowFrom !== row || rowTo <= rowFrom || rowTo > shape.samples || (whole && (rowFrom !== 0 || rowTo !== shape.samples))) {
            throw bad(`its rows of trajectory ${first} (samples ${rowFrom}–${rowTo}) are not the next it should hold: trajectory ${trajectory} from sample ${row}, ${shape.samples} samples each`);
          }
          row = rowTo === shape.samples ? 0 : rowTo;
          if (row === 0) trajectory = first + count;
        }
        yield block;
      }
    } catch (error) {
      throw namingFile(error, path, true);
    }
    const complete = wide ? shape.count === 0 || row === shape.samples : trajectory === end && row === 0;
    if (!complete) throw bad(`it ends before its last rows: ${shape.count} trajectories of ${shape.samples} samples are due`);
  }
  return { ...file, blocks };
}

/** Lines of a text file, read a megabyte at a time. */
function* lines(fd: number): Generator<string> {
  const buffer = Buffer.alloc(1 << 20);
  let rest = '';
  let position = 0;
  for (;;) {
    const n = readSync(fd, buffer, 0, buffer.length, position);
    if (n === 0) break;
    position += n;
    const text = rest + buffer.toString('utf8', 0, n);
    const parts = text.split('\n');
    rest = parts.pop()!;
    yield* parts;
  }
  if (rest) yield rest;
}

function openJson(path: string, fd: number): DatasetFile {
  const iterator = lines(fd);
  const first = iterator.next();
  const head = first.done ? '' : first.value;
  if (!head.startsWith('{"meta":') || !head.endsWith(',')) throw new InputError(`${path} is not a JSON export of phasebook: its first line holds no meta`);
  const meta = parseMeta(head.slice(8, -1), path, 'on its first line');
  const shape = shapeOf(meta);
  const numbered = shape.total > 1;
  const width = shape.columns.length;
  const length = width + (numbered ? 1 : 0);
  return {
    path,
    format: 'json',
    meta,
    shape,
    async *blocks(values) {
      const chunk = Math.max(1, Math.floor(values / width));
      let line = 1;
      let block: { first: number; rows: number[]; rowFrom: number } | undefined;
      let trajectory = -1;
      const flush = function* () {
        if (!block || block.rows.length === 0) return;
        const n = block.rows.length / width;
        yield { first: block.first, count: 1, rowFrom: block.rowFrom, rowTo: block.rowFrom + n, data: Float64Array.from(block.rows) };
        block = { first: block.first, rows: [], rowFrom: block.rowFrom + n };
      };
      for (const text of iterator) {
        line++;
        if (line <= 3) continue; // "columns" and "data": [
        const trimmed = text.endsWith(',') ? text.slice(0, -1) : text;
        if (!trimmed.startsWith('[')) {
          // Only the closing ]} (and the last newline) follow the rows.
          if (trimmed.trim() === ']}' || trimmed.trim() === '') continue;
          throw new InputError(`${path}: line ${line} is neither a row of numbers nor the end of the data`);
        }
        const values = jsonRow(trimmed, length, path, line);
        const j = numbered ? values[0] : shape.first;
        if (j !== trajectory) {
          yield* flush();
          trajectory = j;
          block = { first: j, rows: [], rowFrom: 0 };
        }
        for (let c = numbered ? 1 : 0; c < length; c++) block!.rows.push(values[c]);
        if (block!.rows.length >= chunk * width) yield* flush();
      }
      yield* flush();
    },
    close: () => closeSync(fd),
  };
}

/** One row of a JSON export: `length` values, each a number or a non-finite one as the writer spells it (core/json.ts). */
function jsonRow(text: string, length: number, path: string, line: number): number[] {
  let row: unknown;
  try {
    row = JSON.parse(text);
  } catch {
    throw new InputError(`${path}: line ${line} is not a JSON row of numbers`);
  }
  if (!Array.isArray(row) || row.length !== length) {
    throw new InputError(`${path}: line ${line} has ${Array.isArray(row) ? row.length : 'no'} values; a row of this file has ${length}`);
  }
  return row.map((v, c) => {
    if (typeof v === 'number') return v;
    if (v === null || v === 'NaN') return NaN;
    if (v === 'Infinity' || v === '-Infinity') return Number(v);
    throw new InputError(`${path}: line ${line}, value ${c + 1} is ${JSON.stringify(v)}, not a number`);
  });
}

function openNpz(path: string, fd: number): DatasetFile {
  const entries = zipEntries(fd, path);
  const array = (name: string) => {
    const entry = entries.get(`${name}.npy`);
    if (!entry) return undefined;
    if (entry.method !== 0) throw new InputError(`${path}: ${name}.npy is compressed; phasebook reads the stored NPZ it writes`);
    const header = parseNpyHeader(readAt(fd, entry.dataOffset, Math.min(entry.size, 4096)), `${path}:${name}.npy`);
    return { entry, header, data: entry.dataOffset + header.dataOffset };
  };
  const metaArray = array('meta');
  if (!metaArray) throw new InputError(`${path} has no meta.npy: it was not written by phasebook`);
  const metaBytes = readAt(fd, metaArray.data, metaArray.entry.size - metaArray.header.dataOffset);
  let text = '';
  for (let i = 0; i + 4 <= metaBytes.length; i += 4) {
    const point = metaBytes.readUInt32LE(i);
    if (point > 0x10ffff) throw new InputError(`${path}: meta.npy holds a character code ${point}, which is none`);
    if (point !== 0) text += String.fromCodePoint(point);
  }
  const meta = parseMeta(text, path, 'in meta.npy');
  const shape = shapeOf(meta);
  const dim = shape.names.length;
  /** An array the meta says the file has, checked to be float64 of the shape the meta gives. */
  const needed = (name: string, dims: number[]) => {
    const found = array(name);
    if (!found) throw new InputError(`${path} has no ${name}.npy, which its meta's columns call for`);
    const { descr, shape: has, fortranOrder } = found.header;
    if (descr !== '<f8' || fortranOrder || has.length !== dims.length || has.some((d, i) => d !== dims[i])) {
      throw new InputError(`${path}: ${name}.npy is ${descr} of shape (${has.join(', ')}), not float64 of shape (${dims.join(', ')}) as its meta says`);
    }
    if (found.entry.size - found.header.dataOffset < 8 * dims.reduce((a, b) => a * b, 1)) throw new InputError(`${path}: ${name}.npy is cut short`);
    return found;
  };
  const t = needed('t', [shape.samples]);
  const times = new Float64Array(readAtAligned(fd, t.data, 8 * shape.samples));
  const parts: { a: NonNullable<ReturnType<typeof array>>; n: number }[] = [{ a: needed('x', [shape.count, shape.samples, dim]), n: dim }];
  for (const name of shape.columns.slice(1 + dim)) {
    if (name.endsWith('/dt')) continue;
    parts.push({ a: needed(name, [shape.count, shape.samples]), n: 1 });
  }
  if (shape.columns.some((c) => c.endsWith('/dt'))) parts.push({ a: needed('dxdt', [shape.count, shape.samples, dim]), n: dim });
  const width = shape.columns.length;
  return {
    path,
    format: 'npz',
    meta,
    shape,
    times,
    async *blocks(values) {
      const { samples } = shape;
      const perTrajectory = samples * width;
      const batch = perTrajectory <= values ? Math.max(1, Math.floor(values / perTrajectory)) : 1;
      const rows = perTrajectory <= values ? samples : Math.max(1, Math.floor(values / width));
      for (let j = 0; j < shape.count; j += batch) {
        const count = Math.min(batch, shape.count - j);
        for (let r0 = 0; r0 < samples; r0 += rows) {
          const r1 = Math.min(samples, r0 + rows);
          const span = r1 - r0;
          const data = new Float64Array(count * span * width);
          for (let k = 0; k < count; k++) {
            for (let r = 0; r < span; r++) data[(k * span + r) * width] = times[r0 + r];
            let column = 1;
            for (const { a, n } of parts) {
              const at = a.data + 8 * ((j + k) * samples * n + r0 * n);
              const piece = new Float64Array(readAtAligned(fd, at, 8 * span * n));
              for (let r = 0; r < span; r++) for (let c = 0; c < n; c++) data[(k * span + r) * width + column + c] = piece[r * n + c];
              column += n;
            }
          }
          yield { first: shape.first + j, count, rowFrom: r0, rowTo: r1, data };
        }
      }
    },
    close: () => closeSync(fd),
  };
}

/** Bytes read into a fresh ArrayBuffer, so that a Float64Array can view them. */
function readAtAligned(fd: number, position: number, length: number): ArrayBuffer {
  const bytes = readAt(fd, position, length);
  if (bytes.length < length) throw new InputError(`the file ends before its arrays do (at byte ${position + bytes.length})`);
  const out = new ArrayBuffer(length);
  new Uint8Array(out).set(bytes);
  return out;
}

async function openParquet(path: string, fd: number): Promise<DatasetFile> {
  const { size } = await import('node:fs').then((fs) => fs.fstatSync(fd));
  const file = {
    byteLength: size,
    slice: (start: number, end?: number) => readAtAligned(fd, start, (end ?? size) - start),
  };
  const metadata = await parquetMetadataAsync(file);
  const kv = metadata.key_value_metadata?.find((e) => e.key === 'phasebook');
  if (!kv?.value) throw new InputError(`${path} has no "phasebook" key in its metadata: it was not written by phasebook`);
  const meta = parseMeta(kv.value, path, 'under its "phasebook" key');
  const shape = shapeOf(meta);
  const wide = meta.layout === 'wide';
  const numbered = !wide && shape.total > 1;
  const width = shape.columns.length;
  // A row as the layout lays it out: t then every trajectory's columns (wide), or the trajectory's number then its columns (long).
  const rowLength = wide ? 1 + shape.count * (width - 1) : width + (numbered ? 1 : 0);
  const numbers = (row: unknown, at: number): number[] => {
    if (!Array.isArray(row) || row.length !== rowLength || !row.every((v) => typeof v === 'number')) {
      throw new InputError(`${path}: row ${at + 1} is not ${rowLength} numbers, as a row of its layout must be`);
    }
    return row as number[];
  };
  const groups = metadata.row_groups.map((g) => Number(g.num_rows));
  const read = (rowStart: number, rowEnd: number) =>
    new Promise<unknown[][]>((resolve, reject) => {
      parquetRead({ file, rowStart, rowEnd, onComplete: (rows) => resolve(rows as unknown[][]) }).catch(reject);
    });
  return {
    path,
    format: 'parquet',
    meta,
    shape,
    async *blocks() {
      let start = 0;
      let trajectory = -1;
      let seen = 0;
      for (const n of groups) {
        const rows = await read(start, start + n);
        if (rows.length !== n) throw new InputError(`${path}: a row group of ${n} rows reads as ${rows.length}`);
        start += n;
        if (wide) {
          // A row group of a wide table: every trajectory of the file over these times.
          const rowFrom = start - n;
          const data = new Float64Array(shape.count * n * width);
          for (let r = 0; r < n; r++) {
            const row = numbers(rows[r], rowFrom + r);
            for (let k = 0; k < shape.count; k++) {
              const at = (k * n + r) * width;
              data[at] = row[0];
              for (let c = 1; c < width; c++) data[at + c] = row[1 + k * (width - 1) + (c - 1)];
            }
          }
          yield { first: shape.first, count: shape.count, rowFrom, rowTo: rowFrom + n, data };
          continue;
        }
        // A long table: runs of rows of one trajectory, which may go on from the last row group.
        const checkedRows = rows.map((row, i) => numbers(row, start - n + i));
        let r = 0;
        while (r < n) {
          const j = numbered ? checkedRows[r][0] : shape.first;
          if (j !== trajectory) {
            trajectory = j;
            seen = 0;
          }
          let end = r;
          while (end < n && (numbered ? checkedRows[end][0] : shape.first) === j) end++;
          const data = new Float64Array((end - r) * width);
          for (let i = r; i < end; i++) {
            const row = checkedRows[i];
            for (let c = 0; c < width; c++) data[(i - r) * width + c] = row[c + (numbered ? 1 : 0)];
          }
          yield { first: j, count: 1, rowFrom: seen, rowTo: seen + (end - r), data };
          seen += end - r;
          r = end;
        }
      }
    },
    close: () => closeSync(fd),
  };
}

export type { ZipEntry };
