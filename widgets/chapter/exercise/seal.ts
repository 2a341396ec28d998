/**
 * Keeps an exercise's answer-bearing parts (its truth's arguments, known
 * mistakes, hints, worked solution, reference code) out of the page's plain
 * text, so that reading the page's source or searching it does not show the
 * answer by accident. This is obfuscation, not secrecy: the key is the
 * exercise's id, and anyone who reads this file can undo it. The book says
 * so where the exercises are (grading is for learning, not for exams).
 *
 * JSON → UTF-8 → XOR with a keystream drawn from the id (xorshift32 seeded
 * by an FNV-1a hash) → base64. The same in Node (the build seals) and the
 * browser (the exercise unseals).
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

function scramble(bytes: Uint8Array, id: string): Uint8Array {
  const next = keystream(id);
  return bytes.map((byte) => byte ^ next());
}

export function seal(value: unknown, id: string): string {
  const bytes = scramble(new TextEncoder().encode(JSON.stringify(value)), id);
  let binary = '';
  for (const byte of bytes) binary += String.fromCharCode(byte);
  return btoa(binary);
}

/** The sealed value, or throws (a SyntaxError) when `sealed` was not made by {@link seal} with this id. */
export function unseal(sealed: string, id: string): unknown {
  const binary = atob(sealed);
  const bytes = scramble(Uint8Array.from(binary, (char) => char.charCodeAt(0)), id);
  return JSON.parse(new TextDecoder().decode(bytes));
}
