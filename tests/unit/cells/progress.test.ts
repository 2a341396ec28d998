import { describe, expect, test } from 'vitest';
import { ProgressStore } from '../../../cells/progress.ts';
import { EditStore } from '../../../cells/storage.ts';
import { memoryStorage } from '../support/memory-storage.ts';

const chapters = [
  { slug: 'introduction', page: '/course/introduction/', ids: ['a', 'b'] },
  { slug: 'kepler', page: '/course/kepler/', ids: ['c'] },
];

describe('ProgressStore', () => {
  test('a check is kept beside the edits, under the same secret and page path; solved stays solved', () => {
    const storage = memoryStorage();
    new EditStore('/course/introduction/', storage).save('omega', { draft: 'omega = 5', ran: null, base: 'h' }, null);
    const store = new ProgressStore(storage);
    expect(store.attempt('/course/introduction/', 'a', false, '0.6').record).toMatchObject({ status: 'attempted', attempts: 1, answer: '0.6' });
    store.attempt('/course/introduction/', 'a', true, '1.26');
    expect(store.attempt('/course/introduction/', 'a', false, '9').record).toMatchObject({ status: 'solved', attempts: 3 });
    const keys = Array.from({ length: storage.length }, (_, i) => storage.key(i) ?? '');
    const edit = keys.find((k) => k.endsWith(':edit:omega'))!;
    const progress = keys.find((k) => k.endsWith(':exercise:a'))!;
    expect(progress.replace(/:exercise:a$/, '')).toBe(edit.replace(/:edit:omega$/, ''));
    expect(new ProgressStore(memoryStorage()).load('/course/introduction/', 'a')).toBeNull();
    expect(new ProgressStore(storage).load('/other/introduction/', 'a')).toBeNull();
  });

  test('export then import into another browser, under another base path, restores every record', () => {
    const from = new ProgressStore(memoryStorage());
    from.attempt('/course/introduction/', 'a', true, '1.26');
    from.solutionShown('/course/kepler/', 'c');
    const file = JSON.stringify(from.exportFile(chapters));
    const elsewhere = chapters.map((c) => ({ ...c, page: c.page.replace('/course/', '/') }));
    const to = new ProgressStore(memoryStorage());
    expect(to.importFile(file, elsewhere)).toEqual({ imported: 2, skipped: 0 });
    expect(to.load('/introduction/', 'a')).toEqual(from.load('/course/introduction/', 'a'));
    expect(to.load('/kepler/', 'c')).toMatchObject({ solutionShown: true });
  });

  test('a file that is not an export, or damaged, is refused with a sentence and writes nothing', () => {
    const store = new ProgressStore(memoryStorage());
    expect(store.importFile('not json', chapters)).toHaveProperty('error');
    expect(store.importFile('{"format": "other"}', chapters)).toHaveProperty('error');
    const damaged = JSON.stringify({ format: 'phasebook-progress', version: 1, chapters: { introduction: { a: { status: 'solved', attempts: 1, solutionShown: false, answer: '', at: 1 }, b: { status: 'won' } } } });
    expect(store.importFile(damaged, chapters)).toEqual({ error: expect.stringContaining('“b”') });
    expect(store.load('/course/introduction/', 'a')).toBeNull();
  });

  test('reset forgets every record', () => {
    const store = new ProgressStore(memoryStorage());
    store.attempt('/course/introduction/', 'a', true, '1');
    store.attempt('/course/kepler/', 'c', true, '1');
    expect(store.reset(chapters)).toBe(true);
    expect(store.load('/course/introduction/', 'a')).toBeNull();
    expect(store.load('/course/kepler/', 'c')).toBeNull();
  });

  test('storage that is forbidden or full is said, never thrown', () => {
    const forbidden = new ProgressStore(memoryStorage('forbidden'));
    expect(forbidden.available).toBe(false);
    expect(forbidden.attempt('/x/', 'a', true, '1').write).toEqual({ ok: false, reason: 'unavailable' });
    const storage = memoryStorage();
    const store = new ProgressStore(storage);
    storage.setItem = () => {
      throw new DOMException('full', 'QuotaExceededError');
    };
    expect(store.attempt('/x/', 'a', true, '1').write).toEqual({ ok: false, reason: 'full' });
  });
});
