/**
 * One live cell: ties its view, its runtime variable, the reader's saved edit
 * and (once loaded) its editor together.
 *
 * Invariants the reader can rely on:
 * - the text they typed is never thrown away by the page: a syntax error keeps
 *   the old definition running and the text in the editor, and drafts are
 *   saved as they type;
 * - a saved edit made from an older version of the chapter's cell is offered,
 *   never applied silently.
 */
import { RuntimeError } from '@observablehq/runtime';
import { compileCell } from './compile.ts';
import type { CellEditor } from './editor.ts';
import { loadEditor, loadParser } from './lazy.ts';
import type { CellVariable, Notebook } from './runtime.ts';
import { formatError, type CellSpec } from './spec.ts';
import type { EditStore, SavedEdit } from './storage.ts';
import type { CellView } from './view.ts';

/** Drafts are saved this long after the last keystroke. */
const SAVE_DELAY_MS = 400;

export class LiveCell {
  readonly #view: CellView;
  readonly #notebook: Notebook;
  readonly #store: EditStore;
  readonly #variable: CellVariable;
  readonly #onFirstResult: () => void;
  #hasResult = false;
  /** The text the reader sees, whether or not it runs. */
  #draft: string;
  #editor: CellEditor | null = null;
  #editorLoading: Promise<void> | null = null;
  /** A saved edit from an older version of this cell, while it is on offer. */
  #offer: SavedEdit | null = null;
  #saveTimer: ReturnType<typeof setTimeout> | undefined;

