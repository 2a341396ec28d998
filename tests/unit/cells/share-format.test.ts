import { readFileSync } from 'node:fs';
import { describe, expect, test } from 'vitest';
import {
  decodeShare,
  encodeShare,
  fromBase64Url,
  MAX_INFLATED_BYTES,
  SHARE_VERSION,
  toBase64Url,
  type SharedEdits,
} from '../../../cells/share-format.ts';
import { isShareFragment } from '../../../cells/share-fragment.ts';

/** The fragment of a wire object, packed as encodeShare packs one, but with any content (for malformed cases). */
async function pack(wire: unknown, version = SHARE_VERSION): Promise<string> {
  const bytes = new TextEncoder().encode(typeof wire === 'string' ? wire : JSON.stringify(wire));
  const packed = new Uint8Array(await new Response(new Blob([bytes]).stream().pipeThrough(new CompressionStream('deflate'))).arrayBuffer());
  return `share=${version}.${toBase64Url(packed)}`;
}

// Sources as the playground chapter (content/playground.mdx) has them, each changed the way a reader would.
const PARAMS = 'params = ({u: 0.3, gamma: 21.7, beta: 0.2, kappa: 8, omega: 12, f: 20})';
const H = 'H = "p^2/2 + omega^2*(1 + u*cos(gamma*t))*q^2/2 - f*q*cos(kappa*t + beta) + q^4/4"';
const ADDED = 'energies = sim.states.map(([q, p]) => p*p/2 + params.omega**2*q*q/2)';
/** A long, realistic origin and path (a GitHub Pages project site). */
const PAGE_URL = 'https://some-university.github.io/phasebook-course-2026/playground/';

const sample: SharedEdits = {
  chapter: 'playground',
  cells: [
    { kind: 'edit', id: 'H', source: H, base: '0123456789ab' },
    { kind: 'edit', id: 'params', source: PARAMS, base: 'ba9876543210' },
    { kind: 'added', id: 'added-0badcafe', source: ADDED, after: 'params' },
    { kind: 'added', id: 'added-12345678', source: '', after: 'added-0badcafe' },
    { kind: 'edit', id: 'cell-3', source: 'md`Ünïcödé — ∂H/∂p, 𝜔 and "quotes"\\n`', base: 'ffffffffffff' },
  ],
};

describe('encodeShare / decodeShare', () => {
  test('round trip: every cell, its kind, source and reference come back in order', async () => {
    const fragment = await encodeShare(sample);
    expect(isShareFragment(`#${fragment}`)).toBe(true);
    expect(fragment.startsWith(`share=${SHARE_VERSION}.`)).toBe(true);
    // Only characters that need no escaping in a URL fragment.
    expect(fragment).toMatch(/^share=\d+\.[A-Za-z0-9_-]+$/);
    const decoded = await decodeShare(`#${fragment}`);
    expect(decoded).toEqual({ ok: true, edits: sample });
  });

  test('round trip of large and binary-looking text (every byte value survives base64url)', async () => {
    const source = Array.from({ length: 3000 }, (_, i) => String.fromCodePoint(32 + ((i * 7919) % 5000))).join('');
    const edits: SharedEdits = { chapter: 'kepler', cells: [{ kind: 'edit', id: 'stars', source, base: 'abc' }] };
    expect(await decodeShare(await encodeShare(edits))).toEqual({ ok: true, edits });
    const bytes = Uint8Array.from({ length: 256 }, (_, i) => i);
    expect([...fromBase64Url(toBase64Url(bytes))]).toEqual([...bytes]);
  });

  test('links of typical edits are as long as the README says, far under 2000 characters', async () => {
    // The README's promise (its "Share your edits" paragraph), read from it, so that the two cannot drift apart.
    const readme = readFileSync(new URL('../../../README.md', import.meta.url), 'utf8').replace(/\s+/g, ' ');
    const said = readme.match(/on a (\d+)-character page address, (\d+) for one changed parameter cell, (\d+) for one changed H, (\d+) for an added cell, (\d+) for all three/);
    expect(said, 'the README quotes the lengths of typical links').not.toBeNull();
    const [pageUrlLength, ...documented] = said!.slice(1).map(Number);
    expect(PAGE_URL.length).toBe(pageUrlLength);
    const lengths: Record<string, number> = {};
    const cases: Record<string, SharedEdits['cells']> = {
      'one parameter cell': [sample.cells[1]],
      'one H': [sample.cells[0]],
      'an added cell': [sample.cells[2]],
      'all three': sample.cells.slice(0, 3),
    };
    for (const [name, cells] of Object.entries(cases)) {
      lengths[name] = `${PAGE_URL}#${await encodeShare({ chapter: 'playground', cells })}`.length;
      expect(lengths[name]).toBeLessThan(2000);
    }
    // Exact, as documented: deflate's output for a given input is fixed by zlib's level and strategy, and a
    // change of a single byte in what a link carries (a field added, a longer version tag) moves the length.
    expect(Object.values(lengths)).toEqual(documented);
    // Packing earns its keep: shorter than the same JSON escaped for a URL, the alternative that needs no code.
    const all = await encodeShare({ chapter: 'playground', cells: sample.cells.slice(0, 3) });
    const json = JSON.stringify({ c: 'playground', e: sample.cells.slice(0, 3).map((c) => [c.id, c.source, 'x'.repeat(12)]) });
    expect(all.length).toBeLessThan(encodeURIComponent(json).length);
  });
});

