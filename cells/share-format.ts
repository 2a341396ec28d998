/**
 * A reader's edits of one chapter as a URL fragment, and back:
 * `#share=<version>.<base64url of zlib-deflated JSON>`.
 *
 * The fragment is the part of a URL that browsers never send to a server,
 * so a shared link carries the edits from one browser to another and
 * nowhere else. Compression is the browser's own (CompressionStream), so
 * nothing is added to the page's code; the zlib format ('deflate', not
 * 'deflate-raw') costs 6 bytes more and carries an Adler-32 checksum, so a
 * link changed in transit is refused rather than run as different code. Decoding never throws: anything
 * malformed, truncated, oversized or of another version gives a message for
 * the reader. No DOM here (see share-ui.ts for the page's side).
 *
 * On the wire (before compression), the cells in page order:
 *   {"c":"<chapter slug>","e":[["<cell id>","<source>","<hash or after>"], …]}
 * For a chapter cell the third field is `data-cell-hash` of the original
 * the edit was made from; for a reader's added cell (`added-xxxxxxxx`) it is
 * the id of the cell it follows.
 */

import { SHARE_PREFIX as PREFIX } from './share-fragment.ts';

/** The format this code writes; a link with another number is refused, with a message. */
export const SHARE_VERSION = 1;

/** Longest fragment read (browsers accept far longer URLs; no typical edit comes near). */
export const MAX_FRAGMENT_CHARS = 64_000;
/** Most text a fragment may inflate to: a few hundred kB of JSON is already far beyond any chapter's edits. */
export const MAX_INFLATED_BYTES = 512_000;
const MAX_CELLS = 500;

const ADDED_ID = /^added-[0-9a-f]{8}$/;
/** A chapter cell's id: its name, `name-dupN`, or `cell-N` (site/lib/remark-cells.mjs). */
const CELL_ID = /^[\p{L}\p{N}_$-]{1,200}$/u;
const HASH = /^[0-9a-f]{1,64}$/;
const SLUG = /^[a-z0-9][a-z0-9-]{0,100}$/;

/** One shared cell: an edit of a chapter cell, or a cell the reader added. */
export type SharedCell =
  | { readonly kind: 'edit'; readonly id: string; readonly source: string; /** data-cell-hash of the original it was made from. */ readonly base: string }
  | { readonly kind: 'added'; readonly id: string; readonly source: string; /** The cell it follows. */ readonly after: string };

export interface SharedEdits {
  /** The chapter's slug (`data-chapter`). */
  readonly chapter: string;
  /** In page order. */
  readonly cells: readonly SharedCell[];
}

export type DecodedShare = { readonly ok: true; readonly edits: SharedEdits } | { readonly ok: false; readonly message: string };

/** The fragment (without `#`) that carries `edits`. */
export async function encodeShare(edits: SharedEdits): Promise<string> {
  const wire = {
    c: edits.chapter,
    e: edits.cells.map((cell) => [cell.id, cell.source, cell.kind === 'edit' ? cell.base : cell.after]),
  };
  const bytes = await pipe(new TextEncoder().encode(JSON.stringify(wire)), new CompressionStream('deflate'), Infinity);
  return `${PREFIX}${SHARE_VERSION}.${toBase64Url(bytes)}`;
}

