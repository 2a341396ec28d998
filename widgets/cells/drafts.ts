/**
 * Keeps one cell's text in storage (storage.ts) as the reader works: drafts
 * are saved shortly after typing stops, Run and Reset save at once, and an
 * edit made from an older version of the chapter's cell is held as an offer
 * that nothing overwrites until the reader decides.
 */
import type { EditStore, SavedEdit } from './storage.ts';

/** Drafts are saved this long after the last keystroke. */
const SAVE_DELAY_MS = 400;

/** What a page load should do with the stored edit. */
export type StartingEdit = { kind: 'none' } | { kind: 'apply'; source: string } | { kind: 'offer'; edit: SavedEdit };

export class DraftKeeper {
  readonly #store: EditStore;
  readonly #cellId: string;
  readonly #original: string;
  readonly #hash: string;
  #timer: ReturnType<typeof setTimeout> | undefined;
  #offer: SavedEdit | null = null;

  /** `original` and `hash` are the chapter's source of the cell and its `data-cell-hash`. */
  constructor(store: EditStore, cellId: string, original: string, hash: string) {
    this.#store = store;
    this.#cellId = cellId;
    this.#original = original;
    this.#hash = hash;
  }

  /** An edit of this very original is applied; one of an older original is offered. */
  starting(): StartingEdit {
    const saved = this.#store.load(this.#cellId);
    if (!saved || saved.source === this.#original) return { kind: 'none' };
    if (saved.base === this.#hash) return { kind: 'apply', source: saved.source };
    this.#offer = saved;
    return { kind: 'offer', edit: saved };
  }

  get offering(): boolean {
    return this.#offer !== null;
  }

  /** The reader declined or took the offer; storage is free to change again. */
  closeOffer(): void {
    this.#offer = null;
  }

  /** The reader typed: save soon, unless an offer is pending (then Run decides). */
  changed(source: string): void {
    clearTimeout(this.#timer);
    if (!this.#offer) this.#timer = setTimeout(() => this.commit(source), SAVE_DELAY_MS);
  }

  /** Saves `source` now, or forgets the edit when it is the original again. */
  commit(source: string): void {
    clearTimeout(this.#timer);
    if (this.#offer) return;
    if (source === this.#original) this.#store.forget(this.#cellId);
    else this.#store.save(this.#cellId, source, this.#hash);
  }
}
