/**
 * The cells of one chapter page: the chapter's own, and those the reader
 * added (added-cells.ts). Makes each LiveCell with the hooks it reports
 * through, adds and deletes the reader's cells, and says what the reader
 * changed (provenance, for the data exports).
 */
import { LiveCell, type CellHooks } from './cell.ts';
import type { Notebook } from './runtime.ts';
import type { CellScheduler } from './schedule.ts';
import { explainLoadFailure } from './load-failure.ts';
import { formatError } from './spec.ts';
import type { AddedCell, EditStore } from './storage.ts';
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

/** The code that builds a cell of the reader's: wanted only where the reader added one. */
const loadAddedCells = () => import('./added-cells.ts');

export class ChapterCells {
  readonly cells: LiveCell[] = [];
  readonly #root: HTMLElement;
  readonly #store: EditStore;
  readonly #notebook: Notebook;
  readonly #scheduler: CellScheduler;
  readonly #hooks: PageHooks;
  /** Added cells that could not be put back (their code did not load): kept in storage as they are. */
  #addedKept: readonly AddedCell[] | null = null;

  constructor(root: HTMLElement, store: EditStore, notebook: Notebook, scheduler: CellScheduler, hooks: PageHooks) {
    this.#root = root;
    this.#store = store;
    this.#notebook = notebook;
    this.#scheduler = scheduler;
    this.#hooks = hooks;
  }

  /**
   * Makes the cells of the chapter's markup, then puts back the ones the
   * reader added on earlier visits; the code that builds those loads only
   * on a page that has some (added-cells.ts, a chunk of its own).
   */
  async build(): Promise<void> {
    for (const element of this.#root.querySelectorAll<HTMLElement>('[data-cell]')) this.#make(element);
    const added = this.#store.loadAdded();
    if (!added.length) return;
    let addedCellElement: typeof import('./added-cells.ts').addedCellElement;
    try {
      ({ addedCellElement } = await loadAddedCells());
    } catch (error) {
      // Offline: the chapter's cells run, the reader's own stay kept (never written over) for the next load.
      this.#addedKept = added;
      console.warn(explainLoadFailure(error, 'The cells you added'));
      return;
    }
    for (const { id, after } of added) {
      const anchor = this.cells.find((cell) => cell.id === after) ?? this.cells.at(-1);
      if (anchor && !this.cells.some((cell) => cell.id === id)) this.#insert(anchor, addedCellElement(anchor.root, id));
    }
  }

  /** Adds an empty cell of the reader's below `anchor`, starts it, and puts the cursor in it. */
  async add(anchor: LiveCell): Promise<LiveCell | null> {
    let module: typeof import('./added-cells.ts');
    try {
      module = await loadAddedCells();
    } catch (error) {
      anchor.showLaterError(formatError(explainLoadFailure(error, 'A new cell')));
      return null;
    }
    const cell = this.#insert(anchor, module.addedCellElement(anchor.root, module.addedCellId()));
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

  /** Where the reader's edits are kept (the share code reads the edits of cells not started yet). */
  get store(): EditStore {
    return this.#store;
  }

  /** The reader's edits and added cells, in page order. */
  provenance(): ChangedCell[] {
    return this.cells.flatMap((cell) => {
      const edit = cell.edit;
      if (!edit && !cell.added) return [];
      return [{ cell: cell.id, source: edit?.running ?? '', added: cell.added }];
    });
  }

  #insert(anchor: LiveCell, element: HTMLElement): LiveCell | null {
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
    if (this.#addedKept) return;
    const added = this.cells.flatMap((cell, i) => (cell.added && i > 0 ? [{ id: cell.id, after: this.cells[i - 1].id }] : []));
    this.#store.saveAdded(added);
  }
}
