/**
 * A JSON dataset read back through the core's one reader of the book's JSON
 * export (core/tables/json-read.ts), a megabyte of the file at a time: its meta and
 * columns first, then its rows, grouped into blocks of one trajectory's
 * consecutive samples. A row is `[j, t, …]` when the set has several
 * trajectories, `[t, …]` when it has one.
 */
import { readSync } from 'node:fs';
import { StringDecoder } from 'node:string_decoder';
import { InputError, JsonExportReader } from '../../core/index.ts';
import { checkDatasetMeta, shapeOf, type DatasetFile } from './dataset-file.ts';
import type { Block } from './dataset-shape.ts';

/** The text of the file open as `fd`, a piece at a time, UTF-8 decoded across the pieces' edges. */
export function textPieces(fd: number): () => string | undefined {
  const decoder = new StringDecoder('utf8');
  const buffer = Buffer.alloc(1 << 20);
  let position = 0;
  let ended = false;
  return () => {
    if (ended) return undefined;
    const n = readSync(fd, buffer, 0, buffer.length, position);
    if (n === 0) {
      ended = true;
      const rest = decoder.end();
      return rest === '' ? undefined : rest;
    }
    position += n;
    return decoder.write(buffer.subarray(0, n));
  };
}

/** The dataset of a JSON file whose head (meta and columns, before the data) `reader` has read. */
export function jsonDataset(path: string, reader: JsonExportReader, close: () => void): DatasetFile {
  if (!reader.meta) throw new InputError(`${path} is not a JSON export of phasebook: no meta comes before its data`);
  const meta = checkDatasetMeta(reader.meta.value, path);
  const shape = shapeOf(meta);
  const numbered = shape.total > 1;
  const width = shape.columns.length;
  const columns = numbered ? ['trajectory', ...shape.columns] : [...shape.columns];
  const given = reader.columns?.value;
  if (!given || given.join(',') !== columns.join(',')) {
    throw new InputError(`${path}: its columns (${given?.join(', ') ?? 'none before the data'}) are not those of its meta (${columns.join(', ')})`);
  }
  return {
    path,
    format: 'json',
    meta,
    shape,
    async *blocks(values) {
      const chunk = Math.max(1, Math.floor(values / width));
      let block: { first: number; rows: number[]; rowFrom: number } | undefined;
      let trajectory = -1;
      const flush = function* (): Generator<Block> {
        if (!block || block.rows.length === 0) return;
        const n = block.rows.length / width;
        yield { first: block.first, count: 1, rowFrom: block.rowFrom, rowTo: block.rowFrom + n, data: Float64Array.from(block.rows) };
        block = { first: block.first, rows: [], rowFrom: block.rowFrom + n };
      };
      const row: number[] = [];
      while (reader.row(row)) {
        const j = numbered ? row[0] : shape.first;
        if (j !== trajectory) {
          yield* flush();
          trajectory = j;
          block = { first: j, rows: [], rowFrom: 0 };
        }
        for (let c = numbered ? 1 : 0; c < row.length; c++) block!.rows.push(row[c]);
        if (block!.rows.length >= chunk * width) yield* flush();
      }
      yield* flush();
    },
    close,
  };
}
