/**
 * A Parquet dataset read back with hyparquet, a row group at a time: its
 * meta under the key "phasebook" of the file's key-value metadata, its rows
 * long (a row per sample, numbered by trajectory when there are several) or
 * wide (a row per time, every trajectory's columns side by side).
 */
import { closeSync, fstatSync } from 'node:fs';
import { parquetMetadataAsync, parquetRead } from 'hyparquet';
import { InputError } from '../../core/index.ts';
import { parseDatasetMeta, readAtAligned, shapeOf, type DatasetFile } from './dataset-file.ts';

export async function parquetDataset(path: string, fd: number): Promise<DatasetFile> {
  const { size } = fstatSync(fd);
  const file = {
    byteLength: size,
    slice: (start: number, end?: number) => readAtAligned(fd, start, (end ?? size) - start),
  };
  const metadata = await parquetMetadataAsync(file);
  const kv = metadata.key_value_metadata?.find((e) => e.key === 'phasebook');
  if (!kv?.value) throw new InputError(`${path} has no "phasebook" key in its metadata: it was not written by phasebook`);
  const meta = parseDatasetMeta(kv.value, path, 'under its "phasebook" key');
  const shape = shapeOf(meta);
  const wide = meta.layout === 'wide';
  const numbered = !wide && shape.total > 1;
  const width = shape.columns.length;
  // A row as the layout lays it out: t then every trajectory's columns (wide), or the trajectory's number then its columns (long).
  const rowLength = wide ? 1 + shape.count * (width - 1) : width + (numbered ? 1 : 0);
  const numbers = (row: unknown, at: number): number[] => {
    if (!Array.isArray(row) || row.length !== rowLength || !row.every((v) => typeof v === 'number')) {
      throw new InputError(`${path}: row ${at + 1} is not ${rowLength} numbers, as a row of its layout must be`);
    }
    return row as number[];
  };
  const groups = metadata.row_groups.map((g) => Number(g.num_rows));
  const read = (rowStart: number, rowEnd: number) =>
    new Promise<unknown[][]>((resolve, reject) => {
      parquetRead({ file, rowStart, rowEnd, onComplete: (rows) => resolve(rows as unknown[][]) }).catch(reject);
    });
  return {
    path,
    format: 'parquet',
    meta,
    shape,
    async *blocks() {
      let start = 0;
      let trajectory = -1;
      let seen = 0;
      for (const n of groups) {
        const rows = await read(start, start + n);
        if (rows.length !== n) throw new InputError(`${path}: a row group of ${n} rows reads as ${rows.length}`);
        start += n;
        if (wide) {
          // A row group of a wide table: every trajectory of the file over these times.
          const rowFrom = start - n;
          const data = new Float64Array(shape.count * n * width);
          for (let r = 0; r < n; r++) {
            const row = numbers(rows[r], rowFrom + r);
            for (let k = 0; k < shape.count; k++) {
              const at = (k * n + r) * width;
              data[at] = row[0];
              for (let c = 1; c < width; c++) data[at + c] = row[1 + k * (width - 1) + (c - 1)];
            }
          }
          yield { first: shape.first, count: shape.count, rowFrom, rowTo: rowFrom + n, data };
          continue;
        }
        // A long table: runs of rows of one trajectory, which may go on from the last row group.
        const checkedRows = rows.map((row, i) => numbers(row, start - n + i));
        let r = 0;
        while (r < n) {
          const j = numbered ? checkedRows[r][0] : shape.first;
          if (j !== trajectory) {
            trajectory = j;
            seen = 0;
          }
          let end = r;
          while (end < n && (numbered ? checkedRows[end][0] : shape.first) === j) end++;
          const data = new Float64Array((end - r) * width);
          for (let i = r; i < end; i++) {
            const row = checkedRows[i];
            for (let c = 0; c < width; c++) data[(i - r) * width + c] = row[c + (numbered ? 1 : 0)];
          }
          yield { first: j, count: 1, rowFrom: seen, rowTo: seen + (end - r), data };
          seen += end - r;
          r = end;
        }
      }
    },
    close: () => closeSync(fd),
  };
}
