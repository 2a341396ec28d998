/**
 * The DOM of one cell, as rendered by site/lib/remark-cells.mjs: reads what the
 * build put there and shows values, errors and notices. No runtime logic.
 */
import { colourCode } from './code-tokens.ts';
import { inspect } from './inspect.ts';
import { markSoon as markScrollable } from './scrollables.ts';
import type { CellSpec } from './spec.ts';

/**
 * `compile`: the reader's text does not parse (the old definition keeps running).
 * `runtime`: the running definition threw, or one of its inputs did.
 * `later`: code of the cell failed after it gave its value (a timer, a handler,
 *   a promise it let go, a request the book blocked).
 */
export type ErrorKind = 'compile' | 'runtime' | 'later';
const ERROR_ORDER: readonly ErrorKind[] = ['compile', 'runtime', 'later'];

/**
 * `waiting`: not started yet (it starts when it comes near the view, or when
 * a started cell reads it); then the runtime's `pending`, `fulfilled` or `rejected`.
 */
export type CellState = 'waiting' | 'pending' | 'fulfilled' | 'rejected';

/** The inspector shows a cell's changing value at most this often. */
const INSPECT_INTERVAL_MS = 250;

/** A cell pending longer than this shows "running…". */
const PENDING_NOTICE_MS = 150;

function part<T extends Element>(root: Element, selector: string): T {
  const found = root.querySelector<T>(selector);
  if (!found) throw new Error(`cell ${root.getAttribute('data-cell')} lacks ${selector}`);
  return found;
}

export class CellView {
  readonly root: HTMLElement;
  readonly id: string;
  /** Hash of the chapter's original source, for telling stale saved edits apart. */
  readonly hash: string;
  /** The chapter's original source, as highlighted by the build. */
  readonly originalSource: string;
  /** The build's parse of the original, or null when the build could not parse it. */
  readonly originalSpec: CellSpec | null;
  /** The build's syntax error for the original, if any. */
  readonly buildError: string | null;

  readonly editorHost: HTMLElement;
  readonly runButton: HTMLButtonElement;
  readonly resetButton: HTMLButtonElement;
  /** "+ Cell", absent in markup from an older build. */
  readonly addButton: HTMLButtonElement | null;
  /** A cell the reader added (its Reset deletes it). */
  readonly added: boolean;
  readonly #output: HTMLElement;
  readonly #error: HTMLElement;
  readonly #notice: HTMLElement;
  readonly #status: HTMLElement;
  /** "running…" or "compiling…" while the cell is pending; null in markup from an older build. */
  readonly #activity: HTMLElement | null;
  #activityTimer: ReturnType<typeof setTimeout> | undefined;
  readonly #errors = new Map<ErrorKind, string>();
  /** When the inspector last showed a value, and the repaint it put off. */
  #inspectedAt = -Infinity;
  #inspectTimer: ReturnType<typeof setTimeout> | undefined;
  /** The build's highlighted code, to put back on Reset before an editor exists. */
  readonly #originalCode: Node | null;

  constructor(root: HTMLElement) {
    this.root = root;
    this.id = root.dataset.cell ?? '';
    this.hash = root.dataset.cellHash ?? '';
    const spec = root.dataset.cellSpec;
    this.originalSpec = spec ? (JSON.parse(spec) as CellSpec) : null;
    this.buildError = root.dataset.cellBuildError ?? null;
    this.editorHost = part(root, '.cell-editor');
    const code = this.editorHost.querySelector('pre.cell-code > code');
    this.originalSource = code?.textContent ?? '';
    this.#originalCode = code?.cloneNode(true) ?? null;
    this.runButton = part(root, '[data-cell-run]');
    this.resetButton = part(root, '[data-cell-reset]');
    this.addButton = root.querySelector('[data-cell-add]');
    this.added = root.hasAttribute('data-cell-added');
    this.#output = part(root, '[data-cell-output]');
    this.#error = part(root, '[data-cell-error]');
    this.#notice = part(root, '[data-cell-notice]');
    this.#status = part(root, '[data-cell-status]');
    this.#activity = root.querySelector('[data-cell-activity]');
  }

  /** The build's `<pre>`, until the editor replaces it. */
  get staticCode(): HTMLPreElement | null {
    return this.editorHost.querySelector('pre.cell-code');
  }

