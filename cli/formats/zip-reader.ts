/**
 * The entries of a ZIP archive on disk, found through its central directory
 * (ZIP64 included), with where each stored entry's bytes begin: enough to
 * read the arrays of an NPZ a piece at a time, however large.
 *
 * Every stored entry's bytes are checked against the CRC-32 the directory
 * records before any is used: a flipped bit in an NPZ's x would otherwise be
 * merged into a new file, or reported by reproduce as the run's difference,
 * instead of as the damage it is. It costs one more read of the file, a
 * megabyte at a time, at zlib's speed.
 */
import { fstatSync, readSync } from 'node:fs';
import { InputError } from '../../core/index.ts';
import { crc32 } from './crc32.ts';

export interface ZipEntry {
  name: string;
  /** 0 stored, 8 deflated */
  method: number;
  size: number;
  compressedSize: number;
  /** the CRC-32 of its uncompressed bytes, as the central directory records it */
  crc: number;
  /** where the entry's bytes start in the file */
  dataOffset: number;
}

/** Bytes read at a time to check a CRC: large enough for zlib's speed, small enough for flat memory. */
const CRC_PIECE = 1 << 20;

function readAt(fd: number, position: number, length: number): Buffer {
  const out = Buffer.alloc(length);
  let done = 0;
  while (done < length) {
    const n = readSync(fd, out, done, length - done, position + done);
    if (n === 0) break;
    done += n;
  }
  return done === length ? out : out.subarray(0, done);
}

/** Every entry of the archive open as `fd`; `what` names it in messages. */
export function zipEntries(fd: number, what: string): Map<string, ZipEntry> {
  const bad = (why: string) => new InputError(`${what} is not a ZIP archive (NPZ) that can be read: ${why}`);
  const fileSize = fstatSync(fd).size;
  const tailLength = Math.min(fileSize, 22 + 0xffff);
  const tail = readAt(fd, fileSize - tailLength, tailLength);
  let end = -1;
  for (let i = tail.length - 22; i >= 0; i--) {
    if (tail.readUInt32LE(i) === 0x06054b50) {
      end = i;
      break;
    }
  }
  if (end < 0) throw bad('no end of central directory');
  let count = tail.readUInt16LE(end + 10);
  let size = tail.readUInt32LE(end + 12);
  let start = tail.readUInt32LE(end + 16);
  if (count === 0xffff || size === 0xffffffff || start === 0xffffffff) {
    const locatorAt = fileSize - tailLength + end - 20;
    const locator = readAt(fd, locatorAt, 20);
    if (locator.length < 20 || locator.readUInt32LE(0) !== 0x07064b50) throw bad('a ZIP64 archive without its locator');
    const record = readAt(fd, Number(locator.readBigUInt64LE(8)), 56);
    if (record.readUInt32LE(0) !== 0x06064b50) throw bad('no ZIP64 end of central directory');
    count = Number(record.readBigUInt64LE(32));
    size = Number(record.readBigUInt64LE(40));
    start = Number(record.readBigUInt64LE(48));
  }
  // Sizes from the file itself: one that points past its end is damage, not a reason to allocate gigabytes.
  if (start + size > fileSize || count > size / 46) throw bad('a central directory beyond the end of the file');
  const directory = readAt(fd, start, size);
  const entries = new Map<string, ZipEntry>();
  let at = 0;
  for (let i = 0; i < count; i++) {
    if (at + 46 > directory.length || directory.readUInt32LE(at) !== 0x02014b50) throw bad('a damaged central directory');
    const method = directory.readUInt16LE(at + 10);
    const crc = directory.readUInt32LE(at + 16);
    let compressedSize = directory.readUInt32LE(at + 20);
    let uncompressed = directory.readUInt32LE(at + 24);
    const nameLength = directory.readUInt16LE(at + 28);
    const extraLength = directory.readUInt16LE(at + 30);
    const commentLength = directory.readUInt16LE(at + 32);
    let offset = directory.readUInt32LE(at + 42);
    const name = directory.subarray(at + 46, at + 46 + nameLength).toString('utf8');
    const extra = directory.subarray(at + 46 + nameLength, at + 46 + nameLength + extraLength);
    for (let e = 0; e + 4 <= extra.length; ) {
      const id = extra.readUInt16LE(e);
      const length = extra.readUInt16LE(e + 2);
      if (id === 0x0001) {
        let f = e + 4;
        const next = () => {
          const v = Number(extra.readBigUInt64LE(f));
          f += 8;
          return v;
        };
        if (uncompressed === 0xffffffff) uncompressed = next();
        if (compressedSize === 0xffffffff) compressedSize = next();
        if (offset === 0xffffffff) offset = next();
      }
      e += 4 + length;
    }
    const local = readAt(fd, offset, 30);
    if (local.length < 30 || local.readUInt32LE(0) !== 0x04034b50) throw bad(`no local header for ${name}`);
    const dataOffset = offset + 30 + local.readUInt16LE(26) + local.readUInt16LE(28);
    const entry = { name, method, size: uncompressed, compressedSize, crc, dataOffset };
    // A compressed entry's CRC is of bytes it would have to inflate; the NPZ reader refuses such an entry anyway.
    if (method === 0) checkCrc(fd, entry, fileSize, bad);
    entries.set(name, entry);
    at += 46 + nameLength + extraLength + commentLength;
  }
  return entries;
}

/** Refuses a stored entry whose bytes do not give the CRC-32 the directory records for them. */
function checkCrc(fd: number, entry: ZipEntry, fileSize: number, bad: (why: string) => InputError): void {
  if (entry.dataOffset + entry.size > fileSize) throw bad(`${entry.name} runs past the end of the file`);
  let crc = 0;
  for (let done = 0; done < entry.size; ) {
    const piece = readAt(fd, entry.dataOffset + done, Math.min(CRC_PIECE, entry.size - done));
    if (piece.length === 0) throw bad(`${entry.name} runs past the end of the file`);
    crc = crc32(piece, crc);
    done += piece.length;
  }
  if (crc !== entry.crc) {
    const hex = (n: number) => `0x${n.toString(16).padStart(8, '0')}`;
    throw bad(`${entry.name} is damaged: its bytes' CRC-32 is ${hex(crc)}, the archive records ${hex(entry.crc)}`);
  }
}

export { readAt };
