/**
 * A dataset file read back, whatever its format: its meta, checked for what
 * reading relies on, its shape, and its numbers as blocks. The readers of
 * each format (json-dataset-read.ts, npz-dataset-read.ts,
 * parquet-dataset-read.ts) make one; dataset-read.ts opens the right one and
 * checks every block it yields against the shape.
 */
import { InputError, parseJsonValue } from '../../core/index.ts';
import type { DatasetMeta } from '../dataset/meta.ts';
import type { Block, DatasetShape } from './dataset-shape.ts';
import { readAt } from './zip-reader.ts';

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

const isWhole = (v: unknown, least = 0): v is number => typeof v === 'number' && Number.isSafeInteger(v) && v >= least;
const isNames = (v: unknown): v is string[] => Array.isArray(v) && v.every((s) => typeof s === 'string');

/** Whether a meta is a dataset's (a simulate run's), not only a single export's, such as the page writes. */
export function isDatasetMeta(meta: unknown): boolean {
  const m = meta as Record<string, unknown> | null | undefined;
  return typeof m === 'object' && m !== null && isWhole(m.samples) && isNames(m.columns) && isWhole(m.count) && !!m.initialSet;
}

/** The meta, checked for what reading the file relies on: its rows' columns and how many there are. */
export function checkDatasetMeta(meta: unknown, path: string): DatasetMeta {
  if (!isDatasetMeta(meta)) {
    throw new InputError(`${path} was not written by a phasebook run with a dataset's meta (no samples, columns or initialSet in it)`);
  }
  const m = meta as Record<string, unknown> & { columns: string[]; count: number };
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

/** The meta's JSON text, parsed by the core's JSON reader and checked; `where` says where in the file it is. */
export function parseDatasetMeta(text: string, path: string, where: string): DatasetMeta {
  let meta: unknown;
  try {
    meta = parseJsonValue(text);
  } catch (error) {
    throw new InputError(`${path}: the meta ${where} is not JSON (${(error as Error).message})`);
  }
  return checkDatasetMeta(meta, path);
}

export function shapeOf(meta: DatasetMeta): DatasetShape {
  return { columns: meta.columns, names: meta.names ?? [], count: meta.count, first: meta.shard?.first ?? 0, total: meta.trajectories, samples: meta.samples };
}

/** Bytes read into a fresh ArrayBuffer, so that a Float64Array can view them. */
export function readAtAligned(fd: number, position: number, length: number): ArrayBuffer {
  const bytes = readAt(fd, position, length);
  if (bytes.length < length) throw new InputError(`the file ends before its arrays do (at byte ${position + bytes.length})`);
  const out = new ArrayBuffer(length);
  new Uint8Array(out).set(bytes);
  return out;
}