  constructor(view: CellView, notebook: Notebook, store: EditStore, onFirstResult: () => void) {
    this.#view = view;
    this.#notebook = notebook;
    this.#store = store;
    this.#onFirstResult = onFirstResult;
    this.#draft = view.originalSource;
    this.#variable = notebook.add({
      pending: () => view.setState('pending'),
      fulfilled: (value, name) => {
        view.setState('fulfilled');
        view.setError('runtime', null);
        view.showValue(value, name);
        this.#firstResult();
      },
      rejected: (error, name) => {
        view.setState('rejected');
        view.clearOutput();
        view.setError('runtime', this.#describeFailure(error, name));
        this.#firstResult();
      },
    });
    this.#listen();
  }

  /** Defines the cell: with the reader's saved edit if it matches this chapter, else the original. */
  async start(): Promise<void> {
    const saved = this.#store.load(this.#view.id);
    if (saved && saved.source !== this.#view.originalSource) {
      if (saved.base === this.#view.hash) {
        this.#showDraft(saved.source);
        if (await this.#apply(saved.source)) return;
      } else {
        this.#offerStale(saved);
      }
    }
    this.#defineOriginal();
  }

  /** Runs what the reader sees now (Run button, Shift+Enter). */
  async run(): Promise<void> {
    clearTimeout(this.#saveTimer);
    const source = this.#editor?.source ?? this.#draft;
    this.#draft = source;
    this.#view.setBusy(true);
    try {
      await this.#apply(source);
    } finally {
      this.#view.setBusy(false);
    }
    if (this.#offer && source !== this.#view.originalSource) this.#dismissOffer();
    this.#persist(source);
  }

  /** Back to the chapter's original. Undoable in the editor with Ctrl+Z. */
  async reset(): Promise<void> {
    clearTimeout(this.#saveTimer);
    this.#showDraft(this.#view.originalSource);
    this.#persist(this.#view.originalSource);
    this.#view.setError('compile', null);
    this.#defineOriginal();
  }

  /** Swaps the static code for the editor; `clickAt` keeps the cursor where the reader clicked. */
  mountEditor(clickAt?: { x: number; y: number }): Promise<void> {
    this.#editorLoading ??= loadEditor().then(({ mountEditor }) => {
      const pre = this.#view.staticCode;
      const hadFocus = pre !== null && pre === document.activeElement;
      this.#editor = mountEditor(
        this.#view.editorHost,
        {
          source: this.#draft,
          label: this.#view.root.dataset.cellName ? `Code cell ${this.#view.root.dataset.cellName}` : 'Code cell',
          onRun: () => void this.run(),
          onChange: (source) => this.#changed(source),
        },
        hadFocus ? clickAt : undefined,
      );
      if (hadFocus) this.#editor.focus();
    });
    return this.#editorLoading;
  }

  #listen(): void {
    const host = this.#view.editorHost;
    let clickAt: { x: number; y: number } | undefined;
    host.addEventListener('pointerdown', (event) => (clickAt = { x: event.clientX, y: event.clientY }));
    host.addEventListener('focusin', () => void this.mountEditor(clickAt), { once: true });
    host.addEventListener('keydown', (event) => {
      if (!this.#editor && event.key === 'Enter' && event.shiftKey) {
        event.preventDefault();
        void this.run();
      }
    });
    this.#view.runButton.addEventListener('click', () => void this.run());
    this.#view.resetButton.addEventListener('click', () => void this.reset());
  }

  /**
   * Compiles and defines `source`. On a syntax error the old definition keeps
   * running and the error shows under the cell; returns whether it took.
   */
  async #apply(source: string): Promise<boolean> {
    let spec: CellSpec;
    try {
      const original = this.#view.originalSpec;
      spec = source === this.#view.originalSource && original ? original : (await loadParser()).parseSource(source);
      const definition = compileCell(source, spec, this.#view.id);
      this.#view.setError('compile', null);
      this.#notebook.define(this.#variable, spec, definition);
      return true;
    } catch (error) {
      this.#view.setError('compile', formatError(error));
      this.#firstResult();
      return false;
    }
  }

  /** Defines the original without touching a compile error the reader's text may have. */
  #defineOriginal(): void {
    const spec = this.#view.originalSpec;
    try {
      if (!spec) throw new SyntaxError(this.#view.buildError?.replace(/^SyntaxError: /, '') ?? 'this cell could not be parsed');
      this.#notebook.define(this.#variable, spec, compileCell(this.#view.originalSource, spec, this.#view.id));
    } catch (error) {
      this.#view.setError('compile', formatError(error));
      this.#firstResult();
    }
  }

  #changed(source: string): void {
    this.#draft = source;
    this.#view.setEdited(source !== this.#view.originalSource);
    clearTimeout(this.#saveTimer);
    // While an old edit is on offer, typing must not overwrite it; Run decides.
    if (!this.#offer) this.#saveTimer = setTimeout(() => this.#persist(source), SAVE_DELAY_MS);
  }

  #persist(source: string): void {
    const edited = source !== this.#view.originalSource;
    this.#view.setEdited(edited);
    if (this.#offer) return;
    if (edited) this.#store.save(this.#view.id, source, this.#view.hash);
    else this.#store.forget(this.#view.id);
  }

  #showDraft(source: string): void {
    this.#draft = source;
    if (this.#editor && this.#editor.source !== source) this.#editor.replaceSource(source);
    else if (!this.#editor) this.#view.showStaticSource(source);
    this.#view.setEdited(source !== this.#view.originalSource);
  }

  #offerStale(saved: SavedEdit): void {
    this.#offer = saved;
    const when = new Date(saved.savedAt).toLocaleDateString();
    this.#view.showNotice(`This cell changed since your edit of ${when}.`, [
      {
        label: 'Restore my edit',
        run: () => {
          this.#dismissOffer();
          this.#showDraft(saved.source);
          void this.run();
        },
      },
      {
        label: 'Discard',
        run: () => {
          this.#dismissOffer();
          this.#persist(this.#draft);
        },
      },
    ]);
  }

  #dismissOffer(): void {
    this.#offer = null;
    this.#view.clearNotice();
  }

  /** A failure that came through an input names that input, so the reader looks in the right cell. */
  #describeFailure(error: unknown, name: string | null): string {
    const input = error instanceof RuntimeError ? error.input : undefined;
    if (input && input !== name && this.#notebook.isCell(input)) {
      return `RuntimeError: input ${input} failed: ${(error as Error).message}`;
    }
    return formatError(error);
  }

  #firstResult(): void {
    if (this.#hasResult) return;
    this.#hasResult = true;
    this.#onFirstResult();
  }
}
