/**
 * What every dataset file of a run holds, whatever its format: M
 * trajectories (`count`, numbered from `first` in the whole set), T samples
 * each, and per sample a row of `columns` (t, the state, H, dx/dt).
 *
 * Data travels from the integration to a file, and from a file to merge or
 * reproduce, as blocks: rows [rowFrom, rowTo) of trajectories
 * [first, first + count), laid out trajectory by trajectory, row by row.
 * A file is written from its blocks in one order: trajectory by trajectory
 * (long tables and NPZ, whose x is M×T×2n), or sample by sample for a wide
 * table, whose rows are times.
 */
export interface DatasetShape {
  /** the row of one sample: t, the state, H when known, dx/dt when asked for */
  columns: readonly string[];
  /** names of the state, q's then p's */
  names: readonly string[];
  /** trajectories in this file */
  count: number;
  /** global index of its first trajectory */
  first: number;
  /** trajectories in the whole set (more than count in a shard) */
  total: number;
  /** samples per trajectory */
  samples: number;
}

export type BlockOrder = 'trajectory' | 'time';

export interface Block {
  first: number;
  count: number;
  rowFrom: number;
  rowTo: number;
  /** count × (rowTo − rowFrom) × width values; absent when the block comes as text */
  data?: Float64Array;
  /** the rows already formatted by a worker (CSV or JSON lines), as bytes */
  text?: Uint8Array;
}

/** A file being written from blocks, in its order. */
export interface DatasetWriter {
  readonly order: BlockOrder;
  write(block: Block): void;
  /** writes what closes the file (a footer, arrays kept aside) */
  finish(): void;
  /** removes anything kept aside; never throws */
  abandon(): void;
}

