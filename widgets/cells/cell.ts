/**
 * One live cell: ties its view, its runtime variable, the reader's saved
 * edit (drafts.ts) and, once loaded, its editor together.
 *
 * Promises to the reader:
 * - the page never throws their text away: a syntax error keeps the old
 *   definition running and the text in the editor, and drafts are saved as
 *   they type;
 * - an edit made from an older version of the chapter's cell is offered,
 *   never applied silently.
 */
import { compileCell } from './compile.ts';
import { DraftKeeper } from './drafts.ts';
import type { CellEditor } from './editor.ts';
import { loadEditor, loadParser } from './lazy.ts';
import type { CellVariable, Notebook } from './runtime.ts';
import { formatError, type CellSpec } from './spec.ts';
import type { EditStore, SavedEdit } from './storage.ts';
import type { CellView } from './view.ts';

/** A key that edits text (a character, Enter, Backspace, Delete, Tab), not a shortcut or a move. */
function isTyping(event: KeyboardEvent): boolean {
  if (event.ctrlKey || event.metaKey || event.altKey) return false;
  return event.key.length === 1 || ['Enter', 'Backspace', 'Delete', 'Tab'].includes(event.key);
}

/** What a cell tells whoever schedules it. */
export interface CellHooks {
  /** The cell showed its first value or error. */
  onFirstResult(): void;
  /** The cell is about to be defined by `spec`: the cells it reads must run too. */
  onDefine(spec: CellSpec): void;
}

export class LiveCell {
  readonly #view: CellView;
  readonly #notebook: Notebook;
  readonly #drafts: DraftKeeper;
  readonly #variable: CellVariable;
  readonly #hooks: CellHooks;
  #hasResult = false;
  #started = false;
  /** The text the reader sees, whether or not it runs. */
  #draft: string;
  #editor: CellEditor | null = null;
  #editorLoading: Promise<void> | null = null;
  /** Keys typed into the static code while the editor loads, replayed into it once mounted. */
  #typedAhead: string[] = [];

