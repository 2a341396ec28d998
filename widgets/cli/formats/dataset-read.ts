/**
 * Reading back a dataset file this CLI wrote, as JSON, NPZ or Parquet: its
 * meta, and its numbers as the blocks they were written from, a chunk of
 * rows at a time so that any size reads in flat memory. Merge re-writes
 * them; reproduce compares them with a fresh run. CSV carries no meta, so it
 * can be neither checked nor reproduced.
 */
import { closeSync, openSync, readSync } from 'node:fs';
import { parquetMetadataAsync, parquetRead } from 'hyparquet';
import { InputError } from '../../core/index.ts';
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
    const head = readAt(fd, 0, 4);
    if (head.length === 4 && head.readUInt32LE(0) === MAGIC_ZIP) return openNpz(path, fd);
    if (head.toString('latin1') === 'PAR1') return await openParquet(path, fd);
    if (head.toString('latin1').trimStart().startsWith('{')) return openJson(path, fd);
    throw new InputError(`${path} is not a dataset with its meta: give the JSON, NPZ or Parquet file of a phasebook run (CSV keeps no meta)`);
  } catch (error) {
    closeSync(fd);
    throw error;
  }
}

function checkMeta(meta: unknown, path: string): DatasetMeta {
  const m = meta as DatasetMeta | undefined;
  if (!m || typeof m !== 'object' || typeof m.samples !== 'number' || !Array.isArray(m.columns) || typeof m.count !== 'number' || !m.initialSet) {
    throw new InputError(`${path} was not written by a phasebook run with a dataset's meta (no samples, columns or initialSet in it)`);
  }
  return m;
}

function shapeOf(meta: DatasetMeta): DatasetShape {
  return { columns: meta.columns, names: meta.names ?? [], count: meta.count, first: meta.shard?.first ?? 0, total: meta.trajectories, samples: meta.samples };
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
  let meta: DatasetMeta;
  try {
    meta = checkMeta(JSON.parse(head.slice(8, -1)), path);
  } catch (error) {
    if (error instanceof InputError) throw error;
    throw new InputError(`${path}: the meta on its first line is not JSON (${(error as Error).message})`);
  }
  const shape = shapeOf(meta);
  const numbered = shape.total > 1;
  const width = shape.columns.length;
  return {
    path,
    format: 'json',
    meta,
    shape,
    async *blocks(values) {
      const chunk = Math.max(1, Math.floor(values / width));
      let line = 1;
      let block: { first: number; rows: number[]; rowFrom: number } | undefined;
      let row = 0;
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
        if (!trimmed.startsWith('[')) continue; // the closing ]}
        const values = (JSON.parse(trimmed) as (number | string | null)[]).map((v) => (v === null ? NaN : Number(v)));
        const j = numbered ? values[0] : shape.first;
        if (j !== trajectory) {
          yield* flush();
          trajectory = j;
          row = 0;
          block = { first: j, rows: [], rowFrom: 0 };
        }
        block!.rows.push(...(numbered ? values.slice(1) : values));
        row++;
        if (block!.rows.length >= chunk * width) yield* flush();
      }
      yield* flush();
    },
    close: () => closeSync(fd),
  };
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
    if (point !== 0) text += String.fromCodePoint(point);
  }
  const meta = checkMeta(JSON.parse(text), path);
  const shape = shapeOf(meta);
  const t = array('t')!;
  const times = new Float64Array(readAtAligned(fd, t.data, 8 * shape.samples));
  const dim = shape.names.length;
  const parts: { a: NonNullable<ReturnType<typeof array>>; n: number }[] = [{ a: array('x')!, n: dim }];
  for (const name of shape.columns.slice(1 + dim)) {
    if (name.endsWith('/dt')) continue;
    parts.push({ a: array(name)!, n: 1 });
  }
  if (shape.columns.some((c) => c.endsWith('/dt'))) parts.push({ a: array('dxdt')!, n: dim });
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
  const meta = checkMeta(JSON.parse(kv.value), path);
  const shape = shapeOf(meta);
  const wide = meta.layout === 'wide';
  const numbered = !wide && shape.total > 1;
  const width = shape.columns.length;
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
        start += n;
        if (wide) {
          // A row group of a wide table: every trajectory of the file over these times.
          const rowFrom = start - n;
          const data = new Float64Array(shape.count * n * width);
          for (let r = 0; r < n; r++) {
            const row = rows[r] as number[];
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
        let r = 0;
        while (r < n) {
          const j = numbered ? Number(rows[r][0]) : shape.first;
          if (j !== trajectory) {
            trajectory = j;
            seen = 0;
          }
          let end = r;
          while (end < n && (numbered ? Number(rows[end][0]) : shape.first) === j) end++;
          const data = new Float64Array((end - r) * width);
          for (let i = r; i < end; i++) {
            const row = rows[i] as number[];
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
