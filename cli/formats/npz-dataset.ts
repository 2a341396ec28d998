/**
 * A dataset as NPZ, the archive numpy.load opens: `t` (T), `x` (M × T × 2n),
 * one M × T array per derived series (`H`), `dxdt` (M × T × 2n) when asked
 * for, and `meta`, the run's metadata as a JSON string (a 0-d str array:
 * `json.loads(f['meta'][()])`).
 *
 * The archive is written front to back: x streams straight into it, while
 * the arrays after it are held in spill files (spill-file.ts) and copied in
 * at the end, so memory stays flat whatever the size.
 */
import type { ExportMeta } from '../../core/index.ts';
import type { Sink } from '../output/sink.ts';
import { SpillFile } from '../output/spill-file.ts';
import type { Block, DatasetShape, DatasetWriter } from './dataset-shape.ts';
import { FLOAT64, npyHeader, npyString } from './npy.ts';
import { ZipWriter } from './zip-writer.ts';

/** A column group of the row that becomes one array: columns [from, to) of each row. */
interface Part {
  name: string;
  from: number;
  to: number;
  spill?: SpillFile;
}

/** The arrays of a dataset's rows, in archive order after t: x, each derived series, dxdt. */
export function npzParts(shape: DatasetShape): Part[] {
  const dim = shape.names.length;
  const columns = shape.columns;
  const parts: Part[] = [{ name: 'x', from: 1, to: 1 + dim }];
  let c = 1 + dim;
  while (c < columns.length && !columns[c].endsWith('/dt')) {
    parts.push({ name: columns[c], from: c, to: c + 1 });
    c++;
  }
  if (c < columns.length) parts.push({ name: 'dxdt', from: c, to: columns.length });
  return parts;
}

export class NpzDatasetWriter implements DatasetWriter {
  readonly order = 'trajectory';
  private readonly zip: ZipWriter;
  private readonly parts: Part[];
  private closed = false;

  /**
   * @param times the sample times, written first as `t`
   * @param target the output file, beside which spill files go
   */
  constructor(
    sink: Sink,
    private readonly shape: DatasetShape,
    private readonly meta: ExportMeta,
    times: Float64Array,
    target: string | undefined,
    options: { forceZip64?: boolean } = {},
  ) {
    this.zip = new ZipWriter((bytes) => sink.write(bytes), options.forceZip64);
    this.parts = npzParts(shape);
    try {
      for (const part of this.parts.slice(1)) part.spill = new SpillFile(target, part.name);
    } catch (error) {
      this.abandon();
      throw error;
    }
    this.zip.add('t.npy', Buffer.concat([npyHeader(FLOAT64, [times.length]), bytesOf(times)]));
    this.beginArray(this.parts[0]);
  }

  private shapeOf(part: Part): number[] {
    const { count, samples } = this.shape;
    const n = part.to - part.from;
    return part.name === 'x' || part.name === 'dxdt' ? [count, samples, n] : [count, samples];
  }

  private beginArray(part: Part): void {
    const shape = this.shapeOf(part);
    const header = npyHeader(FLOAT64, shape);
    this.zip.begin(`${part.name}.npy`, header.length + 8 * shape.reduce((a, b) => a * b, 1));
    this.zip.write(header);
  }

  /** One buffer reused for every part of every block: the bytes are written before it is refilled. */
  private scratch = new Float64Array(0);

  write(block: Block): void {
    const data = block.data!;
    const width = this.shape.columns.length;
    const rows = (block.rowTo - block.rowFrom) * block.count;
    for (const part of this.parts) {
      const n = part.to - part.from;
      if (this.scratch.length < rows * n) this.scratch = new Float64Array(rows * n);
      const values = this.scratch.subarray(0, rows * n);
      for (let r = 0, at = 0; r < rows; r++) {
        const row = r * width + part.from;
        for (let c = 0; c < n; c++) values[at++] = data[row + c];
      }
      if (part.spill) part.spill.append(bytesOf(values));
      else this.zip.write(bytesOf(values));
    }
  }

  finish(): void {
    this.zip.end();
    for (const part of this.parts.slice(1)) {
      this.beginArray(part);
      part.spill!.replay((bytes) => this.zip.write(bytes));
      this.zip.end();
      part.spill!.remove();
    }
    this.zip.add('meta.npy', npyString(JSON.stringify(this.meta)));
    this.zip.finish();
    this.closed = true;
  }

  abandon(): void {
    if (this.closed) return;
    this.closed = true;
    for (const part of this.parts) part.spill?.remove();
  }
}

function bytesOf(values: Float64Array): Uint8Array {
  return new Uint8Array(values.buffer, values.byteOffset, values.byteLength);
}
