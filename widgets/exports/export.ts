import { csvHeader, csvRows, type ExportMeta, jsonHead, jsonRows, jsonTail, type TrajectoryRecord } from '../../core/index.ts';

/**
 * Exports of record rows [from, to) in the CLI's formats, built with the
 * core's writers (csv.ts, json.ts) straight from the ring buffer's storage,
 * in blocks, so a long record becomes a list of moderate strings (Blob parts)
 * instead of one huge string or a copy of the whole table.
 */

/** Rows per block of text. */
export const BLOCK_ROWS = 20_000;

/** Calls `block(data, from, to)` for consecutive runs of at most BLOCK_ROWS rows of the ring's storage. */
function eachBlock(record: TrajectoryRecord, from: number, to: number, block: (data: Float64Array, a: number, b: number) => void): void {
  for (const s of from < to ? record.slices(from, to) : []) {
    for (let a = s.from; a < s.to; a += BLOCK_ROWS) block(s.data, a, Math.min(s.to, a + BLOCK_ROWS));
  }
}

/** CSV text of rows [from, to), header first, as blocks whose concatenation is toCSV of those rows. */
export function csvParts(record: TrajectoryRecord, from = 0, to = record.length): string[] {
  const parts = [csvHeader(record.columns)];
  eachBlock(record, from, to, (data, a, b) => parts.push(csvRows(data, record.width, a, b)));
  return parts;
}

/** JSON text of rows [from, to) with `meta`, as blocks whose concatenation is toJSON of those rows. */
export function jsonParts(record: TrajectoryRecord, meta: ExportMeta, from = 0, to = record.length): string[] {
  const parts = [jsonHead(meta, record.columns)];
  let first = true;
  eachBlock(record, from, to, (data, a, b) => {
    parts.push(jsonRows(data, record.width, a, b, first));
    if (b > a) first = false;
  });
  parts.push(jsonTail());
  return parts;
}
