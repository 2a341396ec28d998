/**
 * The rows of a dataset as CSV or JSON lines, written as the single-run
 * export writes them (core/tables/csv.ts, core/tables/json.ts: shortest round-trip
 * numbers, -0 kept, non-finite values as words), with the trajectory's
 * index first when the set has more than one. Used by the workers too, so
 * that formatting, the costly half of a text export, runs on every core.
 *
 * Rows go straight into bytes, a line at a time: no string longer than a
 * line is ever built, so the garbage stays young and cheap, and the bytes
 * can be handed from a worker without a copy.
 */
import { jsonNumber, roundTripNumber } from '../../core/index.ts';
import type { Block } from './dataset-shape.ts';

export type TextFormat = 'csv' | 'json';

/** The most bytes a number takes as text ("-1.2345678901234567e-308" is 24) with its separator, and a row's brackets and index. */
const BYTES_PER_VALUE = 25;
const BYTES_PER_ROW = 28;

/** Bytes enough for the rows of `block`. */
export function textCapacity(block: Pick<Block, 'count' | 'rowFrom' | 'rowTo'>, width: number): number {
  const rows = block.count * (block.rowTo - block.rowFrom);
  return rows * (width * BYTES_PER_VALUE + BYTES_PER_ROW);
}

/**
 * The block's rows, trajectory by trajectory, as bytes in `into` (or a new
 * buffer); returns the part written. JSON rows each start with ",\n[", as
 * every row but the first of a file does; the writer drops the file's first comma.
 */
export function formatRows(format: TextFormat, block: Block, width: number, numbered: boolean, into?: Uint8Array): Uint8Array {
  const data = block.data!;
  const rows = block.rowTo - block.rowFrom;
  const capacity = textCapacity(block, width);
  const out = into && into.length >= capacity ? into : new Uint8Array(capacity);
  const buffer = Buffer.from(out.buffer, out.byteOffset, out.length);
  const number = format === 'csv' ? roundTripNumber : jsonNumber;
  const open = format === 'csv' ? '' : ',\n[';
  const close = format === 'csv' ? '\n' : ']';
  let at = 0;
  for (let j = 0; j < block.count; j++) {
    const prefix = numbered ? `${open}${block.first + j},` : open;
    for (let r = 0; r < rows; r++) {
      const row = (j * rows + r) * width;
      let line = prefix + number(data[row]);
      for (let c = 1; c < width; c++) line += ',' + number(data[row + c]);
      at += buffer.write(line + close, at, 'latin1');
    }
  }
  return out.subarray(0, at);
}
