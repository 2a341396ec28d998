/**
 * A ZIP archive written front to back, never seeking, as NPZ needs (numpy
 * reads an .npz with Python's zipfile): entries stored uncompressed, each
 * followed by a data descriptor holding the CRC-32 computed as its bytes
 * went by, then the central directory. An entry or offset past 4 GiB gets
 * ZIP64 fields (APPNOTE 6.3, sections 4.3.9, 4.5.3, 4.3.14).
 *
 * Every time stamp is the DOS epoch, 1980-01-01 00:00, so that the same
 * arrays make the same bytes on any day: a dataset's file is reproducible
 * byte for byte.
 */
import { crc32 } from './crc32.ts';

const LIMIT32 = 0xffffffff;
const DOS_DATE_1980_01_01 = (0 << 9) | (1 << 5) | 1;
/** bit 3: sizes and CRC in a data descriptor; bit 11: the name is UTF-8 */
const FLAGS = 0x0008 | 0x0800;

interface Entry {
  name: Buffer;
  offset: number;
  size: number;
  crc: number;
  zip64: boolean;
}

export class ZipWriter {
  private offset = 0;
  private readonly entries: Entry[] = [];
  private current: Entry | undefined;
  private written = 0;

  /**
   * @param emit receives the archive's bytes in order
   * @param forceZip64 writes ZIP64 fields even for small entries, for tests of that path
   */
  constructor(
    private readonly emit: (bytes: Uint8Array) => void,
    private readonly forceZip64 = false,
  ) {}

  /** Starts an entry of exactly `size` bytes. */
  begin(name: string, size: number): void {
    if (this.current) throw new Error(`ZipWriter: ${name} begun inside another entry`);
    const entry: Entry = { name: Buffer.from(name, 'utf8'), offset: this.offset, size, crc: 0, zip64: this.forceZip64 || size >= LIMIT32 || this.offset >= LIMIT32 };
    const extra = entry.zip64 ? zip64Extra([size, size]) : Buffer.alloc(0);
    const header = Buffer.alloc(30);
    header.writeUInt32LE(0x04034b50, 0);
    header.writeUInt16LE(entry.zip64 ? 45 : 20, 4);
    header.writeUInt16LE(FLAGS, 6);
    header.writeUInt16LE(0, 8); // stored
    header.writeUInt16LE(0, 10); // 00:00
    header.writeUInt16LE(DOS_DATE_1980_01_01, 12);
    // CRC and sizes follow the data (flag bit 3); ZIP64 says so with all ones.
    header.writeUInt32LE(0, 14);
    header.writeUInt32LE(entry.zip64 ? LIMIT32 : 0, 18);
    header.writeUInt32LE(entry.zip64 ? LIMIT32 : 0, 22);
    header.writeUInt16LE(entry.name.length, 26);
    header.writeUInt16LE(extra.length, 28);
    this.out(header);
    this.out(entry.name);
    this.out(extra);
    this.current = entry;
    this.written = 0;
  }

  /** Bytes of the current entry. */
  write(bytes: Uint8Array): void {
    const entry = this.current;
    if (!entry) throw new Error('ZipWriter: data outside an entry');
    if (bytes.length === 0) return;
    entry.crc = crc32(bytes, entry.crc);
    this.written += bytes.length;
    this.out(bytes);
  }

  /** Ends the current entry, which must have received exactly its size. */
  end(): void {
    const entry = this.current;
    if (!entry) throw new Error('ZipWriter: end outside an entry');
    if (this.written !== entry.size) throw new Error(`ZipWriter: ${entry.name} was to hold ${entry.size} bytes, got ${this.written}`);
    const descriptor = Buffer.alloc(entry.zip64 ? 24 : 16);
    descriptor.writeUInt32LE(0x08074b50, 0);
    descriptor.writeUInt32LE(entry.crc, 4);
    if (entry.zip64) {
      descriptor.writeBigUInt64LE(BigInt(entry.size), 8);
      descriptor.writeBigUInt64LE(BigInt(entry.size), 16);
    } else {
      descriptor.writeUInt32LE(entry.size, 8);
      descriptor.writeUInt32LE(entry.size, 12);
    }
    this.out(descriptor);
    this.entries.push(entry);
    this.current = undefined;
  }

