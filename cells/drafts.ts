/**
 * Keeps one cell's text in storage (storage.ts) as the reader works, and
 * decides what a page load does with it.
 *
 * - A draft (text typed but not run) is saved shortly after typing stops and
 *   when the page is left (flush); it comes back in the editor, and is never
 *   run until the reader runs it.
 * - What the reader ran is saved at once, and runs again on the next load —
 *   unless that code was still running when the page last died (the page
 *   froze, or was closed while stuck), or the chapter's cell has changed
 *   since: then the original runs and the edit is offered.
 * - Nothing overwrites a newer edit that another tab saved, and nothing
 *   overwrites an offered edit until the reader decides.
 */
import type { EditStore, SavedEdit, SaveFailure } from './storage.ts';

/** Drafts are saved this long after the last keystroke. */
const SAVE_DELAY_MS = 400;

/** What a page load does with the stored edit. */
export type StartingEdit =
  | { readonly kind: 'original' }
  /** Run `ran`; the editor shows `draft` (the same text, or a later unrun one). */
  | { readonly kind: 'run'; readonly ran: string; readonly draft: string }
  /** The original runs; the editor shows the reader's unrun draft. */
  | { readonly kind: 'draft'; readonly draft: string }
  /** The original runs; the edit waits for the reader: the chapter changed, or the edit stopped the page. */
  | { readonly kind: 'offer'; readonly edit: SavedEdit; readonly why: 'changed' | 'stopped' }
  /** The original runs; the saved edit could not be read back (`raw`, as stored), and what can be recovered of it is offered (recovery.ts). */
  | { readonly kind: 'damaged'; readonly raw: string };

/** What the cell hears when a save did not take. */
export type SaveProblem = { readonly reason: Exclude<SaveFailure, 'conflict'> } | { readonly reason: 'conflict'; readonly theirs: SavedEdit };

export class DraftKeeper {
  readonly #store: EditStore;
  readonly #cellId: string;
  readonly #original: string;
  readonly #hash: string;
  readonly #onProblem: (problem: SaveProblem) => void;
  #timer: ReturnType<typeof setTimeout> | undefined;
  /** The draft waiting for its delayed save. */
  #pending: string | null = null;
  #offer: SavedEdit | null = null;
  /** The reader's code that runs (null: the original). */
  #ran: string | null = null;
  /** savedAt of the stored edit this tab last saw or wrote. */
  #known: number | null = null;

  /** `original` and `hash` are the chapter's source of the cell and its `data-cell-hash`. */
  constructor(store: EditStore, cellId: string, original: string, hash: string, onProblem: (problem: SaveProblem) => void = () => {}) {
    this.#store = store;
    this.#cellId = cellId;
    this.#original = original;
    this.#hash = hash;
    this.#onProblem = onProblem;
  }

  starting(): StartingEdit {
    const saved = this.#store.load(this.#cellId);
    this.#known = saved?.savedAt ?? null;
    if (!saved) {
      const damaged = this.#store.damaged(this.#cellId);
      return damaged === null ? { kind: 'original' } : { kind: 'damaged', raw: damaged };
    }
    const stopped = this.#store.wasRunning(this.#cellId);
    if (stopped || saved.base !== this.#hash) {
      if (!stopped && saved.draft === this.#original && saved.ran === null) return { kind: 'original' };
      this.#offer = saved;
      return { kind: 'offer', edit: saved, why: stopped ? 'stopped' : 'changed' };
    }
    if (saved.ran !== null && saved.ran !== this.#original) {
      this.#ran = saved.ran;
      return { kind: 'run', ran: saved.ran, draft: saved.draft };
    }
    return saved.draft === this.#original ? { kind: 'original' } : { kind: 'draft', draft: saved.draft };
  }

  get offering(): boolean {
    return this.#offer !== null;
  }

  /** The reader declined or took the offer; storage is free to change again. */
  closeOffer(): void {
    this.#offer = null;
    this.#store.clearRunning(this.#cellId);
    this.#store.forgetDamaged(this.#cellId);
  }

  /** The reader typed: save the draft soon, unless an offer is pending (then the reader decides). */
  changed(draft: string): void {
    clearTimeout(this.#timer);
    if (this.#offer) return;
    this.#pending = draft;
    this.#timer = setTimeout(() => this.flush(), SAVE_DELAY_MS);
  }

  /** Saves a waiting draft now: when the page is hidden or left, nothing typed is lost. */
  flush(): void {
    clearTimeout(this.#timer);
    const draft = this.#pending;
    this.#pending = null;
    if (draft !== null) this.#save(draft, this.#ran);
  }

  /** The reader ran `source` (the original again, after Reset or by hand, means no edit). */
  ran(source: string): void {
    clearTimeout(this.#timer);
    this.#pending = null;
    this.#ran = source === this.#original ? null : source;
    if (this.#offer) return;
    this.#save(source, this.#ran);
  }

  /** Takes another tab's edit as this tab's own (it was offered, and the reader accepted it). */
  adopt(edit: SavedEdit): void {
    this.#known = edit.savedAt;
    this.#ran = edit.ran;
  }

  /** Keeps `draft` as text not run: the original runs, on this load and the next (an edit held back from a reload loop). */
  unrun(draft: string): void {
    clearTimeout(this.#timer);
    this.#pending = null;
    this.#ran = null;
    this.#save(draft, null);
  }

  /** Overwrites whatever is stored with this tab's text (the reader chose to keep theirs). */
  keepMine(draft: string): void {
    this.#save(draft, this.#ran, true);
  }

  /** Forgets the edit altogether (the cell is being deleted). */
  forget(): void {
    clearTimeout(this.#timer);
    this.#pending = null;
    this.#store.forget(this.#cellId);
  }

  /** Marks the reader's code as running, until {@link survived}; see cell.ts. */
  markRunning(): void {
    this.#store.markRunning(this.#cellId);
  }

  /** The reader's code ran and the page came back from it. */
  survived(): void {
    this.#store.clearRunning(this.#cellId);
  }

  #save(draft: string, ran: string | null, force = false): void {
    if (draft === this.#original && ran === null) {
      this.#store.forget(this.#cellId);
      this.#known = null;
      return;
    }
    const result = this.#store.save(this.#cellId, { draft, ran, base: this.#hash }, this.#known, force);
    if (result.ok) this.#known = result.edit.savedAt;
    else if (result.reason === 'conflict' && result.current) this.#onProblem({ reason: 'conflict', theirs: result.current });
    else if (result.reason !== 'conflict') this.#onProblem({ reason: result.reason });
  }
}
