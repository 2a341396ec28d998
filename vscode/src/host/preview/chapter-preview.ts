/**
 * One chapter's live preview: a webview beside the editor that renders the
 * chapter with the book's own cells and widgets (src/preview/). It follows
 * the document as the author types (debounced; the webview keeps every
 * cell whose code did not change, widgets and all), scrolls with the
 * editor and back, runs cells on request, reads theory checks, and turns
 * the cells' runtime errors into diagnostics on their lines.
 */
import * as vscode from 'vscode';
import type { CellReport, CheckResult, HostMessage, PreviewMessage } from '../../shared/messages.ts';
import type { ChapterIndex } from '../chapter-index.ts';
import { previewHtml } from './html.ts';
import { runtimeDiagnostics } from './runtime-diagnostics.ts';

export const PREVIEW_VIEW_TYPE = 'phasebook.preview';

/** How long typing must pause before the preview renders again. */
const RENDER_DELAY_MS = 300;
/** An editor scroll that follows the preview's is not sent back to it within this time. */
const ECHO_MS = 300;

export class ChapterPreview implements vscode.Disposable {
  readonly document: vscode.TextDocument;
  readonly panel: vscode.WebviewPanel;
  readonly #index: ChapterIndex;
  readonly #diagnostics: vscode.DiagnosticCollection;
  readonly #disposables: vscode.Disposable[] = [];
  readonly #closed = new vscode.EventEmitter<void>();
  readonly #messages = new vscode.EventEmitter<PreviewMessage>();
  /** Messages wait here until the webview's script has started. */
  #queue: HostMessage[] | null = [];
  #timer: ReturnType<typeof setTimeout> | undefined;
  #nextRequest = 1;
  /** Until then, the editor's scrolling is the echo of the preview's and is not sent back. */
  #editorQuietUntil = 0;
  #lastCells: readonly CellReport[] = [];

  readonly onDidClose = this.#closed.event;
  /** Every message from the webview (the extension's API passes it on, for tests). */
  readonly onMessage = this.#messages.event;

  constructor(document: vscode.TextDocument, panel: vscode.WebviewPanel, extensionUri: vscode.Uri, index: ChapterIndex, diagnostics: vscode.DiagnosticCollection) {
    this.document = document;
    this.panel = panel;
    this.#index = index;
    this.#diagnostics = diagnostics;
    panel.webview.options = { enableScripts: true, localResourceRoots: [vscode.Uri.joinPath(extensionUri, 'dist')] };
    panel.webview.html = previewHtml(panel.webview, extensionUri, document.uri);
    this.#disposables.push(
      panel.webview.onDidReceiveMessage((message: PreviewMessage) => this.#receive(message)),
      panel.onDidDispose(() => this.dispose()),
      vscode.workspace.onDidChangeTextDocument((event) => {
        if (event.document === document) this.#scheduleRender();
      }),
      vscode.window.onDidChangeTextEditorVisibleRanges((event) => {
        if (event.textEditor.document === document) this.#editorScrolled(event.visibleRanges);
      }),
      index.onDidChange((uri) => {
        if (uri.toString() === document.uri.toString()) this.#publishRuntimeErrors();
      }),
    );
    this.#render();
  }

  /** Runs one cell again (by id), or every cell, and brings it into view. */
  run(cell: string | null): void {
    this.#flushRender();
    this.#post({ type: 'run', cell });
  }

  /** The theory checks of `cells`, read once each has settled (or `timeoutMs` has passed). */
  checks(cells: readonly string[], timeoutMs: number): Promise<readonly CheckResult[]> {
    this.#flushRender();
    const request = this.#nextRequest++;
    return new Promise((resolve) => {
      const listener = this.#messages.event((message) => {
        if (message.type === 'checks' && message.request === request) {
          listener.dispose();
          resolve(message.results);
        }
      });
      this.#disposables.push(listener);
      this.#post({ type: 'checks', request, cells, timeoutMs });
    });
  }

  dispose(): void {
    this.detach().dispose();
  }

  /**
   * Lets go of the chapter but not of its webview panel, which another
   * chapter's preview may then take over (PreviewManager.forChecks): the
   * preview closes as far as anyone listening can tell, and the panel stays.
   */
  detach(): vscode.WebviewPanel {
    clearTimeout(this.#timer);
    this.#diagnostics.delete(this.document.uri);
    for (const disposable of this.#disposables.splice(0)) disposable.dispose();
    this.#closed.fire();
    this.#closed.dispose();
    this.#messages.dispose();
    return this.panel;
  }

  #post(message: HostMessage): void {
    if (this.#queue) this.#queue.push(message);
    else void this.panel.webview.postMessage(message);
  }

  #scheduleRender(): void {
    clearTimeout(this.#timer);
    this.#timer = setTimeout(() => this.#render(), RENDER_DELAY_MS);
  }

  /** Renders now if a render is waiting, so that a run or a check sees the text as it is. */
  #flushRender(): void {
    if (this.#timer === undefined) return;
    this.#render();
  }

  #render(): void {
    clearTimeout(this.#timer);
    this.#timer = undefined;
    this.#post({ type: 'render', version: this.document.version, text: this.document.getText() });
  }

  #receive(message: PreviewMessage): void {
    if (message.type === 'ready') {
      const queued = this.#queue ?? [];
      this.#queue = null;
      // A webview that reloads (it was moved to another window) starts from the current text.
      if (!queued.some((m) => m.type === 'render')) this.#render();
      for (const m of queued) void this.panel.webview.postMessage(m);
    } else if (message.type === 'cells') {
      this.#lastCells = message.cells;
      this.#publishRuntimeErrors();
    } else if (message.type === 'scrolled') {
      this.#previewScrolled(message.line);
    } else if (message.type === 'open') {
      void this.#showLine(message.line);
    }
    this.#messages.fire(message);
  }

  #publishRuntimeErrors(): void {
    this.#diagnostics.set(this.document.uri, runtimeDiagnostics(this.#lastCells, this.#index.analysisOf(this.document)));
  }

  #editorScrolled(ranges: readonly vscode.Range[]): void {
    // The webview ignores the scroll events of its own following, so only the editor's echo needs care here.
    if (Date.now() < this.#editorQuietUntil || !ranges[0]) return;
    this.#post({ type: 'reveal', line: ranges[0].start.line });
  }

  #previewScrolled(line: number): void {
    const editor = vscode.window.visibleTextEditors.find((e) => e.document === this.document);
    if (!editor) return;
    this.#editorQuietUntil = Date.now() + ECHO_MS;
    const at = new vscode.Position(Math.max(0, Math.floor(line)), 0);
    editor.revealRange(new vscode.Range(at, at), vscode.TextEditorRevealType.AtTop);
  }

  async #showLine(line: number): Promise<void> {
    const at = new vscode.Position(line, 0);
    const editor = await vscode.window.showTextDocument(this.document, { viewColumn: vscode.ViewColumn.One, selection: new vscode.Range(at, at) });
    editor.revealRange(new vscode.Range(at, at), vscode.TextEditorRevealType.InCenterIfOutsideViewport);
  }
}
