/**
 * One live cell: ties its view, its runtime variable, the reader's saved
 * edit (drafts.ts) and, once loaded, its editor together.
 *
 * Promises to the reader:
 * - the page never throws their text away: a syntax error keeps the old
 *   definition running and the text in the editor, drafts are saved as they
 *   type and when the page is left, and a save that fails says so;
 * - only code the reader ran runs again on the next load; a draft is shown,
 *   never run;
 * - an edit made from an older version of the chapter's cell, one that was
 *   still running when the page last died, or one another tab saved since,
 *   is offered, never applied silently.
 */
import { compileCell, type CellScope } from './cell-definition.ts';
import { DraftKeeper, type SaveProblem } from './drafts.ts';
import type { CellEditor } from './editor.ts';
import { loadEditor, loadParser } from './lazy.ts';
import type { CellVariable, Notebook } from './runtime.ts';
import { formatError, type CellSpec } from './spec.ts';
import type { EditStore, SavedEdit } from './storage.ts';
import type { CellView } from './cell-view.ts';
import type { LoopStopped } from './loop-guard.ts';
import type { HeldCell } from './sandbox/reload-notice.ts';

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
  /** Offers the reader a download of every edit on the page (storage cannot keep them). */
  downloadEdits(): void;
  /**
   * After a cell's result: puts back any part of Math a cell replaced (naming
   * it) and says whether the chapter is still on the page (integrity.ts).
   */
  checkPage(): { restored: readonly string[]; intact: boolean };
  /** The chapter is gone from the page because of this cell's code. */
  pageBroken(label: string): void;
  /** The reader asked for a cell of their own below this one. */
  addCellAfter(): void;
  /** The reader deleted this cell (one they had added). */
  deleteCell(): void;
  /**
   * Readies the page for code that is not the chapter's own (sandbox/index.ts):
   * the names that code sees in place of some of the page's globals.
   */
  readerScope(): Promise<CellScope>;
  /** A saved edit is about to run as the page loads: true when it must be shown and not run (the page reloads itself in a loop). */
  holdSaved(cell: HeldCell): Promise<boolean>;
  /** Cell `id` is about to be defined again (or deleted): what its old code set going goes with it. */
  redefining(id: string): void;
}

/** After the reader's code has shown a result, the page must stay responsive this long to count as having survived it. */
const SURVIVAL_MS = 1000;
/** …or this long without a result (a cell may wait on a promise for ever without freezing anything). */
const SURVIVAL_WITHOUT_RESULT_MS = 10_000;

export class LiveCell implements HeldCell {
  readonly #view: CellView;
  readonly #notebook: Notebook;
  readonly #drafts: DraftKeeper;
  readonly #variable: CellVariable;
  readonly #hooks: CellHooks;
  #hasResult = false;
  #started = false;
  /** Clears the "running" mark once the page has survived the reader's code (see #runReaderCode). */
  #survival: { result: boolean; timer: ReturnType<typeof setTimeout> } | null = null;
  /** The text the reader sees, whether or not it runs. */
  #draft: string;
  /** The text whose definition runs (the original until the reader runs something else). */
  #running: string;
  /** The inputs of the running definition. */
  #inputs: readonly string[] = [];
  /** The last Run's compile and define, which may still be loading the parser or the sandbox. */
  #applying: Promise<boolean> = Promise.resolve(true);
  #editor: CellEditor | null = null;
  #editorLoading: Promise<void> | null = null;
  /** Keys typed into the static code while the editor loads, replayed into it once mounted. */
  #typedAhead: string[] = [];
  /** The saved edit held back because the page reloads itself in a loop (see {@link runHeld}). */
  #held: string | null = null;
  /** What the running definition failed with, and the line shown for code of the cell that failed later. */
  #runtimeError: string | null = null;
  #laterError: string | null = null;
  /** The value the running definition gave, until it runs again (undefined while pending or failed). */
  #value: unknown = undefined;

