import { describe, expect, test } from 'vitest';
import { EditStore, editKey } from '../../../widgets/cells/storage.ts';

/** An in-memory Storage; `broken` makes every call throw, as a forbidden localStorage does. */
function memoryStorage(broken = false): Storage {
  const items = new Map<string, string>();
  const guard = () => {
    if (broken) throw new DOMException('denied', 'SecurityError');
  };
  return {
    get length() {
      return items.size;
    },
    clear: () => items.clear(),
    getItem: (key) => (guard(), items.get(key) ?? null),
    key: (index) => [...items.keys()][index] ?? null,
    removeItem: (key) => (guard(), void items.delete(key)),
    setItem: (key, value) => (guard(), void items.set(key, value)),
  };
}

describe('EditStore(chapter, storage)', () => {
  test('editKey(chapter, cellId) names the chapter and the cell', () => {
    expect(editKey('introduction', 'omega')).toBe('phasebook:v1:edit:introduction:omega');
  });

  test('save then load returns the source and the base hash', () => {
    const store = new EditStore('introduction', memoryStorage());
    expect(store.save('omega', 'omega = 5', 'abc123')).toBe(true);
    expect(store.load('omega')).toMatchObject({ source: 'omega = 5', base: 'abc123' });
    expect(store.load('period')).toBeNull();
  });

  test('keeps chapters apart', () => {
    const storage = memoryStorage();
    new EditStore('introduction', storage).save('x', 'x = 1', 'h');
    expect(new EditStore('about', storage).load('x')).toBeNull();
  });

  test('forget removes the edit', () => {
    const store = new EditStore('introduction', memoryStorage());
    store.save('omega', 'omega = 5', 'h');
    store.forget('omega');
    expect(store.load('omega')).toBeNull();
  });

  test('load ignores corrupt or foreign values', () => {
    const storage = memoryStorage();
    storage.setItem(editKey('c', 'a'), '{not json');
    storage.setItem(editKey('c', 'b'), JSON.stringify({ source: 1 }));
    const store = new EditStore('c', storage);
    expect(store.load('a')).toBeNull();
    expect(store.load('b')).toBeNull();
  });

  test('fails quietly when storage is forbidden or missing', () => {
    for (const store of [new EditStore('c', memoryStorage(true)), new EditStore('c', null)]) {
      expect(store.save('a', 'a = 1', 'h')).toBe(false);
      expect(store.load('a')).toBeNull();
      expect(() => store.forget('a')).not.toThrow();
    }
  });
});
