/**
 * The reader's edits, kept in localStorage so a reload keeps their work.
 *
 * Keys: `phasebook:v2:<secret>:<page>:edit:<cell id>` holds a {@link SavedEdit}
 * as JSON, `…:running:<cell id>` marks a cell whose reader's code has been
 * started but has not yet shown that the page survived it, `…:damaged:<cell id>`
 * keeps an edit that could not be read back until the reader has seen it,
 * and `phasebook:v2:secret` holds the secret.
 *
 * - `<page>` is the chapter's path, base path included (`/phasebook/kepler/`),
 *   so two books on one origin (GitHub Pages project sites share one) never
 *   read each other's edits.
 * - `<secret>` is 128 random bits this book draws in this browser on first
 *   use. A page that does not know it cannot write an edit this book will
 *   read, so nothing planted under a guessable key ever runs; see README,
 *   "What a cell can do", for what this does and does not protect against.
 *
 * Storage can be missing, full or forbidden (private modes, disabled
 * cookies): no call here throws, and every write says whether it took.
 *
 * Storage can also come back damaged (a disk error, an extension, a hand
 * in the developer tools). Nothing of the reader's is then dropped without
 * a word: an edit that no longer parses is set aside, with what of its
 * text can be recovered, and a damaged or missing secret, which would
 * orphan every edit saved under it, sets this page's orphaned edits aside
 * too. Set-aside text is offered to the reader (cell.ts), never run: an
 * orphan cannot prove this book wrote it.
 */

/** An edit of one cell, as stored. */
export interface SavedEdit {
  /** The text in the reader's editor, run or not. */
  readonly draft: string;
  /** The text the reader last ran, or null when they never ran an edit (the original runs). */
  readonly ran: string | null;
  /** `data-cell-hash` of the original the edit was made from. */
  readonly base: string;
  /** When it was saved, in ms since the epoch. */
  readonly savedAt: number;
  /** Which page load wrote it (a random id per load), to tell another tab's writes from this one's. */
  readonly tab: string;
}

/** A cell the reader added below one of the chapter's (or below another added cell). */
export interface AddedCell {
  readonly id: string;
  /** The id of the cell it was added below. */
  readonly after: string;
}

function isAddedCell(value: unknown): value is AddedCell {
  return typeof value === 'object' && value !== null && typeof (value as AddedCell).id === 'string' && typeof (value as AddedCell).after === 'string'
    && /^added-[0-9a-f]{8}$/.test((value as AddedCell).id);
}

/** Why a write did not take. */
export type SaveFailure = 'unavailable' | 'full' | 'conflict';

export type SaveResult = { readonly ok: true; readonly edit: SavedEdit } | { readonly ok: false; readonly reason: SaveFailure; readonly current?: SavedEdit };

const VERSION = 'phasebook:v2';
const SECRET_KEY = `${VERSION}:secret`;

function defaultStorage(): Storage | null {
  try {
    return globalThis.localStorage ?? null;
  } catch {
    return null;
  }
}

function randomId(): string {
  const bytes = new Uint8Array(16);
  crypto.getRandomValues(bytes);
  return Array.from(bytes, (b) => b.toString(16).padStart(2, '0')).join('');
}

/**
 * The browser's secret for this book: read, or drawn and kept (`drawn`);
 * null when storage cannot keep it. Shared by everything this book keeps
 * (edits here, exercise progress in progress.ts).
 */
export function bookSecret(storage: Storage | null): { secret: string | null; drawn: boolean } {
  let existing: string | null = null;
  try {
    existing = storage?.getItem(SECRET_KEY) ?? null;
  } catch {
    existing = null;
  }
  if (existing && /^[0-9a-f]{32}$/.test(existing)) return { secret: existing, drawn: false };
  if (!storage) return { secret: null, drawn: false };
  const secret = randomId();
  try {
    storage.setItem(SECRET_KEY, secret);
    return storage.getItem(SECRET_KEY) === secret ? { secret, drawn: true } : { secret: null, drawn: false };
  } catch {
    return { secret: null, drawn: false };
  }
}

/** The key prefix of everything this book keeps for one page in this browser, or null when nothing can be kept. */
export function pagePrefix(secret: string | null, page: string): string | null {
  return secret ? `${VERSION}:${secret}:${page}` : null;
}