describe('decodeShare on bad input: a message, never a throw', () => {
  const bad = async (fragment: string): Promise<string> => {
    const decoded = await decodeShare(fragment);
    expect(decoded.ok).toBe(false);
    return decoded.ok ? '' : decoded.message;
  };

  test('a fragment that is not a share', async () => {
    expect(isShareFragment('#cell-omega')).toBe(false);
    expect(await bad('#cell-omega')).toMatch(/does not carry shared edits/);
  });

  test('truncated links, cut anywhere, are reported as damaged', async () => {
    const fragment = await encodeShare(sample);
    for (const keep of [fragment.length - 1, fragment.length - 5, Math.floor(fragment.length / 2), 'share=1.'.length + 3, 'share=1.'.length, 'share=1'.length, 'share='.length]) {
      expect(await bad(fragment.slice(0, keep))).toMatch(/damaged|form Phasebook writes/);
    }
  });

  test('characters outside base64url, a changed byte, and impossible lengths', async () => {
    const fragment = await encodeShare(sample);
    expect(await bad(`${fragment.slice(0, 20)}+/=${fragment.slice(23)}`)).toMatch(/form Phasebook writes/);
    expect(await bad('share=1.A')).toMatch(/damaged/);
    expect(await bad('share=1.AAAAAAAAAAAA')).toMatch(/damaged/);
    // A link changed in transit is refused, never decoded into other code: the zlib checksum sees a changed
    // byte. (The unused padding bits that end a deflate stream change nothing, so they may decode, unchanged.)
    const bytes = fromBase64Url(fragment.slice('share=1.'.length));
    let refused = 0;
    for (let i = 0; i < bytes.length; i++) {
      for (const flip of [0x01, 0x80]) {
        const changed = bytes.slice();
        changed[i] ^= flip;
        const decoded = await decodeShare(`share=1.${toBase64Url(changed)}`);
        if (decoded.ok) expect(decoded.edits).toEqual(sample);
        else refused++;
      }
    }
    expect(refused).toBeGreaterThan(2 * bytes.length - 4);
  });

  test('the version field: another format is refused and named', async () => {
    const inner = (await encodeShare(sample)).slice('share=1.'.length);
    expect(await bad(`share=2.${inner}`)).toMatch(/newer version of Phasebook \(format 2; this page reads format 1\)/);
    expect(await bad(`share=0.${inner}`)).toMatch(/another version of Phasebook \(format 0/);
    expect(await bad(`share=v1.${inner}`)).toMatch(/form Phasebook writes/);
    // The same payload under the right number reads.
    expect((await decodeShare(`share=1.${inner}`)).ok).toBe(true);
  });

  test('well-packed but wrong content: not JSON, wrong shapes, bad ids, duplicates, dangling added cells', async () => {
    expect(await bad(await pack('{"c":'))).toMatch(/cannot be read/);
    expect(await bad(await pack([1, 2]))).toMatch(/not an object/);
    expect(await bad(await pack({ e: [] }))).toMatch(/no chapter/);
    expect(await bad(await pack({ c: '../etc', e: [] }))).toMatch(/no chapter/);
    expect(await bad(await pack({ c: 'kepler' }))).toMatch(/no list of cells/);
    expect(await bad(await pack({ c: 'kepler', e: [['a', 1, 'ab']] }))).toMatch(/not \[id, source, reference\]/);
    expect(await bad(await pack({ c: 'kepler', e: [['a', 'a = 1']] }))).toMatch(/not \[id, source, reference\]/);
    expect(await bad(await pack({ c: 'kepler', e: [['a"><img', 'x', 'ab']] }))).toMatch(/is not a cell id/);
    expect(await bad(await pack({ c: 'kepler', e: [['a', 'x', 'not-hex']] }))).toMatch(/no valid hash/);
    expect(await bad(await pack({ c: 'kepler', e: [['a', 'x', 'ab'], ['a', 'y', 'ab']] }))).toMatch(/appears twice/);
    expect(await bad(await pack({ c: 'kepler', e: [['added-00000001', 'x', 'added-00000002'], ['added-00000002', 'y', 'a']] }))).toMatch(/follows no cell before it/);
    expect(await bad(await pack({ c: 'kepler', e: [['added-zz', 'x', 'a']] }))).toMatch(/is not a cell id/);
    expect(await bad(await pack({ c: 'kepler', e: Array.from({ length: 501 }, (_, i) => [`c${i}`, '', 'ab']) }))).toMatch(/more than 500 cells/);
  });

  test('a small link that inflates beyond the limit (a "zip bomb") is refused without inflating it all', async () => {
    const huge = JSON.stringify({ c: 'kepler', e: [['a', ' '.repeat(MAX_INFLATED_BYTES * 4), 'ab']] });
    const fragment = await pack(huge);
    expect(fragment.length).toBeLessThan(10_000);
    expect(await bad(fragment)).toMatch(/too large to open/);
  });

  test('an over-long fragment is refused before it is read', async () => {
    expect(await bad(`share=1.${'A'.repeat(70_000)}`)).toMatch(/too long to read/);
  });
});
