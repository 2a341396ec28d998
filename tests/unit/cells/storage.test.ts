import { describe, expect, test } from 'vitest';
import { recoverText } from '../../../cells/recovery.ts';
import { EditStore } from '../../../cells/storage.ts';
import { memoryStorage } from '../support/memory-storage.ts';

const edit = (draft: string, ran: string | null = draft, base = 'h') => ({ draft, ran, base });

describe('EditStore(page, storage, tab)', () => {
  test('save then load gives back the draft, what ran, the base hash and who wrote it', () => {
    const store = new EditStore('/introduction/', memoryStorage(), 'tab1');
    const result = store.save('omega', edit('omega = 6', 'omega = 5'), null);
    expect(result.ok).toBe(true);
    expect(store.load('omega')).toMatchObject({ draft: 'omega = 6', ran: 'omega = 5', base: 'h', tab: 'tab1' });
    expect(store.load('period')).toBeNull();
  });

  test('keys carry the page path (base path included) and a secret drawn once per browser', () => {
    const storage = memoryStorage();
    const book = new EditStore('/phasebook/kepler/', storage);
    book.save('k', edit('k = 1'), null);
    expect(new EditStore('/other-book/kepler/', storage).load('k')).toBeNull();
    expect(new EditStore('/phasebook/kepler/', storage).load('k')).toMatchObject({ draft: 'k = 1' });
    const key = book.editKey('k')!;
    expect(key).toMatch(/^phasebook:v2:[0-9a-f]{32}:\/phasebook\/kepler\/:edit:k$/);
    expect(storage.getItem(key)).not.toBeNull();
  });

  test('an edit planted under a key without the secret is never read', () => {
    const storage = memoryStorage();
    const store = new EditStore('/introduction/', storage);
    // What an attacker on the same origin could guess: the old v1 key and the v2 key with any other secret.
    storage.setItem('phasebook:v1:edit:introduction:omega', JSON.stringify({ source: 'fetch("//evil")', base: 'h', savedAt: 1 }));
    storage.setItem(`phasebook:v2:${'0'.repeat(32)}:/introduction/:edit:omega`, JSON.stringify({ draft: 'x', ran: 'x', base: 'h', savedAt: 1, tab: 't' }));
    expect(store.load('omega')).toBeNull();
  });

  test('a newer edit from another tab is not overwritten: the save reports a conflict with it', () => {
    const storage = memoryStorage();
    const mine = new EditStore('/p/', storage, 'mine');
    const theirs = new EditStore('/p/', storage, 'theirs');
    const first = mine.save('a', edit('a = 1'), null);
    if (!first.ok) throw new Error('first save failed');
    const known = first.edit.savedAt;
    expect(theirs.save('a', edit('a = 2'), known).ok).toBe(true);
    const clash = mine.save('a', edit('a = 3'), known);
    expect(clash).toMatchObject({ ok: false, reason: 'conflict', current: { draft: 'a = 2', tab: 'theirs' } });
    expect(mine.load('a')).toMatchObject({ draft: 'a = 2' });
    // Forced, as when the reader chooses to keep theirs over mine.
    expect(mine.save('a', edit('a = 3'), known, true).ok).toBe(true);
    expect(theirs.load('a')).toMatchObject({ draft: 'a = 3', tab: 'mine' });
  });

  test('running marks: set, seen by the next load, cleared', () => {
    const storage = memoryStorage();
    new EditStore('/p/', storage).markRunning('loop');
    const next = new EditStore('/p/', storage);
    expect(next.wasRunning('loop')).toBe(true);
    expect(next.wasRunning('other')).toBe(false);
    next.clearRunning('loop');
    expect(new EditStore('/p/', storage).wasRunning('loop')).toBe(false);
  });

  test('all() lists this page’s edits only, for a download', () => {
    const storage = memoryStorage();
    const store = new EditStore('/p/', storage);
    store.save('a', edit('a = 1'), null);
    store.save('b', edit('b = 2', null), null);
    new EditStore('/q/', storage).save('c', edit('c = 3'), null);
    expect(store.all().map(({ cellId }) => cellId).sort()).toEqual(['a', 'b']);
  });

  test('an edit that cannot be read back is not run, but set aside with the text that can be recovered', () => {
    const storage = memoryStorage();
    const store = new EditStore('/c/', storage);
    const whole = JSON.stringify({ draft: 'a = 2', ran: 'a = "two"\nb', base: 'h', savedAt: 1, tab: 't' });
    storage.setItem(store.editKey('a')!, whole.slice(0, whole.indexOf('b"') + 1));
    storage.setItem(store.editKey('b')!, JSON.stringify({ draft: 1 }));
    expect(store.load('a')).toBeNull();
    expect(store.load('b')).toBeNull();
    expect(recoverText(store.damaged('a')!)).toBe('a = "two"\nb');
    expect(recoverText(store.damaged('b')!)).toBe('{"draft":1}');
    // Set aside, the edit's own key is free for the reader's next save, and what is aside stays until they have seen it.
    expect(store.save('a', edit('a = 3'), null).ok).toBe(true);
    expect(recoverText(new EditStore('/c/', storage).damaged('a')!)).toBe('a = "two"\nb');
    store.forgetDamaged('a');
    expect(store.damaged('a')).toBeNull();
  });

  test('a damaged secret orphans no edit: this page’s edits under the old secret are set aside, to be offered', () => {
    const storage = memoryStorage();
    const before = new EditStore('/c/', storage);
    before.save('a', edit('a = 1'), null);
    new EditStore('/other/', storage).save('a', edit('a = 9'), null);
    storage.setItem('phasebook:v2:secret', storage.getItem('phasebook:v2:secret')!.slice(0, 20));
    const after = new EditStore('/c/', storage);
    expect(after.editKey('a')).not.toBe(before.editKey('a'));
    expect(after.load('a')).toBeNull();
    expect(recoverText(after.damaged('a')!)).toBe('a = 1');
    expect(after.damaged('b')).toBeNull();
    // Only when the secret had to be drawn again: with the secret intact, keys under others stay unread (planted ones).
    expect(new EditStore('/other/', storage).damaged('a')).toBeNull();
  });

  test('says why a write did not take: full, or no storage at all; nothing throws', () => {
    const full = new EditStore('/c/', memoryStorage('full'));
    expect(full.available).toBe(false);
    for (const store of [new EditStore('/c/', memoryStorage('forbidden')), new EditStore('/c/', null), full]) {
      expect(store.save('a', edit('a = 1'), null)).toMatchObject({ ok: false, reason: 'unavailable' });
      expect(store.load('a')).toBeNull();
      expect(() => store.forget('a')).not.toThrow();
      expect(store.markRunning('a')).toBe(false);
    }
    // Full only once the secret is kept: the edit itself then does not fit.
    const storage = memoryStorage();
    const store = new EditStore('/c/', storage);
    const real = storage.setItem;
    storage.setItem = () => {
      throw new DOMException('full', 'QuotaExceededError');
    };
    expect(store.save('a', edit('a = 1'), null)).toMatchObject({ ok: false, reason: 'full' });
    storage.setItem = real;
  });
});
