/** An in-memory Storage; `fail` makes writes (or every call) throw as a full or forbidden localStorage does. */
export function memoryStorage(fail: 'none' | 'forbidden' | 'full' = 'none'): Storage {
  const items = new Map<string, string>();
  const guard = (write: boolean) => {
    if (fail === 'forbidden') throw new DOMException('denied', 'SecurityError');
    if (fail === 'full' && write) throw new DOMException('full', 'QuotaExceededError');
  };
  return {
    get length() {
      return items.size;
    },
    clear: () => items.clear(),
    getItem: (key) => (guard(false), items.get(key) ?? null),
    key: (index) => [...items.keys()][index] ?? null,
    removeItem: (key) => (guard(true), void items.delete(key)),
    setItem: (key, value) => (guard(true), void items.set(key, value)),
  };
}
