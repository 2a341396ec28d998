/**
 * The cells of one chapter page: the chapter's own, and those the reader
 * added (added-cells.ts). Makes each LiveCell with the hooks it reports
 * through, adds and deletes the reader's cells, and says what the reader
 * changed (provenance, for the data exports).
 */
import { addedCellElement, addedCellId } from './added-cells.ts';
import { LiveCell, type CellHooks } from './cell.ts';
import type { SharedCell } from './share-format.ts';
import type { Notebook } from './runtime.ts';
import type { CellScheduler } from './schedule.ts';
import type { EditStore } from './storage.ts';
import { CellView } from './cell-view.ts';

/** What the page does for every cell, besides what ChapterCells itself does. */
export type PageHooks = Omit<CellHooks, 'onFirstResult' | 'onDefine' | 'addCellAfter' | 'deleteCell'>;

/** A reader's change to a chapter, as the data exports record it. */
export interface ChangedCell {
  readonly cell: string;
  /** The code that runs. */
  readonly source: string;
  /** True for a cell the reader added. */
  readonly added: boolean;
}

export class ChapterCells {
  readonly cells: LiveCell[] = [];
  readonly #root: HTMLElement;
  readonly #store: EditStore;
  readonly #notebook: Notebook;
  readonly #scheduler: CellScheduler;
  readonly #hooks: PageHooks;

  constructor(root: HTMLElement, store: EditStore, notebook: Notebook, scheduler: CellScheduler, hooks: PageHooks) {
    this.#root = root;
    this.#store = store;
    this.#notebook = notebook;
    this.#scheduler = scheduler;
    this.#hooks = hooks;
  }

  /** Makes the cells of the chapter's markup, then puts back the ones the reader added on earlier visits. */
  build(): void {
    for (const element of this.#root.querySelectorAll<HTMLElement>('[data-cell]')) this.#make(element);
    for (const { id, after } of this.#store.loadAdded()) {
      const anchor = this.cells.find((cell) => cell.id === after) ?? this.cells.at(-1);
      if (anchor && !this.cells.some((cell) => cell.id === id)) this.#insert(anchor, id);
    }
  }

  /** Adds an empty cell of the reader's below `anchor`, starts it, and puts the cursor in it. */
  add(anchor: LiveCell): LiveCell | null {
    const cell = this.#insert(anchor, addedCellId());
    if (!cell) return null;
    this.#saveAdded();
    this.#scheduler.want(cell);
    void cell.mountEditor().then(() => cell.focus());
    return cell;
  }

  /** Deletes a cell the reader added: its definition, its markup and what was saved of it. */
  remove(cell: LiveCell): void {
    const index = this.cells.indexOf(cell);
    if (index < 0 || !cell.added) return;
    this.cells.splice(index, 1);
    cell.dispose();
    this.#saveAdded();
  }

  /** The reader's edits and added cells, in page order. */
  provenance(): ChangedCell[] {
    return this.cells.flatMap((cell) => {
      const edit = cell.edit;
      if (!edit && !cell.added) return [];
      return [{ cell: cell.id, source: edit?.running ?? '', added: cell.added }];
    });
  }

  /**
   * What a shared link carries (share-ui.ts): the text each changed cell
   * shows, and every added cell that has text, in page order; `unrun` names
   * the cells whose text shown is not the code that runs. A cell not
   * started yet shows, once started, its saved edit unless that is offered
   * instead (drafts.ts), so that is what it contributes.
   */
  shareable(): { cells: SharedCell[]; unrun: string[] } {
    const cells: SharedCell[] = [];
    const unrun: string[] = [];
    let after: string | null = null;
    for (const cell of this.cells) {
      const text = this.#shownEdit(cell);
      if (text && text.draft !== text.running) unrun.push(cell.id);
      if (cell.added && text?.draft) cells.push({ kind: 'added', id: cell.id, source: text.draft, after: after ?? cell.id });
      else if (!cell.added && text) cells.push({ kind: 'edit', id: cell.id, source: text.draft, base: cell.root.dataset.cellHash ?? '' });
      if (!cell.added || text?.draft) after = cell.id;
    }
    // An added cell above every chapter cell cannot be: added cells always follow one.
    return { cells: cells.filter((c) => c.kind === 'edit' || c.after !== c.id), unrun };
  }

  /** The text a cell shows and the code it runs, when either is not the chapter's (null: the original). */
  #shownEdit(cell: LiveCell): { draft: string; running: string } | null {
    if (cell.started) return cell.edit;
    const saved = this.#store.load(cell.id);
    if (!saved || this.#store.wasRunning(cell.id) || saved.base !== (cell.root.dataset.cellHash ?? '')) return null;
    // Not started: its <pre> still holds the chapter's original.
    const original = cell.root.querySelector('pre.cell-code > code')?.textContent ?? '';
    const running = saved.ran ?? original;
    return saved.draft === original && running === original ? null : { draft: saved.draft, running };
  }

  #insert(anchor: LiveCell, id: string): LiveCell | null {
    const element = addedCellElement(anchor.root, id);
    anchor.root.after(element);
    const cell = this.#make(element);
    if (cell) {
      // In page order, so that the saved list and the provenance read top to bottom.
      this.cells.splice(this.cells.indexOf(cell), 1);
      this.cells.splice(this.cells.indexOf(anchor) + 1, 0, cell);
    }
    return cell;
  }

  #make(element: HTMLElement): LiveCell | null {
    try {
      const cell: LiveCell = new LiveCell(new CellView(element), this.#notebook, this.#store, {
        ...this.#hooks,
        onFirstResult: () => this.#scheduler.firstResult(cell),
        onDefine: (spec) => this.#scheduler.wantInputs(spec.inputs),
        addCellAfter: () => void this.add(cell),
        deleteCell: () => this.remove(cell),
      });
      this.cells.push(cell);
      this.#scheduler.add(cell);
      return cell;
    } catch (error) {
      // Markup the build did not produce (hand-edited HTML?): skip this cell, keep the others.
      console.error(error);
      return null;
    }
  }

  #saveAdded(): void {
    const added = this.cells.flatMap((cell, i) => (cell.added && i > 0 ? [{ id: cell.id, after: this.cells[i - 1].id }] : []));
    this.#store.saveAdded(added);
  }
}
