/**
 * A dataset as Parquet, written with hyparquet-writer (pure JavaScript, no
 * native or WebAssembly code to install, maintained by Hyperparam, and able
 * to write a file a row group at a time, which streaming needs). The run's
 * metadata is the file's key-value metadata under the key "phasebook".
 *
 * Two layouts:
 * - long (the default): a row per sample, `trajectory` (when the set has
 *   more than one), t, the state, H, dx/dt; rows trajectory by trajectory,
 *   as pandas and polars group and filter them;
 * - wide: a row per time, t and then the columns of each trajectory,
 *   `q[j]`, `p[j]`, `H[j]` …, as a plot of many trajectories against t
 *   wants them.
 *
 * Row groups have a fixed number of rows, counted from the start of the
 * file, so a file's bytes never depend on how the rows arrived: the same
 * dataset run in one piece, on K workers, or merged from shards is the same
 * file.
 */
import { ByteWriter, ParquetWriter } from 'hyparquet-writer';
import { type ExportMeta, VERSION } from '../../core/index.ts';
import type { Sink } from '../output/sink.ts';
import type { Block, DatasetShape, DatasetWriter } from './dataset-shape.ts';

export type ParquetLayout = 'long' | 'wide';

/** Rows per row group of a long table: 32 Ki rows of a dozen columns is about 3 MB, encoded a column at a time. */
export const LONG_GROUP_ROWS = 32768;
/** Values per row group of a wide table, whose rows are as wide as the set. */
const WIDE_GROUP_VALUES = 1 << 18;
/** Bytes the encoder holds before handing them to the sink. */
const FLUSH_BYTES = 1 << 20;

/** Rows per row group of a wide table of `total` trajectories: about 4 MB, at least one row. */
export function wideGroupRows(shape: DatasetShape): number {
  const width = 1 + shape.total * (shape.columns.length - 1);
  return Math.max(1, Math.min(LONG_GROUP_ROWS, Math.floor(WIDE_GROUP_VALUES / width)));
}

export function parquetColumns(shape: DatasetShape, layout: ParquetLayout): string[] {
  if (layout === 'long') return shape.total > 1 ? ['trajectory', ...shape.columns] : [...shape.columns];
  const columns = ['t'];
  for (let j = shape.first; j < shape.first + shape.count; j++) for (const name of shape.columns.slice(1)) columns.push(`${name}[${j}]`);
  return columns;
}

/** hyparquet-writer's in-memory writer, emptied into the sink whenever it holds a megabyte. */
function sinkWriter(sink: Sink): ByteWriter {
  const writer = new ByteWriter();
  const flush = () => {
    // The sink writes synchronously, so the buffer can be refilled as soon as this returns.
    if (writer.index > 0) sink.write(new Uint8Array(writer.buffer, 0, writer.index));
    writer.index = 0;
  };
  const ensure = writer.ensure.bind(writer);
  writer.ensure = (size: number) => {
    if (writer.index > FLUSH_BYTES) flush();
    ensure(size);
  };
  writer.finish = flush;
  return writer;
}

export class ParquetDatasetWriter implements DatasetWriter {
  readonly order;
  /** rows per chunk the producer must deliver in time order (a wide table's row group) */
  readonly groupRows: number;
  private readonly writer: ParquetWriter;
  private readonly names: string[];
  private readonly buffers: Float64Array[];
  private readonly trajectory: Int32Array | undefined;
  private filled = 0;
  private readonly width: number;

  constructor(
    sink: Sink,
    private readonly shape: DatasetShape,
    meta: ExportMeta,
    private readonly layout: ParquetLayout,
  ) {
    this.order = layout === 'long' ? ('trajectory' as const) : ('time' as const);
    this.width = shape.columns.length;
    this.names = parquetColumns(shape, layout);
    this.groupRows = layout === 'long' ? LONG_GROUP_ROWS : wideGroupRows(shape);
    const numbered = layout === 'long' && shape.total > 1;
    const doubles = numbered ? this.names.slice(1) : this.names;
    this.trajectory = numbered ? new Int32Array(this.groupRows) : undefined;
    this.buffers = doubles.map(() => new Float64Array(this.groupRows));
    const schema = [
      { name: 'root', num_children: this.names.length },
      ...this.names.map((name, i) => ({ name, type: numbered && i === 0 ? ('INT32' as const) : ('DOUBLE' as const), repetition_type: 'REQUIRED' as const })),
    ];
    this.writer = new ParquetWriter({
      writer: sinkWriter(sink),
      schema,
      codec: 'UNCOMPRESSED',
      kvMetadata: [{ key: 'phasebook', value: JSON.stringify(meta) }],
      createdBy: `phasebook ${VERSION}`,
    });
  }

  write(block: Block): void {
    if (this.layout === 'long') this.writeLong(block);
    else this.writeWide(block);
  }

  private writeLong(block: Block): void {
    const data = block.data!;
    const rows = block.rowTo - block.rowFrom;
    const { width, buffers } = this;
    for (let j = 0; j < block.count; j++) {
      for (let r = 0; r < rows; r++) {
        const at = (j * rows + r) * width;
        if (this.trajectory) this.trajectory[this.filled] = block.first + j;
        for (let c = 0; c < width; c++) buffers[c][this.filled] = data[at + c];
        if (++this.filled === this.groupRows) this.flushGroup();
      }
    }
  }

  /** Time order: the blocks of one row chunk cover the file's trajectories in order, then the next chunk's come. */
  private writeWide(block: Block): void {
    const data = block.data!;
    const rows = block.rowTo - block.rowFrom;
    const per = this.width - 1;
    const base = 1 + (block.first - this.shape.first) * per;
    for (let j = 0; j < block.count; j++) {
      for (let r = 0; r < rows; r++) {
        const at = (j * rows + r) * this.width;
        this.buffers[0][r] = data[at];
        for (let c = 0; c < per; c++) this.buffers[base + j * per + c][r] = data[at + 1 + c];
      }
    }
    // The chunk is complete once its last trajectory has come.
    if (block.first + block.count === this.shape.first + this.shape.count) {
      this.filled = rows;
      this.flushGroup();
    }
  }

  private flushGroup(): void {
    if (this.filled === 0) return;
    const n = this.filled;
    const columnData = this.names.map((name, i) => {
      const numberedColumn = this.trajectory !== undefined && i === 0;
      const data = numberedColumn ? this.trajectory!.subarray(0, n) : this.buffers[this.trajectory ? i - 1 : i].subarray(0, n);
      // t and the trajectory index repeat and compress well in a dictionary; the state does not, and is written plain.
      return numberedColumn || name === 't' ? { name, data } : { name, data, encoding: 'PLAIN' as const };
    });
    this.writer.write({ columnData, rowGroupSize: n });
    this.filled = 0;
  }

  finish(): void {
    if (this.layout === 'long') this.flushGroup();
    this.writer.finish();
  }

  abandon(): void {}
}
