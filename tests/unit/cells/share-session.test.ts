import { describe, expect, test } from 'vitest';
import { DraftKeeper } from '../../../cells/drafts.ts';
import type { SharedEdits } from '../../../cells/share-format.ts';
import { MemoryStorage } from '../../../cells/memory-storage.ts';
import { keepShared, markSharedRun, ownEdits, planShared, sharedStore } from '../../../cells/share-session.ts';
import { EditStore } from '../../../cells/storage.ts';

const page = [
  { id: 'H', hash: 'aaaaaaaaaaaa' },
  { id: 'params', hash: 'bbbbbbbbbbbb' },
  { id: 'sim', hash: 'cccccccccccc' },
];
const hashes = new Map(page.map((c) => [c.id, c.hash]));

const link: SharedEdits = {
  chapter: 'playground',
  cells: [
    { kind: 'edit', id: 'H', source: 'H = "p^2/2 + q^4/4"', base: 'aaaaaaaaaaaa' },
    { kind: 'edit', id: 'params', source: 'params = ({omega: 3})', base: '000000000000' },
    { kind: 'edit', id: 'gone', source: 'gone = 1', base: 'dddddddddddd' },
    { kind: 'added', id: 'added-00000001', source: 'mine = 42', after: 'params' },
    { kind: 'added', id: 'added-00000002', source: 'later = 1', after: 'nowhere' },
  ],
};

describe('planShared', () => {
  test('keeps the edits of cells the page has, reports missing and changed ones, re-anchors orphaned added cells', () => {
    const plan = planShared(link, 'playground', page);
    if (typeof plan === 'string') throw new Error(plan);
    expect(plan.cells.map((c) => c.id)).toEqual(['H', 'params', 'added-00000001', 'added-00000002']);
    expect(plan.missing).toEqual(['gone']);
    expect(plan.changed).toEqual(['params']);
    expect(plan.cells.at(-1)).toMatchObject({ kind: 'added', after: 'sim' });
  });

  test('a link of another chapter, or with nothing for this one, is refused with a message', () => {
    expect(planShared(link, 'kepler', page)).toMatch(/another chapter \(“playground”\)/);
    const none: SharedEdits = { chapter: 'playground', cells: [{ kind: 'edit', id: 'gone', source: 'x', base: 'ab' }] };
    expect(planShared(none, 'playground', page)).toMatch(/no edits of the cells this chapter has/);
  });
});

describe('the shared view’s store', () => {
  const plan = planShared(link, 'playground', page);
  if (typeof plan === 'string') throw new Error(plan);

  test('holds every shared edit as a draft on the page’s hash: cells show it and run the original', () => {
    const store = sharedStore('/playground/', plan, hashes);
    // What a cell does on start is decided by drafts.ts from this store.
    const params = new DraftKeeper(store, 'params', 'params = ({omega: 10})', 'bbbbbbbbbbbb');
    expect(params.starting()).toEqual({ kind: 'draft', draft: 'params = ({omega: 3})' });
    const added = new DraftKeeper(store, 'added-00000001', '', 'added');
    expect(added.starting()).toEqual({ kind: 'draft', draft: 'mine = 42' });
    expect(store.loadAdded()).toEqual([
      { id: 'added-00000001', after: 'params' },
      { id: 'added-00000002', after: 'sim' },
    ]);
  });

  test('writes nothing to the reader’s storage (the page’s localStorage)', () => {
    const own = new MemoryStorage();
    const had = Object.getOwnPropertyDescriptor(globalThis, 'localStorage');
    Object.defineProperty(globalThis, 'localStorage', { value: own, configurable: true });
    try {
      const store = sharedStore('/playground/', plan, hashes);
      markSharedRun(store, ['H']);
      expect(store.load('H')?.ran).toBe('H = "p^2/2 + q^4/4"');
      expect(own.length).toBe(0);
      // Whereas a store made the ordinary way does write there (its secret, at least): the check can fail.
      new EditStore('/playground/');
      expect(own.length).toBeGreaterThan(0);
    } finally {
      if (had) Object.defineProperty(globalThis, 'localStorage', had);
      else delete (globalThis as { localStorage?: Storage }).localStorage;
    }
  });

  test('after Run shared edits, cells not started yet start with the shared code', () => {
    const store = sharedStore('/playground/', plan, hashes);
    expect(markSharedRun(store, ['H', 'params', 'absent'])).toEqual(['H', 'params']);
    const h = new DraftKeeper(store, 'H', 'H = "p^2/2 + q^2/2"', 'aaaaaaaaaaaa');
    expect(h.starting()).toEqual({ kind: 'run', ran: 'H = "p^2/2 + q^4/4"', draft: 'H = "p^2/2 + q^4/4"' });
  });
});

describe('keepShared', () => {
  const plan = planShared(link, 'playground', page);
  if (typeof plan === 'string') throw new Error(plan);

  test('lists the reader’s own edits first (so the page can ask), then replaces them all with the shared view', () => {
    const storage = new MemoryStorage();
    const own = new EditStore('/playground/', storage);
    own.save('sim', { draft: 'sim = 1', ran: 'sim = 1', base: 'cccccccccccc' }, null);
    own.save('H', { draft: 'H = "mine"', ran: 'H = "mine"', base: 'aaaaaaaaaaaa' }, null);
    own.saveAdded([{ id: 'added-ffffffff', after: 'H' }]);
    own.save('added-ffffffff', { draft: 'x = 1', ran: 'x = 1', base: 'added' }, null);
    expect(ownEdits(own).sort()).toEqual(['H', 'added-ffffffff', 'sim']);

    const shared = sharedStore('/playground/', plan, hashes);
    markSharedRun(shared, ['H']);
    expect(keepShared(shared, own)).toBe(true);
    const after = new EditStore('/playground/', storage);
    expect(after.load('sim')).toBeNull();
    expect(after.load('added-ffffffff')).toBeNull();
    // What the reader ran in the shared view runs; what was only shown stays a draft.
    expect(after.load('H')).toMatchObject({ draft: 'H = "p^2/2 + q^4/4"', ran: 'H = "p^2/2 + q^4/4"', base: 'aaaaaaaaaaaa' });
    expect(after.load('params')).toMatchObject({ draft: 'params = ({omega: 3})', ran: null, base: 'bbbbbbbbbbbb' });
    expect(after.loadAdded().map((c) => c.id)).toEqual(['added-00000001', 'added-00000002']);
  });

  test('without storage it keeps nothing and says so', () => {
    const forbidden = {
      get length(): number {
        throw new DOMException('denied', 'SecurityError');
      },
      clear() {},
      key: () => null,
      getItem: () => {
        throw new DOMException('denied', 'SecurityError');
      },
      setItem: () => {
        throw new DOMException('denied', 'SecurityError');
      },
      removeItem() {},
    } as Storage;
    const own = new EditStore('/playground/', forbidden);
    expect(keepShared(sharedStore('/playground/', plan, hashes), own)).toBe(false);
  });
});
