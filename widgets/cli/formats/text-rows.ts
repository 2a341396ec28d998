/**
 * The rows of a dataset as CSV or JSON lines, written as the single-run
 * export writes them (core/csv.ts, core/json.ts: shortest round-trip
 * numbers, -0 kept, non-finite values as words), with the trajectory's
 * index first when the set has more than one. Used by the workers too, so
 * that formatting, the costly half of a text export, runs on every core.
 */
import { formatNumber } from '../../core/csv.ts';
import { jsonNumber } from '../../core/json.ts';
import type { Block } from './dataset-shape.ts';

export type TextFormat = 'csv' | 'json';

/**
 * The block's rows, trajectory by trajectory. JSON rows each start with
 * ",\n[", as every row but the first of a file does; the writer drops the
 * first comma of the file.
 */
export function formatRows(format: TextFormat, block: Block, width: number, numbered: boolean): string {
  const data = block.data!;
  const rows = block.rowTo - block.rowFrom;
  const number = format === 'csv' ? formatNumber : jsonNumber;
  const open = format === 'csv' ? '' : ',\n[';
  const close = format === 'csv' ? '\n' : ']';
  let out = '';
  for (let j = 0; j < block.count; j++) {
    const prefix = numbered ? `${open}${block.first + j},` : open;
    for (let r = 0; r < rows; r++) {
      const at = (j * rows + r) * width;
      let line = prefix + number(data[at]);
      for (let c = 1; c < width; c++) line += ',' + number(data[at + c]);
      out += line + close;
    }
  }
  return out;
}