  constructor(view: CellView, notebook: Notebook, store: EditStore, hooks: CellHooks) {
    this.#view = view;
    this.#notebook = notebook;
    this.#drafts = new DraftKeeper(store, view.id, view.originalSource, view.hash);
    this.#hooks = hooks;
    this.#draft = view.originalSource;
    view.setState('waiting');
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
        view.setError('runtime', notebook.describeFailure(error, name));
        this.#firstResult();
      },
    });
    this.#listen();
    document.addEventListener('phasebook:compiling', () => view.showCompiling());
  }

  /** The cell's name as the chapter wrote it, for finding the cells that read it. */
  get name(): string | null {
    return this.#view.originalSpec?.name ?? null;
  }

  get root(): HTMLElement {
    return this.#view.root;
  }

  /** True once the cell has been defined (it then keeps running as its inputs change). */
  get started(): boolean {
    return this.#started;
  }

  /** Defines the cell: with the reader's saved edit if it matches this chapter, else the original. */
  async start(): Promise<void> {
    if (this.#started) return;
    this.#started = true;
    const starting = this.#drafts.starting();
    if (starting.kind === 'apply') {
      this.#showDraft(starting.source);
      if (await this.#apply(starting.source)) return;
    } else if (starting.kind === 'offer') {
      this.#offer(starting.edit);
    }
    this.#defineOriginal();
  }

  /** Runs what the reader sees now (Run button, Shift+Enter). */
  async run(): Promise<void> {
    this.#started = true;
    const source = this.#editor?.source ?? this.#draft;
    this.#draft = source;
    this.#view.setBusy(true);
    try {
      await this.#apply(source);
    } finally {
      this.#view.setBusy(false);
    }
    // Running changed text while an old edit is on offer means the reader moved on.
    if (this.#drafts.offering && source !== this.#view.originalSource) this.#closeOffer();
    this.#drafts.commit(source);
  }

  /** Back to the chapter's original. Undoable in the editor with Ctrl+Z. */
  reset(): void {
    this.#showDraft(this.#view.originalSource);
    this.#drafts.commit(this.#view.originalSource);
    this.#view.setError('compile', null);
    this.#defineOriginal();
  }

  /** Swaps the static code for the editor; `clickAt` keeps the cursor where the reader clicked. */
  mountEditor(clickAt?: { x: number; y: number }): Promise<void> {
    this.#editorLoading ??= loadEditor().then(({ mountEditor }) => {
      const pre = this.#view.staticCode;
      const hadFocus = pre !== null && pre === document.activeElement;
      const name = this.#view.root.dataset.cellName;
      this.#editor = mountEditor(
        this.#view.editorHost,
        {
          source: this.#draft,
          label: name ? `Code cell ${name}` : 'Code cell',
          onRun: () => void this.run(),
          onChange: (source) => this.#changed(source),
        },
        hadFocus ? clickAt : undefined,
      );
      if (hadFocus) this.#editor.focus();
      if (this.#typedAhead.length) this.#editor.typeKeys(this.#typedAhead.splice(0));
    }).catch((error: unknown) => {
      // Offline, or the site changed under the page: the static code stays, and the next focus tries again.
      this.#editorLoading = null;
      this.#view.setError('compile', `The editor could not load (${formatError(error)}); reload the page to edit this cell.`);
    });
    return this.#editorLoading;
  }

  #listen(): void {
    const host = this.#view.editorHost;
    let clickAt: { x: number; y: number } | undefined;
    host.addEventListener('pointerdown', (event) => (clickAt = { x: event.clientX, y: event.clientY }));
    // Hovering a cell is a hint that the reader may edit it: fetch the editor, mount it on focus.
    host.addEventListener('pointerenter', () => void loadEditor().catch(() => undefined), { once: true });
    host.addEventListener('focusin', () => {
      if (!this.#editor) void this.mountEditor(clickAt);
    });
    host.addEventListener('keydown', (event) => {
      if (this.#editor) return;
      if (event.key === 'Enter' && event.shiftKey) {
        event.preventDefault();
        void this.run();
      } else if (isTyping(event)) {
        // The editor is still loading: keep the keystroke for it rather than lose it.
        event.preventDefault();
        this.#typedAhead.push(event.key);
        void this.mountEditor(clickAt);
      }
    });
    this.#view.runButton.addEventListener('click', () => void this.run());
    this.#view.resetButton.addEventListener('click', () => this.reset());
  }

  /**
   * Compiles and defines `source`, loading the parser unless it is the
   * original (which the build parsed). On a syntax error the old definition
   * keeps running and the error shows under the cell; returns whether it took.
   */
  async #apply(source: string): Promise<boolean> {
    let spec: CellSpec;
    try {
      const original = this.#view.originalSpec;
      spec = source === this.#view.originalSource && original ? original : (await loadParser()).parseSource(source);
      const definition = compileCell(source, spec, this.#view.id);
      this.#view.setError('compile', null);
      this.#hooks.onDefine(spec);
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
      const definition = compileCell(this.#view.originalSource, spec, this.#view.id);
      this.#hooks.onDefine(spec);
      this.#notebook.define(this.#variable, spec, definition);
    } catch (error) {
      this.#view.setError('compile', formatError(error));
      this.#firstResult();
    }
  }

  #changed(source: string): void {
    this.#draft = source;
    this.#view.setEdited(source !== this.#view.originalSource);
    this.#drafts.changed(source);
  }

  #showDraft(source: string): void {
    this.#draft = source;
    if (this.#editor && this.#editor.source !== source) this.#editor.replaceSource(source);
    else if (!this.#editor) this.#view.showStaticSource(source);
    this.#view.setEdited(source !== this.#view.originalSource);
  }

  #offer(edit: SavedEdit): void {
    const when = new Date(edit.savedAt).toLocaleDateString();
    this.#view.showNotice(`This cell changed since your edit of ${when}.`, [
      {
        label: 'Restore my edit',
        run: () => {
          this.#closeOffer();
          this.#showDraft(edit.source);
          void this.run();
        },
      },
      {
        label: 'Discard',
        run: () => {
          this.#closeOffer();
          this.#drafts.commit(this.#draft);
        },
      },
    ]);
  }

  #closeOffer(): void {
    this.#drafts.closeOffer();
    this.#view.clearNotice();
  }

  #firstResult(): void {
    if (this.#hasResult) return;
    this.#hasResult = true;
    this.#hooks.onFirstResult();
  }
}
