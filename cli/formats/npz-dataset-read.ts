/**
 * An NPZ dataset read back: the stored (uncompressed) arrays phasebook
 * writes, found through the ZIP directory (whose CRCs zip-reader.ts checks),
 * each checked to be float64 of the shape the meta gives, and read a block
 * of trajectories at a time straight from the file, however large.
 */
import { closeSync } from 'node:fs';
import { InputError } from '../../core/index.ts';
import { parseDatasetMeta, readAtAligned, shapeOf, type DatasetFile } from './dataset-file.ts';
import { parseNpyHeader } from './npy.ts';
import { readAt, zipEntries } from './zip-reader.ts';

export function npzDataset(path: string, fd: number): DatasetFile {
  const entries = zipEntries(fd, path);
  const array = (name: string) => {
    const entry = entries.get(`${name}.npy`);
    if (!entry) return undefined;
    if (entry.method !== 0) throw new InputError(`${path}: ${name}.npy is compressed; phasebook reads the stored NPZ it writes`);
    const header = parseNpyHeader(readAt(fd, entry.dataOffset, Math.min(entry.size, 4096)), `${path}:${name}.npy`);
    return { entry, header, data: entry.dataOffset + header.dataOffset };
  };
  const metaArray = array('meta');
  if (!metaArray) throw new InputError(`${path} has no meta.npy: it was not written by phasebook`);
  const metaBytes = readAt(fd, metaArray.data, metaArray.entry.size - metaArray.header.dataOffset);
  let text = '';
  for (let i = 0; i + 4 <= metaBytes.length; i += 4) {
    const point = metaBytes.readUInt32LE(i);
    if (point > 0x10ffff) throw new InputError(`${path}: meta.npy holds a character code ${point}, which is none`);
    if (point !== 0) text += String.fromCodePoint(point);
  }
  const meta = parseDatasetMeta(text, path, 'in meta.npy');
  const shape = shapeOf(meta);
  const dim = shape.names.length;
  /** An array the meta says the file has, checked to be float64 of the shape the meta gives. */
  const needed = (name: string, dims: number[]) => {
    const found = array(name);
    if (!found) throw new InputError(`${path} has no ${name}.npy, which its meta's columns call for`);
    const { descr, shape: has, fortranOrder } = found.header;
    if (descr !== '<f8' || fortranOrder || has.length !== dims.length || has.some((d, i) => d !== dims[i])) {
      throw new InputError(`${path}: ${name}.npy is ${descr} of shape (${has.join(', ')}), not float64 of shape (${dims.join(', ')}) as its meta says`);
    }
    if (found.entry.size - found.header.dataOffset < 8 * dims.reduce((a, b) => a * b, 1)) throw new InputError(`${path}: ${name}.npy is cut short`);
    return found;
  };
  const t = needed('t', [shape.samples]);
  const times = new Float64Array(readAtAligned(fd, t.data, 8 * shape.samples));
  const parts: { a: NonNullable<ReturnType<typeof array>>; n: number }[] = [{ a: needed('x', [shape.count, shape.samples, dim]), n: dim }];
  for (const name of shape.columns.slice(1 + dim)) {
    if (name.endsWith('/dt')) continue;
    parts.push({ a: needed(name, [shape.count, shape.samples]), n: 1 });
  }
  if (shape.columns.some((c) => c.endsWith('/dt'))) parts.push({ a: needed('dxdt', [shape.count, shape.samples, dim]), n: dim });
  const width = shape.columns.length;
  return {
    path,
    format: 'npz',
    meta,
    shape,
    times,
    async *blocks(values) {
      const { samples } = shape;
      const perTrajectory = samples * width;
      const batch = perTrajectory <= values ? Math.max(1, Math.floor(values / perTrajectory)) : 1;
      const rows = perTrajectory <= values ? samples : Math.max(1, Math.floor(values / width));
      for (let j = 0; j < shape.count; j += batch) {
        const count = Math.min(batch, shape.count - j);
        for (let r0 = 0; r0 < samples; r0 += rows) {
          const r1 = Math.min(samples, r0 + rows);
          const span = r1 - r0;
          const data = new Float64Array(count * span * width);
          for (let k = 0; k < count; k++) {
            for (let r = 0; r < span; r++) data[(k * span + r) * width] = times[r0 + r];
            let column = 1;
            for (const { a, n } of parts) {
              const at = a.data + 8 * ((j + k) * samples * n + r0 * n);
              const piece = new Float64Array(readAtAligned(fd, at, 8 * span * n));
              for (let r = 0; r < span; r++) for (let c = 0; c < n; c++) data[(k * span + r) * width + column + c] = piece[r * n + c];
              column += n;
            }
          }
          yield { first: shape.first + j, count, rowFrom: r0, rowTo: r1, data };
        }
      }
    },
    close: () => closeSync(fd),
  };
}
