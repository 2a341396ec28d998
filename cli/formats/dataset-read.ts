/**
 * Opening a file of samples, whatever its format, told by its first bytes:
 * the one reading path of merge, reproduce and spectrum.
 *
 * A dataset file this CLI wrote (JSON, NPZ or Parquet, with a dataset's
 * meta) is read a chunk of rows at a time, so that any size reads in flat
 * memory: merge re-writes its blocks, reproduce compares them with a fresh
 * run, spectrum takes one trajectory's column. A text table without that
 * meta (a CSV, the page's JSON export) is left to the core's readers
 * (read-table.ts); only spectrum takes one, since it carries nothing to
 * check or run again.
 *
 * A file is data from whoever made it. Its meta's shape is checked before it
 * is used, every block it yields is checked against that shape (a row with a
 * value missing once went into a merge as "undefined"), and every message
 * names the file: a parser's own error (hyparquet's "thrift unhandled type")
 * is said as the file's damage.
 */
import { closeSync, openSync } from 'node:fs';
import { InputError, JsonExportReader } from '../../core/index.ts';
import { namingFile } from './file-errors.ts';
import { isDatasetMeta, type DatasetFile } from './dataset-file.ts';
import type { Block } from './dataset-shape.ts';
import { jsonDataset, textPieces } from './json-dataset-read.ts';
import { npzDataset } from './npz-dataset-read.ts';
import { parquetDataset } from './parquet-dataset-read.ts';
import { readAt } from './zip-reader.ts';

export type { DatasetFile };

/** A file opened: a dataset, or a text table (CSV, or JSON without a dataset's meta) for the core's readers, or neither. */
export type OpenedFile = { kind: 'dataset'; file: DatasetFile } | { kind: 'table'; format: 'csv' | 'json' } | { kind: 'binary' };

const MAGIC_ZIP = 0x04034b50;

/** Opens `path` and tells what it holds by its first bytes; a dataset comes back open and checked, anything else closed. */
export async function openFile(path: string): Promise<OpenedFile> {
  let fd: number;
  try {
    fd = openSync(path, 'r');
  } catch (error) {
    const code = (error as NodeJS.ErrnoException).code;
    throw new InputError(`cannot read ${path}: ${code === 'ENOENT' ? 'no such file' : code === 'EISDIR' ? 'it is a directory' : code === 'EACCES' ? 'permission denied' : (code ?? (error as Error).message)}`);
  }
  let opened: OpenedFile | undefined;
  try {
    opened = await openFormat(path, fd);
    if (opened.kind === 'dataset') opened = { kind: 'dataset', file: checked(opened.file) };
    return opened;
  } catch (error) {
    throw namingFile(error, path, true);
  } finally {
    if (opened?.kind !== 'dataset') closeSync(fd);
  }
}

/** Opens a dataset file this CLI wrote, for merge and reproduce. */
export async function openDataset(path: string): Promise<DatasetFile> {
  const opened = await openFile(path);
  if (opened.kind === 'dataset') return opened.file;
  if (opened.kind === 'table' && opened.format === 'json') {
    throw new InputError(`${path} was not written by a phasebook run with a dataset's meta (no samples, columns or initialSet in it)`);
  }
  throw new InputError(`${path} is not a dataset with its meta: give the JSON, NPZ or Parquet file of a phasebook run (CSV keeps no meta)`);
}

async function openFormat(path: string, fd: number): Promise<OpenedFile> {
  const head = readAt(fd, 0, 8192);
  const close = () => closeSync(fd);
  if (head.length >= 4 && head.readUInt32LE(0) === MAGIC_ZIP) return { kind: 'dataset', file: npzDataset(path, fd) };
  if (head.subarray(0, 4).toString('latin1') === 'PAR1') return { kind: 'dataset', file: await parquetDataset(path, fd) };
  if (head.includes(0)) return { kind: 'binary' };
  if (!/^(\uFEFF)?\s*\{/.test(head.toString('utf8'))) return { kind: 'table', format: 'csv' };
  const reader = new JsonExportReader('', textPieces(fd)).head();
  // A dataset's meta comes first, as phasebook writes it; any other JSON is a table for the core's parseJSON.
  if (!reader.meta || !isDatasetMeta(reader.meta.value)) return { kind: 'table', format: 'json' };
  return { kind: 'dataset', file: jsonDataset(path, reader, close) };
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
