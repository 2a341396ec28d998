/**
 * One cell of the preview, on the book's own parts: its markup and view
 * (cells/cell-view.ts), compiled by cell-definition.ts, defined in the page's
 * notebook (runtime.ts). Unlike a reader's cell on the page it has no
 * editor and keeps no edits: its code is the chapter's, and a new version
 * of the code (the author typed) redefines the same runtime variable, so
 * the cells that read it follow.
 */
import { compileCell, type CellVariable, type Notebook, formatError, CellView } from '../../../cells/index.ts';
import type { CellReport } from '../shared/messages.ts';

type State = CellReport['state'];

export class PreviewCell {
  readonly #notebook: Notebook;
  readonly #variable: CellVariable;
  readonly #changed: () => void;
  #view: CellView;
  #state: State = 'waiting';
  /** The cell's own runtime error; one that came through an input is its input's to report. */
  #error: string | undefined;
  #waiters: (() => void)[] = [];

  constructor(root: HTMLElement, notebook: Notebook, changed: () => void) {
    this.#notebook = notebook;
    this.#changed = changed;
    this.#view = new CellView(root);
    this.#variable = notebook.add({
      pending: () => this.#setState('pending'),
      fulfilled: (value, name) => {
        this.#view.setState('fulfilled');
        this.#view.setError('runtime', null);
        this.#view.showValue(value, name);
        this.#error = undefined;
        this.#setState('fulfilled');
      },
      rejected: (error, name) => {
        const message = notebook.describeFailure(error, name);
        this.#view.setState('rejected');
        this.#view.clearOutput();
        this.#view.setError('runtime', message);
        // describeFailure rewrites only an error that came through another cell.
        this.#error = message === formatError(error) ? message : undefined;
        this.#setState('rejected');
      },
    });
    this.#listen();
    this.#define();
  }

  get root(): HTMLElement {
    return this.#view.root;
  }

  get state(): State {
    return this.#state;
  }

  get error(): string | undefined {
    return this.#error;
  }

  /**
   * Takes the place of `fresh`, a new rendering of this cell: the live
   * element stays (widget and all) when the code is the same; otherwise the
   * fresh element comes in, showing the old value until the new one arrives.
   */
  adopt(fresh: HTMLElement): 'kept' | 'changed' {
    if (fresh === this.root) return 'kept';
    if (fresh.dataset.cellHash === this.root.dataset.cellHash) {
      fresh.replaceWith(this.root);
      return 'kept';
    }
    const output = this.root.querySelector('[data-cell-output]');
    if (output) fresh.querySelector('[data-cell-output]')?.replaceWith(output);
    this.#view = new CellView(fresh);
    this.#listen();
    this.#define();
    return 'changed';
  }

  /** Runs the cell again (the runtime recomputes it and what reads it). */
  run(): void {
    this.#define();
  }

  /** Resolves once the cell has a value or an error; at once when it has one already. */
  settled(): Promise<void> {
    if (this.#state === 'fulfilled' || this.#state === 'rejected') return Promise.resolve();
    return new Promise((resolve) => this.#waiters.push(resolve));
  }

  /** The cell left the chapter: its name is freed and its widgets are invalidated. */
  dispose(): void {
    this.#notebook.define(this.#variable, { name: null, inputs: [], async: false, generator: false, body: [0, 0], block: false }, () => undefined);
    this.#variable.delete();
    this.#waiters.splice(0).forEach((wake) => wake());
  }

  #setState(state: State): void {
    if (state === 'pending') this.#view.setState('pending');
    this.#state = state;
    if (state === 'fulfilled' || state === 'rejected') this.#waiters.splice(0).forEach((wake) => wake());
    this.#changed();
  }

  #listen(): void {
    this.#view.runButton.addEventListener('click', () => this.run());
  }

  /**
   * Compiles and defines the chapter's code. Code that does not parse keeps
   * the previous definition running, as on the page, with the error shown.
   */
  #define(): void {
    const view = this.#view;
    try {
      const spec = view.originalSpec;
      if (!spec) throw new SyntaxError(view.buildError?.replace(/^SyntaxError: /, '') ?? 'this cell could not be parsed');
      const definition = compileCell(view.originalSource, spec, view.id);
      view.setError('compile', null);
      this.#notebook.define(this.#variable, spec, definition);
      // Redefined: whatever it showed is about to be replaced.
      this.#setState('pending');
    } catch (error) {
      view.setError('compile', formatError(error));
      if (this.#state === 'waiting') {
        this.#error = formatError(error);
        this.#setState('rejected');
      }
    }
  }
}
