/**
 * The reader's edits, kept in localStorage so a reload keeps their work.
 *
 * Key: `phasebook:v1:edit:<chapter slug>:<cell id>`.
 * Value: JSON {@link SavedEdit}. `base` is the hash of the chapter's original
 * cell source the edit was made from; when the chapter's cell has changed
 * since, the edit is offered to the reader rather than applied.
 *
 * Storage can be missing, full or forbidden (private modes, disabled cookies):
 * every call here fails quietly, and the page works without persistence.
 */

/** An edit of one cell, as stored. */
export interface SavedEdit {
  /** The reader's source text. */
  readonly source: string;
  /** `data-cell-hash` of the original the edit was made from. */
  readonly base: string;
  /** When it was saved, in ms since the epoch. */
  readonly savedAt: number;
}

const PREFIX = 'phasebook:v1:edit';

export function editKey(chapter: string, cellId: string): string {
  return `${PREFIX}:${chapter}:${cellId}`;
}

function isSavedEdit(value: unknown): value is SavedEdit {
  if (typeof value !== 'object' || value === null) return false;
  const edit = value as Record<string, unknown>;
  return typeof edit.source === 'string' && typeof edit.base === 'string' && typeof edit.savedAt === 'number';
}

function defaultStorage(): Storage | null {
  try {
    return globalThis.localStorage ?? null;
  } catch {
    return null;
  }
}

/** The saved edits of one chapter. */
export class EditStore {
  readonly #chapter: string;
  readonly #storage: Storage | null;

  constructor(chapter: string, storage: Storage | null = defaultStorage()) {
    this.#chapter = chapter;
    this.#storage = storage;
  }

  load(cellId: string): SavedEdit | null {
    try {
      const raw = this.#storage?.getItem(editKey(this.#chapter, cellId));
      if (!raw) return null;
      const parsed: unknown = JSON.parse(raw);
      return isSavedEdit(parsed) ? parsed : null;
    } catch {
      return null;
    }
  }

  /** Returns false when the edit could not be kept (no storage, quota). */
  save(cellId: string, source: string, base: string): boolean {
    const edit: SavedEdit = { source, base, savedAt: Date.now() };
    try {
      this.#storage?.setItem(editKey(this.#chapter, cellId), JSON.stringify(edit));
      return this.#storage !== null;
    } catch {
      return false;
    }
  }

  forget(cellId: string): void {
    try {
      this.#storage?.removeItem(editKey(this.#chapter, cellId));
    } catch {
      // Nothing to undo: the page keeps working without storage.
    }
  }
}
