/**
 * CRC-32 (ISO 3309, the one ZIP uses), continued over successive pieces:
 * zlib's own where Node has it (20.15 and 22.2 on), a table otherwise. The
 * package allows any Node 20, so the table is the CRC of some users' files:
 * it is exported to be tested on its own, against the check value and zlib.
 */
import * as zlib from 'node:zlib';

let table: Uint32Array | undefined;

/** The CRC-32 of what came before (`crc`) followed by `bytes`, by the 256-entry table of the reflected polynomial 0xEDB88320. */
export function crc32ByTable(bytes: Uint8Array, crc = 0): number {
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
  return native ? native(bytes, crc) : crc32ByTable(bytes, crc);
}