export function defaultBookStorage(): Storage | null {
  return defaultStorage();
}

function isSavedEdit(value: unknown): value is SavedEdit {
  if (typeof value !== 'object' || value === null) return false;
  const edit = value as Record<string, unknown>;
  return typeof edit.draft === 'string' && (edit.ran === null || typeof edit.ran === 'string')
    && typeof edit.base === 'string' && typeof edit.savedAt === 'number' && typeof edit.tab === 'string';
}

function isQuotaError(error: unknown): boolean {
  return error instanceof DOMException && (error.name === 'QuotaExceededError' || error.name === 'NS_ERROR_DOM_QUOTA_REACHED');
}

/** The saved edits of one chapter page. */
export class EditStore {
  readonly #storage: Storage | null;
  readonly #prefix: string | null;
  readonly #page: string;
  /** This page load's id, written into every edit it saves. */
  readonly tab: string;

  /** `page` is the chapter's path, e.g. `location.pathname`. */
  constructor(page: string, storage: Storage | null = defaultStorage(), tab: string = randomId()) {
    this.#storage = storage;
    this.#page = page;
    this.tab = tab;
    const { secret, drawn } = bookSecret(this.#storage);
    this.#prefix = pagePrefix(secret, page);
    if (drawn) this.#setAsideOrphans();
  }

  /** False when nothing can be kept (no storage, forbidden, or it would not keep the secret). */
  get available(): boolean {
    return this.#prefix !== null;
  }

  /** The key of a cell's edit, for recognising it in a `storage` event. */
  editKey(cellId: string): string | null {
    return this.#prefix && `${this.#prefix}:edit:${cellId}`;
  }

  /** The cell's edit; one that cannot be read back is set aside (see {@link damaged}) and null returned. */
  load(cellId: string): SavedEdit | null {
    const key = this.editKey(cellId);
    const raw = this.#get(key);
    const edit = this.#parse(raw);
    if (raw && !edit && key) this.#setAside(cellId, raw, key);
    return edit;
  }

  /** This cell's edit as stored when it was set aside because it could not be read back (recovery.ts reads what it can of it), or null. */
  damaged(cellId: string): string | null {
    return this.#get(this.#prefix && `${this.#prefix}:damaged:${cellId}`);
  }

  /** The reader has seen the set-aside edit (taken into the editor, or discarded). */
  forgetDamaged(cellId: string): void {
    this.#remove(this.#prefix && `${this.#prefix}:damaged:${cellId}`);
  }

  /**
   * Saves a cell's edit. Unless `force`, a newer edit written by another tab
   * since `known` (the savedAt this tab last saw) is not overwritten: the
   * result is a conflict carrying it.
   */
  save(cellId: string, edit: { draft: string; ran: string | null; base: string }, known: number | null, force = false): SaveResult {
    const key = this.editKey(cellId);
    if (!key || !this.#storage) return { ok: false, reason: 'unavailable' };
    const current = this.load(cellId);
    if (!force && current && current.tab !== this.tab && current.savedAt > (known ?? 0)) return { ok: false, reason: 'conflict', current };
    const saved: SavedEdit = { ...edit, savedAt: Math.max(Date.now(), (current?.savedAt ?? 0) + 1), tab: this.tab };
    try {
      this.#storage.setItem(key, JSON.stringify(saved));
      return { ok: true, edit: saved };
    } catch (error) {
      return { ok: false, reason: isQuotaError(error) ? 'full' : 'unavailable' };
    }
  }

  forget(cellId: string): void {
    this.#remove(this.editKey(cellId));
  }

  /** Marks that the reader's code of a cell is about to run (see cell.ts); true if the mark could be kept. */
  markRunning(cellId: string): boolean {
    const key = this.#prefix && `${this.#prefix}:running:${cellId}`;
    if (!key || !this.#storage) return false;
    try {
      this.#storage.setItem(key, String(Date.now()));
      return true;
    } catch {
      return false;
    }
  }

  clearRunning(cellId: string): void {
    this.#remove(this.#prefix && `${this.#prefix}:running:${cellId}`);
  }

  /** True when a cell's code was started on an earlier load and the page never got to say it survived. */
  wasRunning(cellId: string): boolean {
    return this.#get(this.#prefix && `${this.#prefix}:running:${cellId}`) !== null;
  }

  /** The cells the reader added to this page, in page order, each with the cell it follows. */
  loadAdded(): AddedCell[] {
    try {
      const parsed: unknown = JSON.parse(this.#get(this.#prefix && `${this.#prefix}:added`) ?? '[]');
      return Array.isArray(parsed) ? parsed.filter(isAddedCell) : [];
    } catch {
      return [];
    }
  }

  /** Keeps the list of added cells; false when storage would not. */
  saveAdded(cells: readonly AddedCell[]): boolean {
    const key = this.#prefix && `${this.#prefix}:added`;
    if (!key || !this.#storage) return false;
    try {
      if (cells.length) this.#storage.setItem(key, JSON.stringify(cells));
      else this.#storage.removeItem(key);
      return true;
    } catch {
      return false;
    }
  }

  /** Every edit of this page, for a download when storage fails. */
  all(): { cellId: string; edit: SavedEdit }[] {
    const found: { cellId: string; edit: SavedEdit }[] = [];
    const prefix = this.#prefix && `${this.#prefix}:edit:`;
    if (!prefix || !this.#storage) return found;
    try {
      for (let i = 0; i < this.#storage.length; i++) {
        const key = this.#storage.key(i);
        const edit = key?.startsWith(prefix) ? this.#parse(this.#storage.getItem(key)) : null;
        if (key && edit) found.push({ cellId: key.slice(prefix.length), edit });
      }
    } catch {
      // What was read so far is what there is.
    }
    return found;
  }

  /** Parses the new value of a `storage` event for cell `cellId` (null: removed or not an edit). */
  parseEvent(value: string | null): SavedEdit | null {
    return this.#parse(value);
  }

  /**
   * Edits of this page saved under another secret: after the secret was
   * damaged or lost, these are the reader's own, out of reach. Each cell's
   * latest is set aside under the new secret, to be offered, not run.
   */
  #setAsideOrphans(): void {
    if (!this.#storage || !this.#prefix) return;
    const suffix = `:${this.#page}:edit:`;
    const latest = new Map<string, { raw: string; savedAt: number }>();
    try {
      for (let i = 0; i < this.#storage.length; i++) {
        const key = this.#storage.key(i);
        const match = key && /^phasebook:v2:([^:]*)(:.*)$/.exec(key);
        if (!key || !match || !match[2].startsWith(suffix) || key.startsWith(`${this.#prefix}:`)) continue;
        const raw = this.#storage.getItem(key) ?? '';
        const savedAt = this.#parse(raw)?.savedAt ?? 0;
        const cellId = match[2].slice(suffix.length);
        if ((latest.get(cellId)?.savedAt ?? -1) < savedAt) latest.set(cellId, { raw, savedAt });
      }
    } catch {
      return;
    }
    for (const [cellId, { raw }] of latest) this.#setAside(cellId, raw, null);
  }

  /** Keeps `raw` aside for the reader (unless something is aside already), and takes it from `from`. */
  #setAside(cellId: string, raw: string, from: string | null): void {
    const aside = `${this.#prefix}:damaged:${cellId}`;
    try {
      if (this.#storage?.getItem(aside) === null) this.#storage.setItem(aside, raw);
      if (from) this.#storage?.removeItem(from);
    } catch {
      // Storage full or gone: the damaged value stays where it is, and is read (and set aside) again next time.
    }
  }

  #get(key: string | null): string | null {
    if (!key || !this.#storage) return null;
    try {
      return this.#storage.getItem(key);
    } catch {
      return null;
    }
  }

  #remove(key: string | null): void {
    if (!key) return;
    try {
      this.#storage?.removeItem(key);
    } catch {
      // Nothing to undo: the page keeps working without storage.
    }
  }

  #parse(raw: string | null): SavedEdit | null {
    if (!raw) return null;
    try {
      const parsed: unknown = JSON.parse(raw);
      return isSavedEdit(parsed) ? parsed : null;
    } catch {
      return null;
    }
  }
}