  /** Shows `source` in the static `<pre>` when no editor is mounted yet (highlighted only if it is the original). */
  showStaticSource(source: string): void {
    const code = this.staticCode?.querySelector('code');
    if (!code || code.textContent === source) return;
    if (source === this.originalSource && this.#originalCode) {
      const original = this.#originalCode.cloneNode(true) as Element;
      code.replaceWith(original);
      // Code the build left plain until near the view is shown where the reader is working: coloured now.
      colourCode(original);
    } else code.textContent = source;
  }

  /**
   * The runtime's state of the cell. A cell pending for more than a moment
   * says so ("running…"), so a slow computation never passes for its old
   * result; see also {@link showCompiling}.
   */
  setState(state: CellState): void {
    this.root.dataset.cellState = state;
    clearTimeout(this.#activityTimer);
    if (state === 'pending') this.#activityTimer = setTimeout(() => this.#setActivity('running…'), PENDING_NOTICE_MS);
    else this.#setActivity('');
  }

  /** A model is being compiled for the page (`fraction` done, when known): a pending cell is waiting for it. */
  showCompiling(fraction?: number): void {
    if (this.root.dataset.cellState !== 'pending') return;
    const done = fraction !== undefined && fraction > 0 && fraction < 1 ? ` ${Math.round(fraction * 100)}%` : '';
    this.#setActivity(`compiling…${done}`);
  }

  #setActivity(text: string): void {
    if (this.#activity && this.#activity.textContent !== text) this.#activity.textContent = text;
  }

  /**
   * A DOM node is shown as itself (kept if it is already shown); anything
   * else through the inspector, at most a few times a second: a generator
   * cell's state changes every frame, and a line of numbers rewritten sixty
   * times a second cannot be read. A cell that wants every frame shows a DOM
   * node (html`…`), which is always shown at once.
   */
  showValue(value: unknown, name: string | null): void {
    clearTimeout(this.#inspectTimer);
    this.#inspectTimer = undefined;
    if (value instanceof Node) {
      if (this.#output.firstChild !== value || this.#output.childNodes.length !== 1) this.#output.replaceChildren(value);
      // A wide table or figure makes the output scroll: then it must be reachable by keyboard (checked once it is laid out).
      markScrollable(this.#output);
      return;
    }
    if (value === undefined && !name) {
      this.#output.replaceChildren();
      return;
    }
    const wait = this.#inspectedAt + INSPECT_INTERVAL_MS - performance.now();
    if (wait > 0) {
      this.#inspectTimer = setTimeout(() => this.showValue(value, name), wait);
      return;
    }
    this.#inspectedAt = performance.now();
    this.#output.replaceChildren(inspect(value, name));
    markScrollable(this.#output);
  }

  /**
   * Sets or clears (`null`) one kind of error. A compile error (the text in
   * the editor does not parse) and a runtime error (the running definition
   * failed) can show at once, compile first.
   */
  setError(kind: ErrorKind, message: string | null): void {
    if (message === null) this.#errors.delete(kind);
    else this.#errors.set(kind, message);
    const lines = [...this.#errors].sort(([a], [b]) => ERROR_ORDER.indexOf(a) - ERROR_ORDER.indexOf(b)).map(([k, text]) => {
      const line = document.createElement('div');
      line.className = `cell-error-${k}`;
      line.textContent = text;
      return line;
    });
    this.#error.replaceChildren(...lines);
    this.#error.hidden = lines.length === 0;
  }

  clearOutput(): void {
    clearTimeout(this.#inspectTimer);
    this.#output.replaceChildren();
  }

  /** A one-line notice with buttons, e.g. a saved edit that no longer matches the chapter. */
  showNotice(message: string, actions: ReadonlyArray<{ label: string; run: () => void }>): void {
    const text = document.createElement('span');
    text.textContent = message;
    const buttons = actions.map(({ label, run }) => {
      const button = document.createElement('button');
      button.type = 'button';
      button.className = 'cell-button';
      button.textContent = label;
      button.addEventListener('click', run);
      return button;
    });
    this.#notice.replaceChildren(text, ...buttons);
    this.#notice.hidden = false;
  }

  clearNotice(): void {
    this.#notice.hidden = true;
    this.#notice.replaceChildren();
  }

  /**
   * Marks the cell as differing from the chapter's original (Reset becomes
   * available), and says when the text shown is not the code that runs.
   */
  setEdited(edited: boolean, unrun = false): void {
    this.root.toggleAttribute('data-cell-edited', edited);
    this.root.toggleAttribute('data-cell-unrun', unrun);
    this.resetButton.disabled = !edited && !this.added;
    this.#status.textContent = unrun ? 'not run yet' : edited ? 'edited' : '';
  }

  setBusy(busy: boolean): void {
    this.runButton.disabled = busy;
  }
}
