/**
 * Keeps an exercise's answer-bearing parts (its truth's arguments, known
 * mistakes, hints, worked solution, reference code) out of the page's plain
 * text, so that reading the page's source or searching it does not show the
 * answer by accident. This is obfuscation, not secrecy: the key is the
 * exercise's id, and anyone who reads this file can undo it. The book says
 * so where the exercises are (grading is for learning, not for exams).
 *
 * JSON → UTF-8 → deflate (raw) → XOR with a keystream drawn from the id
 * (xorshift32 seeded by an FNV-1a hash) → base64. The same in Node (the
 * build seals) and the browser (the exercise unseals), through the
 * Compression Streams both have.
 *
 * Deflated first because scrambled bytes do not compress: the hints and
 * solutions are HTML with typeset math, 20–50 KB an exercise, and sealed
 * plain they made up 40–60 % of a chapter's gzipped page (order and chaos:
 * 175 KB, of which the seals 118 KB), which a phone on a slow network
 * downloads before the page is whole. Deflated, they are a tenth of that.
 */

function keystream(id: string): () => number {
  let state = 0x811c9dc5;
  for (const char of id) state = Math.imul(state ^ char.charCodeAt(0), 0x01000193) >>> 0;
  state ||= 1;
  return () => {
    state ^= state << 13;
    state >>>= 0;
    state ^= state >>> 17;
    state ^= state << 5;
    state >>>= 0;
    return state & 0xff;
  };
}

function scramble(bytes: Uint8Array, id: string): Uint8Array<ArrayBuffer> {
  const next = keystream(id);
  return bytes.map((byte) => byte ^ next());
}

/** `bytes` through a compression or decompression stream, whole. */
async function through(bytes: Uint8Array<ArrayBuffer>, stream: CompressionStream | DecompressionStream): Promise<Uint8Array<ArrayBuffer>> {
  const written = new Blob([bytes]).stream().pipeThrough(stream);
  return new Uint8Array(await new Response(written).arrayBuffer());
}

export async function seal(value: unknown, id: string): Promise<string> {
  const packed = await through(new TextEncoder().encode(JSON.stringify(value)), new CompressionStream('deflate-raw'));
  let binary = '';
  for (const byte of scramble(packed, id)) binary += String.fromCharCode(byte);
  return btoa(binary);
}

/**
 * The sealed value; rejects when `sealed` was not made by {@link seal} with
 * this id (a damaged page, or another exercise's seal): the bytes then do
 * not inflate, or what they inflate to is not JSON.
 */
export async function unseal(sealed: string, id: string): Promise<unknown> {
  const binary = atob(sealed);
  const packed = scramble(Uint8Array.from(binary, (char) => char.charCodeAt(0)), id);
  return JSON.parse(new TextDecoder('utf-8', { fatal: true }).decode(await through(packed, new DecompressionStream('deflate-raw'))));
}
