/**
 * What a shared link carries (share-ui.ts): the text each changed cell
 * shows, and every added cell that has text, in page order. Share code, so
 * it loads with the Share button, not with every page.
 */
import type { LiveCell } from './cell.ts';
import type { SharedCell } from './share-format.ts';
import type { EditStore } from './storage.ts';

/**
 * The cells of a link, and in `unrun` the cells whose text shown is not the
 * code that runs. A cell not started yet shows, once started, its saved
 * edit unless that is offered instead (drafts.ts), so that is what it
 * contributes.
 */
export function shareable(pageCells: readonly LiveCell[], store: EditStore): { cells: SharedCell[]; unrun: string[] } {
  const cells: SharedCell[] = [];
  const unrun: string[] = [];
  let after: string | null = null;
  for (const cell of pageCells) {
    const text = shownEdit(cell, store);
    if (text && text.draft !== text.running) unrun.push(cell.id);
    if (cell.added && text?.draft) cells.push({ kind: 'added', id: cell.id, source: text.draft, after: after ?? cell.id });
    else if (!cell.added && text) cells.push({ kind: 'edit', id: cell.id, source: text.draft, base: cell.root.dataset.cellHash ?? '' });
    if (!cell.added || text?.draft) after = cell.id;
  }
  // An added cell above every chapter cell cannot be: added cells always follow one.
  return { cells: cells.filter((c) => c.kind === 'edit' || c.after !== c.id), unrun };
}

/** The text a cell shows and the code it runs, when either is not the chapter's (null: the original). */
function shownEdit(cell: LiveCell, store: EditStore): { draft: string; running: string } | null {
  if (cell.started) return cell.edit;
  const saved = store.load(cell.id);
  if (!saved || store.wasRunning(cell.id) || saved.base !== (cell.root.dataset.cellHash ?? '')) return null;
  // Not started: its <pre> still holds the chapter's original.
  const original = cell.root.querySelector('pre.cell-code > code')?.textContent ?? '';
  const running = saved.ran ?? original;
  return saved.draft === original && running === original ? null : { draft: saved.draft, running };
}