  constructor(view: CellView, notebook: Notebook, store: EditStore, hooks: CellHooks) {
    this.#view = view;
    this.#notebook = notebook;
    this.#drafts = new DraftKeeper(store, view.id, view.originalSource, view.hash, (problem) => this.#saveProblem(problem));
    this.#hooks = hooks;
    this.#draft = view.originalSource;
    this.#running = view.originalSource;
    view.setState('waiting');
    this.#variable = notebook.add({
      pending: () => {
        this.#value = undefined;
        view.setState('pending');
      },
      fulfilled: (value, name) => {
        this.#value = value;
        view.setState('fulfilled');
        this.#runtimeError = null;
        view.setError('runtime', null);
        view.showValue(value, name);
        this.#firstResult();
        this.#resulted();
      },
      rejected: (error, name) => {
        this.#value = undefined;
        view.setState('rejected');
        view.clearOutput();
        this.#runtimeError = notebook.describeFailure(error, name);
        view.setError('runtime', this.#runtimeError);
        // A stopped loop is said once: as the cell's failure, when it failed with it.
        if (this.#laterError === this.#runtimeError) this.#setLaterError(null);
        this.#firstResult();
        this.#resulted();
      },
    });
    this.#listen();
    document.addEventListener('phasebook:compiling', (event) => view.showCompiling((event as CustomEvent<{ fraction?: number } | null>).detail?.fraction));
  }

  /** The cell's id on the page (its name, or `cell-N`). */
  get id(): string {
    return this.#view.id;
  }