  /** One whole entry. */
  add(name: string, bytes: Uint8Array): void {
    this.begin(name, bytes.length);
    this.write(bytes);
    this.end();
  }

  /** The central directory and the end records. */
  finish(): void {
    if (this.current) throw new Error('ZipWriter: finish inside an entry');
    const start = this.offset;
    for (const entry of this.entries) {
      const big = entry.zip64 || entry.offset >= LIMIT32;
      const fields = big ? [entry.size, entry.size, entry.offset] : [];
      const extra = big ? zip64Extra(fields) : Buffer.alloc(0);
      const record = Buffer.alloc(46);
      record.writeUInt32LE(0x02014b50, 0);
      record.writeUInt16LE((3 << 8) | 45, 4); // made by: Unix, APPNOTE 4.5
      record.writeUInt16LE(big ? 45 : 20, 6);
      record.writeUInt16LE(FLAGS, 8);
      record.writeUInt16LE(0, 10);
      record.writeUInt16LE(0, 12);
      record.writeUInt16LE(DOS_DATE_1980_01_01, 14);
      record.writeUInt32LE(entry.crc, 16);
      record.writeUInt32LE(big ? LIMIT32 : entry.size, 20);
      record.writeUInt32LE(big ? LIMIT32 : entry.size, 24);
      record.writeUInt16LE(entry.name.length, 28);
      record.writeUInt16LE(extra.length, 30);
      record.writeUInt16LE(0, 32); // comment
      record.writeUInt16LE(0, 34); // disk
      record.writeUInt16LE(0, 36); // internal attributes
      record.writeUInt32LE((0o100644 << 16) >>> 0, 38); // a regular file, rw-r--r--
      record.writeUInt32LE(big ? LIMIT32 : entry.offset, 42);
      this.out(record);
      this.out(entry.name);
      this.out(extra);
    }
    const size = this.offset - start;
    const count = this.entries.length;
    const zip64 = this.forceZip64 || start >= LIMIT32 || size >= LIMIT32 || count >= 0xffff;
    if (zip64) {
      const record = Buffer.alloc(56);
      const at = this.offset;
      record.writeUInt32LE(0x06064b50, 0);
      record.writeBigUInt64LE(44n, 4);
      record.writeUInt16LE((3 << 8) | 45, 12);
      record.writeUInt16LE(45, 14);
      record.writeUInt32LE(0, 16);
      record.writeUInt32LE(0, 20);
      record.writeBigUInt64LE(BigInt(count), 24);
      record.writeBigUInt64LE(BigInt(count), 32);
      record.writeBigUInt64LE(BigInt(size), 40);
      record.writeBigUInt64LE(BigInt(start), 48);
      this.out(record);
      const locator = Buffer.alloc(20);
      locator.writeUInt32LE(0x07064b50, 0);
      locator.writeUInt32LE(0, 4);
      locator.writeBigUInt64LE(BigInt(at), 8);
      locator.writeUInt32LE(1, 16);
      this.out(locator);
    }
    const end = Buffer.alloc(22);
    end.writeUInt32LE(0x06054b50, 0);
    end.writeUInt16LE(0, 4);
    end.writeUInt16LE(0, 6);
    end.writeUInt16LE(zip64 ? 0xffff : count, 8);
    end.writeUInt16LE(zip64 ? 0xffff : count, 10);
    end.writeUInt32LE(zip64 ? LIMIT32 : size, 12);
    end.writeUInt32LE(zip64 ? LIMIT32 : start, 16);
    end.writeUInt16LE(0, 20);
    this.out(end);
  }

  private out(bytes: Uint8Array): void {
    if (bytes.length === 0) return;
    this.offset += bytes.length;
    this.emit(bytes);
  }
}

/** The ZIP64 extended information field (header 0x0001) with the given 8-byte values. */
function zip64Extra(values: readonly number[]): Buffer {
  const extra = Buffer.alloc(4 + 8 * values.length);
  extra.writeUInt16LE(0x0001, 0);
  extra.writeUInt16LE(8 * values.length, 2);
  values.forEach((v, i) => extra.writeBigUInt64LE(BigInt(v), 4 + 8 * i));
  return extra;
}
