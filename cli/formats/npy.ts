/**
 * The NPY format, version 1.0 (numpy/lib/format.py, NEP 1): a magic string,
 * a little header that is a Python dict literal (dtype, order, shape), padded
 * with spaces to a multiple of 64 bytes, then the raw array in C order.
 */
import { endianness } from 'node:os';
import { InputError } from '../../core/index.ts';

const MAGIC = [0x93, 0x4e, 0x55, 0x4d, 0x50, 0x59]; // \x93NUMPY

/** This machine's float64, as numpy names it: '<f8' on every little-endian processor. */
export const FLOAT64 = endianness() === 'LE' ? '<f8' : '>f8';

/** The header bytes of an array of `descr` with `shape`, in C order. */
export function npyHeader(descr: string, shape: readonly number[]): Buffer {
  const dims = shape.length === 1 ? `(${shape[0]},)` : `(${shape.join(', ')})`;
  let dict = `{'descr': '${descr}', 'fortran_order': False, 'shape': ${dims}, }`;
  // Magic (6) + version (2) + length (2) + dict + '\n', padded to 64 bytes with spaces.
  const unpadded = 10 + dict.length + 1;
  dict += ' '.repeat((64 - (unpadded % 64)) % 64) + '\n';
  if (dict.length > 0xffff) throw new Error('npyHeader: the header needs NPY version 2');
  const out = Buffer.alloc(10 + dict.length);
  MAGIC.forEach((b, i) => (out[i] = b));
  out[6] = 1;
  out[7] = 0;
  out.writeUInt16LE(dict.length, 8);
  out.write(dict, 10, 'latin1');
  return out;
}

/** A whole .npy of one string, a 0-d array of dtype <U n (UTF-32, little-endian), as numpy stores str. */
export function npyString(text: string): Buffer {
  const points = Array.from(text, (c) => c.codePointAt(0)!);
  const header = npyHeader(`<U${Math.max(1, points.length)}`, []);
  const body = Buffer.alloc(4 * Math.max(1, points.length));
  points.forEach((p, i) => body.writeUInt32LE(p, 4 * i));
  return Buffer.concat([header, body]);
}

export interface NpyHeader {
  descr: string;
  fortranOrder: boolean;
  shape: number[];
  /** bytes before the data */
  dataOffset: number;
}

/** Reads an NPY header (versions 1 to 3) from the start of `bytes`; `what` names the file in messages. */
export function parseNpyHeader(bytes: Uint8Array, what: string): NpyHeader {
  const bad = (why: string) => new InputError(`${what} is not an NPY file numpy would read: ${why}`);
  if (bytes.length < 10 || MAGIC.some((b, i) => bytes[i] !== b)) throw bad('it does not start with \\x93NUMPY');
  const major = bytes[6];
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  let length: number;
  let start: number;
  if (major === 1) {
    length = view.getUint16(8, true);
    start = 10;
  } else if (major === 2 || major === 3) {
    if (bytes.length < 12) throw bad('the header is cut short');
    length = view.getUint32(8, true);
    start = 12;
  } else throw bad(`version ${major} is unknown`);
  if (bytes.length < start + length) throw bad('the header is cut short');
  const dict = Buffer.from(bytes.subarray(start, start + length)).toString(major === 3 ? 'utf8' : 'latin1');
  const descr = /'descr'\s*:\s*'([^']*)'/.exec(dict)?.[1];
  const fortran = /'fortran_order'\s*:\s*(True|False)/.exec(dict)?.[1];
  const shape = /'shape'\s*:\s*\(([^)]*)\)/.exec(dict)?.[1];
  if (descr === undefined || fortran === undefined || shape === undefined) throw bad(`its header ${JSON.stringify(dict.trim())} lacks descr, fortran_order or shape`);
  const dims = shape
    .split(',')
    .map((s) => s.trim())
    .filter((s) => s !== '')
    .map((s) => Number(s.replace(/L$/, '')));
  if (dims.some((d) => !Number.isSafeInteger(d) || d < 0)) throw bad(`the shape (${shape}) is not a list of sizes`);
  return { descr, fortranOrder: fortran === 'True', shape: dims, dataOffset: start + length };
}

/** Bytes per element and a reader for the numeric dtypes an initial file may use. */
export function numericDtype(descr: string): { size: number; read: (view: DataView, at: number) => number } | undefined {
  const m = /^([<>|=])([fiu])(\d+)$/.exec(descr);
  if (!m) return undefined;
  const little = m[1] === '<' || m[1] === '|' || (m[1] === '=' && endianness() === 'LE');
  const size = Number(m[3]);
  const key = `${m[2]}${size}`;
  const readers: Record<string, (v: DataView, at: number) => number> = {
    f8: (v, at) => v.getFloat64(at, little),
    f4: (v, at) => v.getFloat32(at, little),
    i8: (v, at) => Number(v.getBigInt64(at, little)),
    i4: (v, at) => v.getInt32(at, little),
    i2: (v, at) => v.getInt16(at, little),
    i1: (v, at) => v.getInt8(at),
    u8: (v, at) => Number(v.getBigUint64(at, little)),
    u4: (v, at) => v.getUint32(at, little),
    u2: (v, at) => v.getUint16(at, little),
    u1: (v, at) => v.getUint8(at),
  };
  const read = readers[key] as ((v: DataView, at: number) => number) | undefined;
  return read === undefined ? undefined : { size, read };
}
