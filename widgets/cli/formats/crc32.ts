/**
 * CRC-32 (ISO 3309, the one ZIP uses), continued over successive pieces:
 * zlib's own where Node has it (20.15 and later), a table otherwise.
 */
import * as zlib from 'node:zlib';

let table: Uint32Array | undefined;

function tableCrc(bytes: Uint8Array, crc: number): number {
  if (!table) {
    table = new Uint32Array(256);
    for (let n = 0; n < 256; n++) {
      let c = n;
      for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
      table[n] = c >>> 0;
    }
  }
  let c = ~crc >>> 0;
  for (let i = 0; i < bytes.length; i++) c = table[(c ^ bytes[i]) & 0xff] ^ (c >>> 8);
  return ~c >>> 0;
}

const native = (zlib as { crc32?: (data: Uint8Array, value?: number) => number }).crc32;

/** The CRC-32 of what came before (`crc`) followed by `bytes`. */
export function crc32(bytes: Uint8Array, crc = 0): number {
  return native ? native(bytes, crc) : tableCrc(bytes, crc);
}

/** The table version, for tests to hold zlib's against. */
export const crc32Table = tableCrc;
