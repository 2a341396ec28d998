/**
 * The NPZ container checked by something other than numpy, so that CI
 * without Python still holds it: the NPY header against the bytes
 * numpy.save writes (numpy 2.4.6, copied here), the CRC-32 against its
 * check value and zlib, and the ZIP reader's refusal of an entry whose bytes
 * do not match the CRC its directory records.
 */
import { closeSync, mkdtempSync, openSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import * as zlib from 'node:zlib';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { crc32, crc32ByTable } from '../../../../cli/formats/crc32.ts';
import { npyHeader, npyString, parseNpyHeader } from '../../../../cli/formats/npy.ts';
import { zipEntries } from '../../../../cli/formats/zip-reader.ts';
import { ZipWriter } from '../../../../cli/formats/zip-writer.ts';

let dir: string;
beforeEach(() => {
  dir = mkdtempSync(join(tmpdir(), 'phasebook-zip-'));
});
afterEach(() => rmSync(dir, { recursive: true, force: true }));

/** A version 1.0 NPY header as numpy.save writes it: the dict padded with spaces to 128 bytes in all, then a newline. */
function numpyHeader(dict: string): Buffer {
  const head = Buffer.from([0x93, 0x4e, 0x55, 0x4d, 0x50, 0x59, 1, 0, 118, 0]);
  return Buffer.concat([head, Buffer.from(dict.padEnd(117, ' ') + '\n', 'latin1')]);
}

describe('NPY headers, byte for byte as numpy.save writes them', () => {
  it.each([
    ['<f8', [3, 2], "{'descr': '<f8', 'fortran_order': False, 'shape': (3, 2), }"],
    ['<f8', [7], "{'descr': '<f8', 'fortran_order': False, 'shape': (7,), }"],
    ['<f8', [5, 11, 2], "{'descr': '<f8', 'fortran_order': False, 'shape': (5, 11, 2), }"],
    ['<f8', [0, 4], "{'descr': '<f8', 'fortran_order': False, 'shape': (0, 4), }"],
  ])('npyHeader(%s, %j)', (descr, shape, dict) => {
    const header = npyHeader(descr, shape);
    expect(header.toString('latin1')).toBe(numpyHeader(dict).toString('latin1'));
    // The data starts 64-byte aligned, as numpy's ARRAY_ALIGN wants.
    expect(header.length % 64).toBe(0);
    expect(parseNpyHeader(header, 'x.npy')).toEqual({ descr, fortranOrder: false, shape, dataOffset: 128 });
  });

  it("npyString(text) is numpy.save(np.array(text)): a 0-d <U array of UTF-32 code points", () => {
    const expected = Buffer.concat([
      numpyHeader("{'descr': '<U5', 'fortran_order': False, 'shape': (), }"),
      Buffer.from('68000000e90000006c0000006c0000006f000000', 'hex'),
    ]);
    expect(npyString('héllo').equals(expected)).toBe(true);
  });
});

describe('CRC-32', () => {
  const bytes = Uint8Array.from({ length: 10_000 }, (_, i) => (i * 2654435761) >>> 24);

  it('crc32ByTable, the fallback for Node before 20.15, gives the check value of "123456789" (0xCBF43926) and zlib\'s CRC', () => {
    expect(crc32ByTable(Buffer.from('123456789'))).toBe(0xcbf43926);
    expect(crc32ByTable(new Uint8Array(0))).toBe(0);
    const native = (zlib as { crc32?: (data: Uint8Array, value?: number) => number }).crc32;
    if (native) expect(crc32ByTable(bytes)).toBe(native(bytes));
  });

  it('continues over pieces, the table and crc32 alike', () => {
    const whole = crc32ByTable(bytes);
    expect(crc32ByTable(bytes.subarray(3000), crc32ByTable(bytes.subarray(0, 3000)))).toBe(whole);
    expect(crc32(bytes.subarray(7), crc32(bytes.subarray(0, 7)))).toBe(whole);
  });
});

describe('the ZIP reader checks every stored entry against its CRC', () => {
  /** An archive of two entries as the NPZ writer makes them. */
  function archive(): Buffer {
    const chunks: Uint8Array[] = [];
    const zip = new ZipWriter((b) => chunks.push(Buffer.from(b)));
    zip.add('t.npy', Buffer.from('0123456789'));
    zip.add('x.npy', Buffer.alloc(3 << 20, 7)); // more than one piece of the check
    zip.finish();
    return Buffer.concat(chunks);
  }
  const entriesOf = (bytes: Buffer) => {
    const path = join(dir, 'a.npz');
    writeFileSync(path, bytes);
    const fd = openSync(path, 'r');
    try {
      return zipEntries(fd, path);
    } finally {
      closeSync(fd);
    }
  };

  it('reads an intact archive, with the CRC the writer computed', () => {
    const entries = entriesOf(archive());
    expect([...entries.keys()]).toEqual(['t.npy', 'x.npy']);
    expect(entries.get('t.npy')!.crc).toBe(crc32ByTable(Buffer.from('0123456789')));
  });

  it.each([
    ['the first entry', (a: Buffer) => a.indexOf('0123456789') + 4, 't.npy'],
    ['the last megabyte of a large entry', (a: Buffer) => a.indexOf('x.npy') + 5 + (3 << 20) - 1, 'x.npy'],
  ])('refuses a flipped bit in %s, naming the file and the entry', (_, at, name) => {
    const bytes = archive();
    bytes[at(bytes)] ^= 0x10;
    expect(() => entriesOf(bytes)).toThrow(new RegExp(`a\\.npz is not a ZIP archive \\(NPZ\\) that can be read: ${name.replace('.', '\\.')} is damaged: its bytes' CRC-32 is 0x[0-9a-f]{8}, the archive records 0x[0-9a-f]{8}$`));
  });
});