/** Reads a fragment made by {@link encodeShare}; never throws. */
export async function decodeShare(hash: string): Promise<DecodedShare> {
  const fragment = hash.replace(/^#/, '');
  if (!fragment.startsWith(PREFIX)) return fail('This link does not carry shared edits.');
  if (fragment.length > MAX_FRAGMENT_CHARS) return fail(`The link's shared edits are too long to read (${fragment.length} characters; at most ${MAX_FRAGMENT_CHARS}).`);
  const match = /^(\d{1,6})\.([A-Za-z0-9_-]*)$/.exec(fragment.slice(PREFIX.length));
  if (!match) return fail('The link is damaged: its shared edits are not in the form Phasebook writes. Was it cut short or changed?');
  const version = Number(match[1]);
  if (version !== SHARE_VERSION) {
    return fail(`The link was made by ${version > SHARE_VERSION ? 'a newer' : 'another'} version of Phasebook (format ${version}; this page reads format ${SHARE_VERSION}).`);
  }
  let text: string;
  try {
    const inflated = await pipe(fromBase64Url(match[2]), new DecompressionStream('deflate'), MAX_INFLATED_BYTES);
    text = new TextDecoder('utf-8', { fatal: true }).decode(inflated);
  } catch (error) {
    if (error instanceof TooLarge) return fail(`The link's shared edits are too large to open (more than ${MAX_INFLATED_BYTES / 1000} kB).`);
    return fail('The link is damaged: its shared edits cannot be unpacked. It may have been cut short when it was copied.');
  }
  let wire: unknown;
  try {
    wire = JSON.parse(text);
  } catch {
    return fail('The link is damaged: its shared edits cannot be read.');
  }
  const edits = fromWire(wire);
  return typeof edits === 'string' ? fail(`The link's shared edits are not valid: ${edits}.`) : { ok: true, edits };
}

function fail(message: string): DecodedShare {
  return { ok: false, message };
}

/** The shared edits in `wire`, or why they are not valid. */
function fromWire(wire: unknown): SharedEdits | string {
  if (typeof wire !== 'object' || wire === null || Array.isArray(wire)) return 'not an object';
  const { c: chapter, e: entries } = wire as { c?: unknown; e?: unknown };
  if (typeof chapter !== 'string' || !SLUG.test(chapter)) return 'no chapter named';
  if (!Array.isArray(entries)) return 'no list of cells';
  if (entries.length > MAX_CELLS) return `more than ${MAX_CELLS} cells`;
  const cells: SharedCell[] = [];
  const seen = new Set<string>();
  for (const entry of entries as unknown[]) {
    if (!Array.isArray(entry) || entry.length !== 3 || !entry.every((field) => typeof field === 'string')) return 'a cell is not [id, source, reference]';
    const [id, source, reference] = entry as [string, string, string];
    if (seen.has(id)) return `cell ${id} appears twice`;
    seen.add(id);
    if (ADDED_ID.test(id)) {
      // An added cell follows a chapter cell or an added cell listed before it (page order).
      if (!CELL_ID.test(reference) || (ADDED_ID.test(reference) && !seen.has(reference))) return `added cell ${id} follows no cell before it`;
      cells.push({ kind: 'added', id, source, after: reference });
    } else {
      if (!CELL_ID.test(id) || id.startsWith('added-')) return `"${id.slice(0, 40)}" is not a cell id`;
      if (!HASH.test(reference)) return `cell ${id} has no valid hash`;
      cells.push({ kind: 'edit', id, source, base: reference });
    }
  }
  return { chapter, cells };
}

class TooLarge extends Error {}

/** Runs `bytes` through a (de)compression stream, stopping once more than `limit` bytes come out. */
async function pipe(bytes: Uint8Array, transform: CompressionStream | DecompressionStream, limit: number): Promise<Uint8Array> {
  const reader = new Blob([bytes as BlobPart]).stream().pipeThrough(transform).getReader();
  const chunks: Uint8Array[] = [];
  let total = 0;
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    total += value.length;
    if (total > limit) {
      await reader.cancel().catch(() => undefined);
      throw new TooLarge();
    }
    chunks.push(value);
  }
  const out = new Uint8Array(total);
  let offset = 0;
  for (const chunk of chunks) {
    out.set(chunk, offset);
    offset += chunk.length;
  }
  return out;
}

/** Base64 with the URL-safe alphabet and no padding (RFC 4648 §5): every character is legal in a fragment. */
export function toBase64Url(bytes: Uint8Array): string {
  let binary = '';
  for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

/** Inverse of {@link toBase64Url}; throws on a length no encoding gives. */
export function fromBase64Url(text: string): Uint8Array {
  if (text.length % 4 === 1) throw new SyntaxError('impossible base64 length');
  const binary = atob(text.replace(/-/g, '+').replace(/_/g, '/') + '='.repeat((4 - (text.length % 4)) % 4));
  return Uint8Array.from(binary, (char) => char.charCodeAt(0));
}
