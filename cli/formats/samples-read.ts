/**
 * The samples of a file, as spectrum reads them: whatever the format, a
 * sample's columns (t first) and every sample with its trajectory. A
 * dataset (JSON, NPZ or Parquet with its meta) comes through the same
 * reader as merge and reproduce use, a block at a time; a text table
 * without one (a CSV, the page's JSON export) through the core's readers,
 * with a `trajectory` column numbering its trajectories when it has several.
 */
import { readFileSync } from 'node:fs';
import { InputError, readTable } from '../../core/index.ts';
import { BLOCK_VALUES } from '../dataset/plan-tasks.ts';
import { namingFile } from './file-errors.ts';
import { openFile, type DatasetFile } from './dataset-read.ts';

export interface Samples {
  /** the columns of one sample, t first where the file has it */
  columns: readonly string[];
  /** whether the samples are numbered by trajectory: the file holds several, or a shard of a set */
  numbered: boolean;
  /** how many trajectories the file holds, when its meta says */
  count?: number;
  /** calls `take` with every sample's trajectory, time and value of `column` (an index into columns), in the file's order */
  each(column: number, take: (trajectory: number, t: number, value: number) => void): Promise<void>;
  close(): void;
}

/** Opens `path` for its samples. */
export async function openSamples(path: string): Promise<Samples> {
  const opened = await openFile(path);
  if (opened.kind === 'dataset') return datasetSamples(opened.file);
  if (opened.kind === 'binary') throw new InputError(`${path} is binary; spectrum reads CSV, JSON, NPZ or Parquet files as phasebook writes them`);
  return tableSamples(path);
}

function datasetSamples(file: DatasetFile): Samples {
  const { shape } = file;
  const width = shape.columns.length;
  return {
    columns: shape.columns,
    numbered: shape.total > 1,
    count: shape.count,
    async each(column, take) {
      try {
        for await (const block of file.blocks(BLOCK_VALUES)) {
          const data = block.data!;
          const rows = block.rowTo - block.rowFrom;
          for (let k = 0; k < block.count; k++) {
            for (let r = 0; r < rows; r++) {
              const at = (k * rows + r) * width;
              take(block.first + k, data[at], data[at + column]);
            }
          }
        }
      } catch (error) {
        throw namingFile(error, file.path, true);
      }
    },
    close: () => file.close(),
  };
}

function tableSamples(path: string): Samples {
  const table = readTable(readFileSync(path).toString('utf8'), path);
  const width = table.columns.length;
  const numberedBy = table.columns.indexOf('trajectory');
  const time = table.columns.indexOf('t');
  const columns = table.columns.filter((c) => c !== 'trajectory');
  return {
    columns,
    numbered: numberedBy >= 0,
    async each(column, take) {
      const c = table.columns.indexOf(columns[column]);
      for (let r = 0; r < table.rows; r++) {
        const at = r * width;
        take(numberedBy >= 0 ? table.data[at + numberedBy] : 0, time >= 0 ? table.data[at + time] : NaN, table.data[at + c]);
      }
    },
    close: () => {},
  };
}
