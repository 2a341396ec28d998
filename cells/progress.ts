/**
 * The reader's progress on the exercises, kept in localStorage beside their
 * edits and under the same rules (storage.ts): keys carry the book's secret
 * for this browser and the chapter's path, base path included,
 * `phasebook:v2:<secret>:<page>:exercise:<id>`; no call throws, every write
 * says whether it took, and a value that does not parse counts as none.
 *
 * Export and import move it as one JSON file keyed by chapter slug, not by
 * path, so a file exported from one copy of the book imports into another
 * served under a different base path.
 */
import { bookSecret, defaultBookStorage, pagePrefix } from './storage.ts';

export type ExerciseStatus = 'solved' | 'attempted';

export interface ExerciseRecord {
  readonly status: ExerciseStatus;
  /** Checks made, passed or not. */
  readonly attempts: number;
  /** Whether the worked solution was shown. */
  readonly solutionShown: boolean;
  /** The reader's last answer (a number's text; empty for code, which the cell keeps). */
  readonly answer: string;
  /** ms since the epoch. */
  readonly at: number;
}

/** One chapter as the book lists it: its slug, its path on this site, its exercises' ids. */
export interface ChapterExercises {
  readonly slug: string;
  readonly page: string;
  readonly ids: readonly string[];
}

export const PROGRESS_FORMAT = 'phasebook-progress';

/**
 * The hook for whoever follows the reader's results on a page (the SCORM
 * adapter of a packaged chapter, site/scorm/): after every check of an
 * exercise, `document` receives a CustomEvent of this type whose `detail`
 * is an {@link ExerciseResult}. It is sent whether or not storage kept the
 * result, and nothing in the book itself listens to it.
 */
export const EXERCISE_RESULT_EVENT = 'phasebook:exercise-result';

export interface ExerciseResult {
  /** The exercise's id, as its declaration names it. */
  readonly id: string;
  /** Whether this check passed. */
  readonly passed: boolean;
  /** Whether the exercise counts as solved now: this check or an earlier one passed. */
  readonly solved: boolean;
}

export type WriteResult = { readonly ok: true } | { readonly ok: false; readonly reason: 'unavailable' | 'full' };

export function isExerciseRecord(value: unknown): value is ExerciseRecord {
  if (typeof value !== 'object' || value === null) return false;
  const r = value as Record<string, unknown>;
  return (r.status === 'solved' || r.status === 'attempted') && Number.isInteger(r.attempts) && (r.attempts as number) >= 0
    && typeof r.solutionShown === 'boolean' && typeof r.answer === 'string' && r.answer.length <= 200 && typeof r.at === 'number';
}

export class ProgressStore {
  readonly #storage: Storage | null;
  readonly #secret: string | null;

  constructor(storage: Storage | null = defaultBookStorage()) {
    this.#storage = storage;
    this.#secret = bookSecret(storage).secret;
  }

  get available(): boolean {
    return this.#secret !== null;
  }

  #key(page: string, id: string): string | null {
    const prefix = pagePrefix(this.#secret, page);
    return prefix && `${prefix}:exercise:${id}`;
  }

  load(page: string, id: string): ExerciseRecord | null {
    const key = this.#key(page, id);
    try {
      const raw = key && this.#storage?.getItem(key);
      const parsed: unknown = raw ? JSON.parse(raw) : null;
      return isExerciseRecord(parsed) ? parsed : null;
    } catch {
      return null;
    }
  }

  save(page: string, id: string, record: ExerciseRecord): WriteResult {
    const key = this.#key(page, id);
    if (!key || !this.#storage) return { ok: false, reason: 'unavailable' };
    try {
      this.#storage.setItem(key, JSON.stringify(record));
      return { ok: true };
    } catch (error) {
      const full = error instanceof DOMException && (error.name === 'QuotaExceededError' || error.name === 'NS_ERROR_DOM_QUOTA_REACHED');
      return { ok: false, reason: full ? 'full' : 'unavailable' };
    }
  }

  /** Records a check: solved stays solved (a later wrong try does not undo learning). */
  attempt(page: string, id: string, passed: boolean, answer: string): { record: ExerciseRecord; write: WriteResult } {
    const before = this.load(page, id);
    const record: ExerciseRecord = {
      status: passed || before?.status === 'solved' ? 'solved' : 'attempted',
      attempts: (before?.attempts ?? 0) + 1,
      solutionShown: before?.solutionShown ?? false,
      answer: answer.slice(0, 200),
      at: Date.now(),
    };
    return { record, write: this.save(page, id, record) };
  }

  /** Records that the worked solution was shown. */
  solutionShown(page: string, id: string): { record: ExerciseRecord; write: WriteResult } {
    const before = this.load(page, id);
    const record: ExerciseRecord = { status: before?.status ?? 'attempted', attempts: before?.attempts ?? 0, solutionShown: true, answer: before?.answer ?? '', at: Date.now() };
    return { record, write: this.save(page, id, record) };
  }

  /** Every chapter's records, as the export file holds them. */
  exportFile(chapters: readonly ChapterExercises[], now = new Date()): { format: string; version: 1; exported: string; chapters: Record<string, Record<string, ExerciseRecord>> } {
    const out: Record<string, Record<string, ExerciseRecord>> = {};
    for (const { slug, page, ids } of chapters) {
      for (const id of ids) {
        const record = this.load(page, id);
        if (record) (out[slug] ??= {})[id] = record;
      }
    }
    return { format: PROGRESS_FORMAT, version: 1, exported: now.toISOString(), chapters: out };
  }

  /**
   * Reads an export file and writes its records for the exercises this book
   * has; unknown chapters and exercises are counted, not kept. Nothing is
   * written unless the whole file is valid.
   */
  importFile(text: string, chapters: readonly ChapterExercises[]): { imported: number; skipped: number } | { error: string } {
    let file: unknown;
    try {
      file = JSON.parse(text);
    } catch {
      return { error: 'That file is not JSON: choose a file this page exported.' };
    }
    const f = file as { format?: unknown; version?: unknown; chapters?: unknown };
    if (typeof file !== 'object' || file === null || f.format !== PROGRESS_FORMAT || f.version !== 1 || typeof f.chapters !== 'object' || f.chapters === null) {
      return { error: 'That file is not a Phasebook progress export (version 1).' };
    }
    const writes: [string, string, ExerciseRecord][] = [];
    let skipped = 0;
    for (const [slug, records] of Object.entries(f.chapters as Record<string, unknown>)) {
      const chapter = chapters.find((c) => c.slug === slug);
      if (typeof records !== 'object' || records === null) return { error: `The progress of “${slug}” in that file is damaged.` };
      for (const [id, record] of Object.entries(records)) {
        if (!isExerciseRecord(record)) return { error: `The record of exercise “${id}” in that file is damaged.` };
        if (chapter?.ids.includes(id)) writes.push([chapter.page, id, record]);
        else skipped++;
      }
    }
    for (const [page, id, record] of writes) {
      const result = this.save(page, id, record);
      if (!result.ok) return { error: result.reason === 'full' ? 'This browser’s storage is full: the progress could not all be kept.' : 'This browser keeps nothing for this site: the progress could not be kept.' };
    }
    return { imported: writes.length, skipped };
  }

  /** Forgets every record of these chapters; true when storage let it. */
  reset(chapters: readonly ChapterExercises[]): boolean {
    try {
      for (const { page, ids } of chapters) for (const id of ids) {
        const key = this.#key(page, id);
        if (key) this.#storage?.removeItem(key);
      }
      return true;
    } catch {
      return false;
    }
  }
}
