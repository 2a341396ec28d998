/**
 * A chapter opened from a shared link: the edits it carries, held in memory
 * for this page load only, and never run until the reader asks.
 *
 * The page's cells work as always, over an {@link EditStore} on a
 * {@link MemoryStorage}: each shared edit is put there as a draft (text not
 * run), so every changed cell shows the shared code marked "not run yet"
 * while the chapter's original runs (drafts.ts). Nothing is written to the
 * reader's own storage until they press "Keep these edits", and that asks
 * before it replaces edits they saved themselves (see {@link keepShared}).
 */
import type { SharedCell, SharedEdits } from './share-format.ts';
import { MemoryStorage } from './memory-storage.ts';
import { EditStore, type AddedCell } from './storage.ts';

/** A chapter cell on the page, as the build rendered it. */
export interface PageCell {
  readonly id: string;
  /** `data-cell-hash`: the original's hash. */
  readonly hash: string;
}

/** What of a link applies to this page. */
export interface SharedPlan {
  /** The cells to show with shared code, in page order. */
  readonly cells: readonly SharedCell[];
  /** Ids of chapter cells the link edits that this page does not have (left out). */
  readonly missing: readonly string[];
  /** Ids of cells whose original changed since the link was made (the edit is still shown, as made). */
  readonly changed: readonly string[];
}

/** Matches a link's edits to the page's cells, or says why none apply. */
export function planShared(edits: SharedEdits, chapter: string, page: readonly PageCell[]): SharedPlan | string {
  if (edits.chapter !== chapter) return `This link holds edits of another chapter (“${edits.chapter}”), not of this one.`;
  const byId = new Map(page.map((cell) => [cell.id, cell]));
  const cells: SharedCell[] = [];
  const missing: string[] = [];
  const changed: string[] = [];
  const present = new Set<string>();
  for (const cell of edits.cells) {
    if (cell.kind === 'edit') {
      const here = byId.get(cell.id);
      if (!here) {
        missing.push(cell.id);
        continue;
      }
      if (here.hash !== cell.base) changed.push(cell.id);
      cells.push(cell);
    } else {
      // An added cell whose anchor is gone goes below the chapter's last cell (as chapter.ts puts back the reader's own).
      const anchored = byId.has(cell.after) || present.has(cell.after);
      cells.push(anchored ? cell : { ...cell, after: page.at(-1)?.id ?? cell.after });
    }
    present.add(cell.id);
  }
  if (cells.length === 0) return 'This link holds no edits of the cells this chapter has now.';
  return { cells, missing, changed };
}

/**
 * The store the shared view's cells use: in memory, holding each shared edit
 * as an unrun draft on the page's own hash (so it is shown, not offered,
 * and the original runs), and the shared added cells.
 */
export function sharedStore(page: string, plan: SharedPlan, hashes: ReadonlyMap<string, string>): EditStore {
  const store = new EditStore(page, new MemoryStorage());
  for (const cell of plan.cells) {
    const base = cell.kind === 'added' ? 'added' : (hashes.get(cell.id) ?? cell.base);
    store.save(cell.id, { draft: cell.source, ran: null, base }, null, true);
  }
  store.saveAdded(plan.cells.flatMap((cell): AddedCell[] => (cell.kind === 'added' ? [{ id: cell.id, after: cell.after }] : [])));
  return store;
}

/**
 * The reader pressed "Run shared edits": from now on the shared text runs.
 * Cells not started yet start with it (their stored edit now says it ran);
 * the caller runs the started ones. Returns the ids it marked.
 */
export function markSharedRun(store: EditStore, ids: readonly string[]): string[] {
  const marked: string[] = [];
  for (const id of ids) {
    const edit = store.load(id);
    if (!edit) continue;
    store.save(id, { draft: edit.draft, ran: edit.draft, base: edit.base }, null, true);
    marked.push(id);
  }
  return marked;
}

/** What the reader's own storage holds for this chapter: the ids "Keep these edits" would replace. */
export function ownEdits(own: EditStore): string[] {
  const ids = new Set([...own.all().map(({ cellId }) => cellId), ...own.loadAdded().map(({ id }) => id)]);
  return [...ids];
}

/**
 * Makes the shared view the reader's own: their saved edits and added cells
 * of this chapter are replaced by what the shared view holds now (the
 * caller has asked them first when {@link ownEdits} is not empty). What ran
 * is kept as having run, what was only shown stays a draft. False when the
 * reader's storage would not keep it (their earlier edits are then as they were,
 * as far as storage allowed).
 */
export function keepShared(shared: EditStore, own: EditStore): boolean {
  if (!own.available) return false;
  const edits = shared.all();
  const kept = new Set(edits.map(({ cellId }) => cellId));
  // Write first, then forget: a write that fails leaves the reader's other edits where they were.
  let ok = true;
  for (const { cellId, edit } of edits) {
    ok = own.save(cellId, { draft: edit.draft, ran: edit.ran, base: edit.base }, null, true).ok && ok;
    own.clearRunning(cellId);
  }
  ok = own.saveAdded(shared.loadAdded()) && ok;
  if (!ok) return false;
  for (const { cellId } of own.all()) {
    if (kept.has(cellId)) continue;
    own.forget(cellId);
    own.clearRunning(cellId);
  }
  return true;
}
