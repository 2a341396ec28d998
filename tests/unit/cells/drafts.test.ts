import { afterEach, beforeEach, describe, expect, test, vi } from 'vitest';
import { DraftKeeper } from '../../../widgets/cells/drafts.ts';
import { EditStore } from '../../../widgets/cells/storage.ts';

function memoryStorage(): Storage {
  const items = new Map<string, string>();
  return {
    get length() {
      return items.size;
    },
    clear: () => items.clear(),
    getItem: (key) => items.get(key) ?? null,
    key: (index) => [...items.keys()][index] ?? null,
    removeItem: (key) => void items.delete(key),
    setItem: (key, value) => void items.set(key, value),
  };
}

describe('DraftKeeper(store, cellId, original, hash)', () => {
  let store: EditStore;
  beforeEach(() => {
    vi.useFakeTimers();
    store = new EditStore('chapter', memoryStorage());
  });
  afterEach(() => vi.useRealTimers());

  test('starting() applies an edit of this original and offers one of an older original', () => {
    expect(new DraftKeeper(store, 'a', 'a = 1', 'h1').starting()).toEqual({ kind: 'none' });
    store.save('a', 'a = 2', 'h1');
    expect(new DraftKeeper(store, 'a', 'a = 1', 'h1').starting()).toEqual({ kind: 'apply', source: 'a = 2' });
    const keeper = new DraftKeeper(store, 'a', 'a = 10', 'h2');
    expect(keeper.starting()).toMatchObject({ kind: 'offer', edit: { source: 'a = 2', base: 'h1' } });
    expect(keeper.offering).toBe(true);
  });

  test('changed(source) saves after the reader pauses', () => {
    const keeper = new DraftKeeper(store, 'a', 'a = 1', 'h');
    keeper.changed('a = 2');
    expect(store.load('a')).toBeNull();
    vi.advanceTimersByTime(1000);
    expect(store.load('a')).toMatchObject({ source: 'a = 2', base: 'h' });
  });

  test('commit(original) forgets the edit', () => {
    const keeper = new DraftKeeper(store, 'a', 'a = 1', 'h');
    keeper.commit('a = 2');
    keeper.commit('a = 1');
    expect(store.load('a')).toBeNull();
  });

  test('nothing overwrites an offered edit until the offer closes', () => {
    store.save('a', 'a = 2', 'old');
    const keeper = new DraftKeeper(store, 'a', 'a = 1', 'new');
    keeper.starting();
    keeper.changed('a = 3');
    vi.advanceTimersByTime(1000);
    keeper.commit('a = 4');
    expect(store.load('a')).toMatchObject({ source: 'a = 2', base: 'old' });
    keeper.closeOffer();
    keeper.commit('a = 4');
    expect(store.load('a')).toMatchObject({ source: 'a = 4', base: 'new' });
  });
});