  /** The reader's text and the code that runs, when either is not the chapter's original. */
  get edit(): { draft: string; running: string } | null {
    const original = this.#view.originalSource;
    const draft = this.#editor?.source ?? this.#draft;
    return draft === original && this.#running === original ? null : { draft, running: this.#running };
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

  /** Defines the cell: with the code the reader last ran, if the page may run it (drafts.ts), else the original. */
  async start(): Promise<void> {
    if (this.#started) return;
    this.#started = true;
    const starting = this.#drafts.starting();
    if (starting.kind === 'run') {
      this.#showDraft(starting.draft);
      // The edit needs the parser as well as the sandbox: both are fetched at once.
      void loadParser().catch(() => undefined);
      if (await this.#hooks.holdSaved(this)) this.#held = starting.ran;
      else if (await this.#apply(starting.ran)) return;
    } else if (starting.kind === 'draft') {
      this.#showDraft(starting.draft);
    } else if (starting.kind === 'offer') {
      this.#offer(starting.edit, starting.why);
    } else if (starting.kind === 'damaged') {
      this.#offerDamaged(starting.raw);
    }
    this.#defineOriginal();
  }

  /** Runs what the reader sees now (Run button, Shift+Enter). */
  async run(): Promise<void> {
    this.#started = true;
    this.#held = null;
    const source = this.#editor?.source ?? this.#draft;
    this.#draft = source;
    this.#view.setBusy(true);
    let took: boolean;
    const applying = this.#apply(source);
    this.#applying = applying;
    try {
      took = await applying;
    } finally {
      this.#view.setBusy(false);
    }
    // Running changed text while an old edit is on offer means the reader moved on.
    if (this.#drafts.offering && source !== this.#view.originalSource) this.#closeOffer();
    // Text that does not parse did not run: it is kept as a draft, and what ran before stays what runs.
    if (took) this.#drafts.ran(source);
    else this.#drafts.changed(source);
  }

  /** A cell the reader added rather than one of the chapter's. */
  get added(): boolean {
    return this.#view.added;
  }

  /** Puts the cursor in the cell's editor, once mounted. */
  focus(): void {
    this.#editor?.focus();
  }

  /** Takes the cell off the page: its definition, its markup and what was saved of it. */
  dispose(): void {
    if (this.#survival) clearTimeout(this.#survival.timer);
    this.#hooks.redefining(this.id);
    this.#drafts.survived();
    this.#drafts.forget();
    this.#notebook.remove(this.#variable);
    this.#view.root.remove();
  }

  /** Back to the chapter's original (for an added cell: delete it). Undoable in the editor with Ctrl+Z. */
  reset(): void {
    if (this.added) {
      this.#hooks.deleteCell();
      return;
    }
    this.#showDraft(this.#view.originalSource);
    this.#closeOffer();
    this.#drafts.ran(this.#view.originalSource);
    this.#view.setError('compile', null);
    this.#defineOriginal();
  }

  /** Saves a draft that is waiting for its delayed save: the page is being hidden or left. */
  flush(): void {
    this.#drafts.flush();
  }

  /**
   * The page is being left normally. A frozen page runs no handler, so a page
   * that gets here survived whatever the reader's code was doing.
   */
  leaving(): void {
    this.flush();
    if (this.#survival) {
      clearTimeout(this.#survival.timer);
      this.#survived();
    }
  }

  /** Code of this cell failed after the cell gave its value: shown until the cell runs again. */
  showLaterError(message: string): void {
    this.#setLaterError(message);
  }

  /**
   * A loop of this cell's code was stopped (loop-guard.ts). Said under the
   * cell unless its definition fails with it anyway; when its loops kept
   * being stopped and its timers and listeners were cleared (`cleared` says
   * so, sandbox/index.ts), that is said too, and the edit is offered rather
   * than run on the next load.
   */
  loopStopped(stop: LoopStopped, cleared: string | null): void {
    const message = `${formatError(stop)}${cleared ? `; ${cleared}` : ''}`;
    if (message !== this.#runtimeError) this.#setLaterError(message);
    if (cleared && this.#running !== this.#view.originalSource) {
      if (this.#survival) clearTimeout(this.#survival.timer);
      this.#survival = null;
      this.#drafts.markRunning();
    }
  }

  /** Runs the saved edit that was held back (the reader chose **Run my edits**). */
  runHeld(): void {
    const held = this.#held;
    this.#held = null;
    if (held !== null) void this.#apply(held);
  }

  /** Keeps the held edit as text not run, on this load and the next (the reader chose **Keep them off**). */
  keepHeldOff(): void {
    this.#held = null;
    this.#drafts.unrun(this.#editor?.source ?? this.#draft);
  }

  #setLaterError(message: string | null): void {
    this.#laterError = message;
    this.#view.setError('later', message);
  }

  /** The cell's current value: what its code last gave, or undefined while it runs or after it failed. */
  get value(): unknown {
    return this.#value;
  }

  /**
   * Resolves once the last Run has been compiled and defined, or refused.
   * Until then the runtime still holds the code that ran before: a reader of
   * the cell's value (an exercise's "Check my code") waits for this first.
   */
  get applied(): Promise<void> {
    return this.#applying.then(() => undefined);
  }

  /** True when the text the reader sees is not the code that runs (typed but not run, or refused by the parser). */
  get hasUnrunEdit(): boolean {
    return (this.#editor?.source ?? this.#draft) !== this.#running;
  }

  /** What the cell's code failed with, as shown under it, or null. */
  get error(): string | null {
    return this.#runtimeError;
  }

  /** The code the cell runs now. */
  get running(): string {
    return this.#running;
  }

  /**
   * Shows `source` in the cell and runs it as if the reader had typed it, under
   * the same rules: the page around an embed setting a cell (cells/embed.ts),
   * an exercise's "show me in the simulator" and its undo (cells/exercises.ts).
   */
  setSource(source: string): Promise<void> {
    this.#showDraft(source);
    return this.run();
  }

  /** The names this cell reads, as it is defined now. */
  get inputs(): readonly string[] {
    return this.#inputs;
  }

  /**
   * A widget set this cell's value (the dt field of a simulator whose dt came
   * from here): the cell becomes `name = value`, run as the reader's edit.
   */
  setFromWidget(value: number): void {
    const name = this.name;
    if (!name) return;
    void this.setSource(`${name} = ${value}`);
  }

  /** Another tab saved (or removed) this cell's edit. */
  externalChange(edit: SavedEdit | null): void {
    if (!edit || edit.draft === this.#draft) return;
    this.#offerTheirs(edit, 'This cell was changed in another tab.');
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
    this.#view.addButton?.addEventListener('click', () => this.#hooks.addCellAfter());
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
      const isOriginal = source === this.#view.originalSource && original !== null;
      spec = isOriginal && original ? original : (await loadParser()).parseSource(source);
      // Code that is not the chapter's runs in the sandbox, which must be in place first.
      const scope = isOriginal ? undefined : await this.#hooks.readerScope();
      const definition = compileCell(source, spec, this.#view.id, undefined, scope);
      this.#view.setError('compile', null);
      this.#hooks.onDefine(spec);
      if (source !== this.#view.originalSource) this.#watchSurvival();
      this.#setLaterError(null);
      this.#hooks.redefining(this.id);
      this.#notebook.define(this.#variable, spec, definition);
      this.#running = source;
      this.#inputs = spec.inputs;
      this.#updateStatus();
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
      this.#setLaterError(null);
      this.#hooks.redefining(this.id);
      this.#notebook.define(this.#variable, spec, definition);
      this.#running = this.#view.originalSource;
      this.#inputs = spec.inputs;
      this.#updateStatus();
    } catch (error) {
      this.#view.setError('compile', formatError(error));
      this.#firstResult();
    }
  }

  #changed(source: string): void {
    this.#draft = source;
    this.#updateStatus();
    this.#drafts.changed(source);
  }

  #showDraft(source: string): void {
    this.#draft = source;
    if (this.#editor && this.#editor.source !== source) this.#editor.replaceSource(source);
    else if (!this.#editor) this.#view.showStaticSource(source);
    this.#updateStatus();
  }

  /** "edited" when the reader's code runs, "not run yet" when the text shown is not what runs. */
  #updateStatus(): void {
    const original = this.#view.originalSource;
    this.#view.setEdited(this.#draft !== original || this.#running !== original, this.#draft !== this.#running);
  }

  #offer(edit: SavedEdit, why: 'changed' | 'stopped'): void {
    const when = new Date(edit.savedAt).toLocaleDateString();
    const text = edit.ran ?? edit.draft;
    if (why === 'stopped') {
      this.#view.showNotice('Your edit of this cell did not finish the last time it ran: the page stopped. The original runs instead.', [
        { label: 'Run my edit', run: () => this.#takeEdit(text, true) },
        { label: 'Edit it', run: () => this.#takeEdit(text, false) },
        { label: 'Discard', run: () => this.#discardOffer() },
      ]);
      return;
    }
    this.#view.showNotice(`This cell changed since your edit of ${when}.`, [
      { label: 'Restore my edit', run: () => this.#takeEdit(text, true) },
      { label: 'Discard', run: () => this.#discardOffer() },
    ]);
  }

  /** An edit the browser's storage gave back damaged (`raw`): what can be recovered of it is offered, never run. */
  #offerDamaged(raw: string): void {
    const offer = (text: string) =>
      this.#view.showNotice('Your saved edit of this cell came back damaged from the browser’s storage, so the original runs. What could be recovered of it is kept for you:', [
        { label: 'Edit it', run: () => this.#takeEdit(text, false) },
        { label: 'Discard', run: () => this.#closeOffer() },
      ]);
    // Offline, the raw text is still the reader's.
    void import('./recovery.ts').then((m) => offer(m.recoverText(raw)), () => offer(raw));
  }

  /** The reader takes an offered edit: into the editor, and run it or not. */
  #takeEdit(source: string, run: boolean): void {
    this.#closeOffer();
    this.#showDraft(source);
    if (run) void this.run();
    else this.#drafts.changed(source);
  }

  #discardOffer(): void {
    this.#closeOffer();
    this.#drafts.ran(this.#view.originalSource);
  }

  #offerTheirs(theirs: SavedEdit, message: string): void {
    this.#view.showNotice(message, [
      {
        label: 'Use theirs',
        run: () => {
          this.#view.clearNotice();
          this.#drafts.adopt(theirs);
          this.#showDraft(theirs.draft);
          if (theirs.ran !== null) void this.#apply(theirs.ran);
          else this.#defineOriginal();
        },
      },
      {
        label: 'Keep mine',
        run: () => {
          this.#view.clearNotice();
          this.#drafts.keepMine(this.#editor?.source ?? this.#draft);
        },
      },
    ]);
  }

  #saveProblem(problem: SaveProblem): void {
    if (problem.reason === 'conflict') {
      this.#offerTheirs(problem.theirs, `This cell was changed in another tab since you loaded it (${new Date(problem.theirs.savedAt).toLocaleTimeString()}); your text is not saved yet.`);
      return;
    }
    const why = problem.reason === 'full' ? 'the browser’s storage for this site is full' : 'the browser does not let this page keep data';
    this.#view.showNotice(`Your edit cannot be kept: ${why}. It will be lost when you leave the page.`, [
      { label: 'Download my edits', run: () => this.#hooks.downloadEdits() },
    ]);
  }

  /**
   * Marks the reader's code as running until the page has shown it survived:
   * if the page freezes in it (or is closed while frozen), the next load runs
   * the original and offers the edit instead of freezing again.
   */
  #watchSurvival(): void {
    if (this.#survival) clearTimeout(this.#survival.timer);
    this.#drafts.markRunning();
    this.#survival = { result: false, timer: setTimeout(() => this.#survived(), SURVIVAL_WITHOUT_RESULT_MS) };
  }

  /** The cell showed a value or an error: if the page is still responsive a moment later, it survived. */
  #resulted(): void {
    const { restored, intact } = this.#hooks.checkPage();
    if (restored.length) {
      this.#view.setError('later', `RuntimeError: this cell changed ${restored.join(', ')}, which every cell and widget relies on; the change was undone.`);
    }
    if (!intact) {
      // The mark stays: the next load offers this edit instead of running it, and the page says so now.
      if (this.#survival) clearTimeout(this.#survival.timer);
      this.#survival = null;
      this.#drafts.markRunning();
      this.#hooks.pageBroken(this.name ? `cell ${this.name}` : 'a cell');
      return;
    }
    const survival = this.#survival;
    if (!survival || survival.result) return;
    clearTimeout(survival.timer);
    this.#survival = { result: true, timer: setTimeout(() => this.#survived(), SURVIVAL_MS) };
  }

  #survived(): void {
    this.#survival = null;
    this.#drafts.survived();
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

