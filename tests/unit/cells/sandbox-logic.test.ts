/**
 * The sandbox's decisions that need no page (cells/sandbox/):
 * allocation bounds, reload-loop detection, where a navigation may go, and
 * how many history entries a cell may add.
 */
import { describe, expect, test } from 'vitest';
import { allocationScope, arrayRefusal, bufferRefusal, MAX_ARRAY_LENGTH, MAX_BUFFER_BYTES } from '../../../cells/sandbox/allocation.ts';
import { editsKey, loopTurns, selfLoadNote, type ThisLoad } from '../../../cells/sandbox/reload-loop.ts';
import { forbiddenDestination, HISTORY_BURST, HISTORY_WINDOW_MS, HistoryBudget } from '../../../cells/sandbox/navigation.ts';

describe('allocation bounds', () => {
  test('say the size asked for and the bound', () => {
    expect(arrayRefusal('Array(1e9)', 1e9)).toBe('Array(1e9) would make an array of 1e9 elements, more than the 3e7 the book lets a cell make at once: an array that size can crash the tab');
    expect(bufferRefusal('new Float64Array(1e10)', 8e10)).toBe('new Float64Array(1e10) would take 80 GB, more than the 1 GB the book lets a cell allocate at once');
    expect(arrayRefusal('Array(10)', 10)).toBeNull();
    expect(bufferRefusal('x', MAX_BUFFER_BYTES)).toBeNull();
  });

  test('the guarded constructors refuse what is known to be too big, before allocating, and make the rest as usual', () => {
    const scope = allocationScope() as { Array: ArrayConstructor; Float64Array: Float64ArrayConstructor; ArrayBuffer: ArrayBufferConstructor; Uint8Array: Uint8ArrayConstructor };
    const { Array: A, Float64Array: F, ArrayBuffer: B, Uint8Array: U } = scope;
    expect(() => [...A(1e9).keys()]).toThrow(/^Array\(1e9\) would make an array of 1e9 elements/);
    expect(() => new A(1e9).fill(0)).toThrow(RangeError);
    expect(() => A.from({ length: 1e9 })).toThrow(/Array\.from would make an array of 1e9 elements/);
    expect(() => new F(1e10)).toThrow(/^new Float64Array\(1e10\) would take 80 GB/);
    expect(() => F.from({ length: 2e8 })).toThrow(/would take 1.6 GB/);
    expect(() => new B(2e9)).toThrow(RangeError);
    expect(() => new (B as unknown as new (n: number, o: object) => ArrayBuffer)(8, { maxByteLength: 2 ** 40 })).toThrow(/maxByteLength/);
    // Within the bounds, everything is as with the page's own.
    expect(A(3).length).toBe(3);
    expect(A(1, 2, 3)).toEqual([1, 2, 3]);
    expect(new A(MAX_ARRAY_LENGTH).length).toBe(MAX_ARRAY_LENGTH);
    expect(A.from('ab')).toEqual(['a', 'b']);
    expect(A.isArray(A.of(1))).toBe(true);
    expect([] instanceof A).toBe(true);
    expect(new F([1, 2]).length).toBe(2);
    expect(new U(new B(16), 4, 8).length).toBe(8);
    class Mine extends A {}
    expect(new Mine(2)).toBeInstanceOf(Mine);
  });
});

describe('reload loops', () => {
  const edits = editsKey([['H0', 'H0 = { location.reload(); return 1 }']]);
  /** A load that began at `loadedAt`, its edits running from `ranAt` (by default, 8 s later: a slow load). */
  const load = (loadedAt: number, ranAt = loadedAt + 8_000, key = edits): ThisLoad => ({ path: '/playground/', loadedAt, ranAt, edits: key });

  test('a load the page started itself as soon as its edits ran, with the same edits, is a turn of a loop; turns add up', () => {
    const first = load(1_000);
    const note = selfLoadNote(first, 9_300, loopTurns(null, first));
    expect(loopTurns(note, load(9_350))).toBe(1);
    const second = selfLoadNote(load(9_350), 17_700, 1);
    expect(loopTurns(second, load(17_750))).toBe(2);
  });

  test('not a loop: other edits, another page, edits that ran a while first, or a note about an older load', () => {
    const note = selfLoadNote(load(1_000), 9_300, 0);
    expect(loopTurns(note, load(9_350, undefined, editsKey([['H0', 'H0 = 1']])))).toBe(0);
    expect(loopTurns(note, { ...load(9_350), path: '/kepler/' })).toBe(0);
    expect(loopTurns(selfLoadNote(load(1_000), 60_000, 0), load(60_050))).toBe(0);
    expect(loopTurns(note, load(40_000))).toBe(0);
    expect(loopTurns(null, load(9_350))).toBe(0);
  });

  test('the key of the edits is the same in any order, and differs with any change', () => {
    expect(editsKey([['a', '1'], ['b', '2']])).toBe(editsKey([['b', '2'], ['a', '1']]));
    expect(editsKey([['a', '1']])).not.toBe(editsKey([['a', '2']]));
  });
});

describe('navigation', () => {
  const here = new URL('http://book.test/playground/');
  test('a page of the site may be loaded; another site, or a blob:, data: or about: page, may not', () => {
    expect(forbiddenDestination(new URL('http://book.test/kepler/'), here, false)).toBeNull();
    expect(forbiddenDestination(new URL('http://other.test/?secret'), here, false)).toBe('other.test');
    expect(forbiddenDestination(new URL('blob:http://book.test/1234'), here, false)).toBe('a blob: address');
    expect(forbiddenDestination(new URL('data:text/html,hi'), here, false)).toBe('a data: address');
    expect(forbiddenDestination(new URL('about:blank'), here, false)).toBe('a about: address');
    // The page's own downloads are blobs of its origin.
    expect(forbiddenDestination(new URL('blob:http://book.test/1234'), here, true)).toBeNull();
    expect(forbiddenDestination(new URL('http://other.test/file.csv'), here, true)).toBe('other.test');
  });

  test('history entries: a burst is let through, more are refused (said once) until the window has passed', () => {
    const budget = new HistoryBudget();
    for (let i = 0; i < HISTORY_BURST; i++) expect(budget.take(i)).toEqual({ allowed: true, first: false });
    expect(budget.take(100)).toEqual({ allowed: false, first: true });
    expect(budget.take(200)).toEqual({ allowed: false, first: false });
    expect(budget.take(HISTORY_WINDOW_MS + 1)).toEqual({ allowed: true, first: false });
  });
});
