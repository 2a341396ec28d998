/**
 * A page that reloads itself as soon as it has loaded, for ever:
 * `H0 = { location.reload(); return 1 }` runs on every load, since the
 * reader ran it, and made 70 loads in 40 s. No single load freezes, so the
 * "did not finish" mark (cell.ts) never sees it.
 *
 * When a cell's code starts a load of this same page (a reload, or the
 * same address assigned) without the reader asking, the page notes that in the tab's
 * sessionStorage: when, how long after the reader's code began to run on
 * it, and which edits were in force. The next load reads the note: if that
 * load came within a few seconds of the edits running, with the same
 * edits, the page is reloading itself in a loop, and the edits are offered
 * instead of run (cell.ts, reload-notice.ts). The clock starts when the
 * edits run, not when the page started loading, so that a slow load (a
 * busy machine, a long chapter) does not hide the loop. A reload by the
 * reader (the browser's button, F5), or by the book itself (keeping a
 * shared link's edits), is never noted.
 */

/** A page that starts its own load this soon after the reader's code began to run on it is going round a loop. */
export const LOOP_WINDOW_MS = 5000;

/** What one load notes when it starts the next. */
export interface SelfLoad {
  /** The page's path. */
  readonly path: string;
  /** When the load was started (ms since the epoch). */
  readonly at: number;
  /** When the reader's code began to run on the page that started it. */
  readonly ranAt: number;
  /** The edits in force then (editsKey). */
  readonly edits: string;
  /** Loads in a row so far that were turns of the loop, this one included. */
  readonly turns: number;
}

/** What a load knows of itself. */
export interface ThisLoad {
  readonly path: string;
  /** When this load began (performance.timeOrigin). */
  readonly loadedAt: number;
  /** When the reader's code began to run on it (the sandbox was installed). */
  readonly ranAt: number;
  /** The edits that would run now (editsKey). */
  readonly edits: string;
}

/**
 * How many times in a row the page has reloaded itself, this load the last
 * of them; 0 when this load is not a turn of a loop (the reader's own
 * reload, other edits, a page that lived a while before reloading).
 */
export function loopTurns(note: SelfLoad | null, load: ThisLoad): number {
  if (!note || note.path !== load.path || note.edits !== load.edits) return 0;
  // The note must be about this very load: it started just before this load began.
  const started = load.loadedAt - note.at;
  if (started < -1000 || started > LOOP_WINDOW_MS) return 0;
  // And the page that started it did so as soon as the edits ran.
  return note.at - note.ranAt <= LOOP_WINDOW_MS ? note.turns : 0;
}

/** The note a load leaves when it starts the next one; `turns` is this load's own loopTurns. */
export function selfLoadNote(load: ThisLoad, now: number, turns: number): SelfLoad {
  return { path: load.path, at: now, ranAt: load.ranAt, edits: load.edits, turns: turns + 1 };
}

/** A short, stable key of the edits in force: cell ids with the code that runs, in any order. */
export function editsKey(edits: Iterable<readonly [string, string]>): string {
  const text = JSON.stringify([...edits].sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0)));
  // FNV-1a, 32 bits twice over different seeds: equal edits give equal keys, and the note stays small.
  let h1 = 0x811c9dc5;
  let h2 = 0x01000193;
  for (let i = 0; i < text.length; i++) {
    const c = text.charCodeAt(i);
    h1 = Math.imul(h1 ^ c, 0x01000193);
    h2 = Math.imul(h2 ^ c, 0x5bd1e995);
  }
  return `${text.length}:${(h1 >>> 0).toString(36)}${(h2 >>> 0).toString(36)}`;
}

const NOTE_KEY = 'phasebook:self-load';

function isNote(value: unknown): value is SelfLoad {
  const note = value as SelfLoad;
  return typeof value === 'object' && value !== null && typeof note.path === 'string' && typeof note.at === 'number'
    && typeof note.ranAt === 'number' && typeof note.edits === 'string' && typeof note.turns === 'number';
}

/** The note the previous load of this tab left, taken (read once, then removed). */
export function takeNote(storage: Storage | null = sessionStorageOrNull()): SelfLoad | null {
  try {
    const raw = storage?.getItem(NOTE_KEY);
    storage?.removeItem(NOTE_KEY);
    const parsed: unknown = raw ? JSON.parse(raw) : null;
    return isNote(parsed) ? parsed : null;
  } catch {
    return null;
  }
}

export function leaveNote(note: SelfLoad, storage: Storage | null = sessionStorageOrNull()): void {
  try {
    storage?.setItem(NOTE_KEY, JSON.stringify(note));
  } catch {
    // Without storage the loop cannot be seen; the page works as before.
  }
}

function sessionStorageOrNull(): Storage | null {
  try {
    return globalThis.sessionStorage ?? null;
  } catch {
    return null;
  }
}
