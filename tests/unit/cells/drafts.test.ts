import { afterEach, beforeEach, describe, expect, test, vi } from 'vitest';
import { DraftKeeper, type SaveProblem } from '../../../cells/drafts.ts';
import { EditStore } from '../../../cells/storage.ts';
import { memoryStorage } from '../support/memory-storage.ts';

describe('DraftKeeper(store, cellId, original, hash)', () => {
  let storage: Storage;
  let store: EditStore;
  beforeEach(() => {
    vi.useFakeTimers();
    storage = memoryStorage();
    store = new EditStore('/chapter/', storage, 'tab');
  });
  afterEach(() => vi.useRealTimers());

  test('what the reader ran runs again on the next load; a later draft comes back beside it, unrun', () => {
    const keeper = new DraftKeeper(store, 'a', 'a = 1', 'h');
    keeper.ran('a = 2');
    expect(new DraftKeeper(store, 'a', 'a = 1', 'h').starting()).toEqual({ kind: 'run', ran: 'a = 2', draft: 'a = 2' });
    keeper.changed('a = 3');
    vi.advanceTimersByTime(1000);
    expect(new DraftKeeper(store, 'a', 'a = 1', 'h').starting()).toEqual({ kind: 'run', ran: 'a = 2', draft: 'a = 3' });
  });

  test('a draft that was never run is shown, not run', () => {
    const keeper = new DraftKeeper(store, 'a', 'a = 1', 'h');
    keeper.changed('while (true) {}');
    vi.advanceTimersByTime(1000);
    expect(new DraftKeeper(store, 'a', 'a = 1', 'h').starting()).toEqual({ kind: 'draft', draft: 'while (true) {}' });
  });

  test('flush() saves a draft typed a moment ago, before its delay is up (the page is being left)', () => {
    const keeper = new DraftKeeper(store, 'a', 'a = 1', 'h');
    keeper.changed('a = 9');
    expect(store.load('a')).toBeNull();
    keeper.flush();
    expect(store.load('a')).toMatchObject({ draft: 'a = 9', ran: null });
  });

  test('code that was still running when the page died is offered, not run, until the reader decides', () => {
    const keeper = new DraftKeeper(store, 'a', 'a = 1', 'h');
    keeper.ran('a = loop()');
    keeper.markRunning();
    // …the page froze here; the next load:
    const next = new DraftKeeper(store, 'a', 'a = 1', 'h');
    expect(next.starting()).toMatchObject({ kind: 'offer', why: 'stopped', edit: { ran: 'a = loop()' } });
    next.closeOffer();
    expect(new DraftKeeper(store, 'a', 'a = 1', 'h').starting()).toMatchObject({ kind: 'run', ran: 'a = loop()' });
    // Had it survived, there would have been nothing to offer.
    keeper.markRunning();
    keeper.survived();
    expect(new DraftKeeper(store, 'a', 'a = 1', 'h').starting().kind).toBe('run');
  });

  test('an edit of an older original is offered, and nothing overwrites it until the offer closes', () => {
    new DraftKeeper(store, 'a', 'a = 1', 'old').ran('a = 2');
    const keeper = new DraftKeeper(store, 'a', 'a = 10', 'new');
    expect(keeper.starting()).toMatchObject({ kind: 'offer', why: 'changed', edit: { ran: 'a = 2', base: 'old' } });
    expect(keeper.offering).toBe(true);
    keeper.changed('a = 3');
    vi.advanceTimersByTime(1000);
    keeper.ran('a = 4');
    expect(store.load('a')).toMatchObject({ ran: 'a = 2', base: 'old' });
    keeper.closeOffer();
    keeper.ran('a = 4');
    expect(store.load('a')).toMatchObject({ ran: 'a = 4', base: 'new' });
  });

  test('running the original again forgets the edit', () => {
    const keeper = new DraftKeeper(store, 'a', 'a = 1', 'h');
    keeper.ran('a = 2');
    keeper.ran('a = 1');
    expect(store.load('a')).toBeNull();
    expect(new DraftKeeper(store, 'a', 'a = 1', 'h').starting()).toEqual({ kind: 'original' });
  });

  test('another tab’s newer edit is reported as a conflict, not overwritten; storage failures are reported too', () => {
    const problems: SaveProblem[] = [];
    const mine = new DraftKeeper(store, 'a', 'a = 1', 'h', (p) => problems.push(p));
    mine.starting();
    vi.advanceTimersByTime(5);
    new DraftKeeper(new EditStore('/chapter/', storage, 'other'), 'a', 'a = 1', 'h').ran('a = 7');
    mine.ran('a = 8');
    expect(problems).toMatchObject([{ reason: 'conflict', theirs: { ran: 'a = 7', tab: 'other' } }]);
    expect(store.load('a')).toMatchObject({ ran: 'a = 7' });
    mine.keepMine('a = 8');
    expect(store.load('a')).toMatchObject({ draft: 'a = 8', tab: 'tab' });

    const nowhere: SaveProblem[] = [];
    new DraftKeeper(new EditStore('/chapter/', null), 'a', 'a = 1', 'h', (p) => nowhere.push(p)).ran('a = 2');
    expect(nowhere).toEqual([{ reason: 'unavailable' }]);
  });
});
