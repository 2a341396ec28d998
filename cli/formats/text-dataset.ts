/**
 * A dataset as CSV or JSON text: the single-run layout (t, q, p, H) when the
 * set has one trajectory, a long table with the trajectory's index first
 * when it has more, its rows trajectory by trajectory. JSON carries the meta
 * at its head; CSV has nowhere to keep it.
 */
import { csvHeader, type ExportMeta, jsonHead, jsonTail } from '../../core/index.ts';
import type { Sink } from '../output/sink.ts';
import type { Block, DatasetShape, DatasetWriter } from './dataset-shape.ts';
import { formatRows, type TextFormat } from './text-rows.ts';

/** A long table numbers its rows by trajectory once the set has more than one. */
export function numbered(shape: DatasetShape): boolean {
  return shape.total > 1;
}

export function textColumns(shape: DatasetShape): string[] {
  return numbered(shape) ? ['trajectory', ...shape.columns] : [...shape.columns];
}

export class TextDatasetWriter implements DatasetWriter {
  readonly order = 'trajectory';
  /** what a worker needs to format the rows itself */
  readonly textFormat: { format: TextFormat; numbered: boolean };
  private first = true;

  constructor(
    private readonly sink: Sink,
    private readonly format: TextFormat,
    private readonly shape: DatasetShape,
    meta: ExportMeta,
  ) {
    this.textFormat = { format, numbered: numbered(shape) };
    const columns = textColumns(shape);
    sink.write(format === 'csv' ? csvHeader(columns) : jsonHead(meta, columns));
  }

  /** Formatting buffer for blocks that come as numbers (merge), reused. */
  private scratch: Uint8Array | undefined;

  write(block: Block): void {
    let text = block.text;
    if (!text) {
      text = formatRows(this.format, block, this.shape.columns.length, numbered(this.shape), this.scratch);
      this.scratch = new Uint8Array(text.buffer);
    }
    if (text.length === 0) return;
    if (this.format === 'json' && this.first) text = text.subarray(1);
    this.first = false;
    this.sink.write(text);
  }

  finish(): void {
    if (this.format === 'json') this.sink.write(jsonTail());
  }

  abandon(): void {}
}
