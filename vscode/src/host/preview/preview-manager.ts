/**
 * The open previews, one per chapter: opens one beside the editor (or
 * reuses it), and gives the commands and the Test Explorer the preview a
 * chapter's cells run in.
 */
import * as vscode from 'vscode';
import type { ChapterIndex } from '../chapter-index.ts';
import { ChapterPreview, PREVIEW_VIEW_TYPE } from './chapter-preview.ts';

const titleOf = (uri: vscode.Uri) => `Preview ${uri.path.slice(uri.path.lastIndexOf('/') + 1)}`;

export class PreviewManager implements vscode.Disposable {
  readonly #previews = new Map<string, ChapterPreview>();
  readonly #extensionUri: vscode.Uri;
  readonly #index: ChapterIndex;
  readonly #diagnostics: vscode.DiagnosticCollection;
  readonly #opened = new vscode.EventEmitter<ChapterPreview>();
  /** The preview test runs opened for themselves (see {@link forChecks}). */
  #forChecks: ChapterPreview | undefined;

  /** Fires when a preview opens. */
  readonly onDidOpen = this.#opened.event;

  constructor(extensionUri: vscode.Uri, index: ChapterIndex, diagnostics: vscode.DiagnosticCollection) {
    this.#extensionUri = extensionUri;
    this.#index = index;
    this.#diagnostics = diagnostics;
  }

  /** The preview in the active editor group's foreground, if any. */
  active(): ChapterPreview | undefined {
    return [...this.#previews.values()].find((preview) => preview.panel.active);
  }

  get(uri: vscode.Uri): ChapterPreview | undefined {
    return this.#previews.get(uri.toString());
  }

  /** The chapter's preview, opened beside the active editor if it is not open; `focus` brings it forward. */
  async open(uri: vscode.Uri, focus = true): Promise<ChapterPreview> {
    const preview = await this.#open(uri, focus);
    // A preview asked for (by the author, a command) is theirs from now on: test runs no longer move it.
    if (preview === this.#forChecks) this.#forChecks = undefined;
    return preview;
  }

  /**
   * The preview to run a chapter's theory checks in: the chapter's own when
   * it is open (it shows what the author sees, unsaved edits and all); else
   * the one preview that runs of the tests keep for themselves, in the
   * background, moved to this chapter; else that preview, opened now. A run
   * of every test of the workspace thus opens one preview, not one per chapter.
   */
  async forChecks(uri: vscode.Uri): Promise<ChapterPreview> {
    const own = this.get(uri);
    if (own) return own;
    const spare = this.#forChecks;
    this.#forChecks = spare && this.get(spare.document.uri) === spare ? await this.#move(spare, uri) : await this.#open(uri, false);
    return this.#forChecks;
  }

  async #open(uri: vscode.Uri, focus: boolean): Promise<ChapterPreview> {
    // The preview runs the chapter's cells, which are code: not in a workspace the user has not trusted.
    if (!vscode.workspace.isTrusted) throw new Error('the preview runs the chapter’s code, so it opens only in a trusted workspace');
    const known = this.get(uri);
    if (known) {
      if (focus) known.panel.reveal(undefined, true);
      return known;
    }
    const document = await vscode.workspace.openTextDocument(uri);
    const panel = vscode.window.createWebviewPanel(PREVIEW_VIEW_TYPE, titleOf(uri), { viewColumn: vscode.ViewColumn.Beside, preserveFocus: true }, {
      enableScripts: true,
      // Widgets keep running (and their state) while the preview is behind another tab.
      retainContextWhenHidden: true,
      localResourceRoots: [vscode.Uri.joinPath(this.#extensionUri, 'dist')],
    });
    return this.#adopt(document, panel);
  }

  /** The panel of `preview`, which shows another chapter, now showing this one (its page loads afresh). */
  async #move(preview: ChapterPreview, uri: vscode.Uri): Promise<ChapterPreview> {
    const document = await vscode.workspace.openTextDocument(uri);
    const panel = preview.detach();
    panel.title = titleOf(uri);
    return this.#adopt(document, panel);
  }

  /**
   * A preview VS Code restores after a reload (registered as the webview
   * panel serializer): the webview kept its chapter's URI in its state.
   */
  async revive(panel: vscode.WebviewPanel, state: unknown): Promise<void> {
    const uri = typeof state === 'object' && state !== null && typeof (state as { uri?: unknown }).uri === 'string' ? (state as { uri: string }).uri : null;
    if (!uri || !vscode.workspace.isTrusted || this.get(vscode.Uri.parse(uri))) {
      panel.dispose();
      return;
    }
    try {
      this.#adopt(await vscode.workspace.openTextDocument(vscode.Uri.parse(uri)), panel);
    } catch {
      // The chapter is gone (deleted, renamed): its old preview goes too.
      panel.dispose();
    }
  }

  #adopt(document: vscode.TextDocument, panel: vscode.WebviewPanel): ChapterPreview {
    const key = document.uri.toString();
    const preview = new ChapterPreview(document, panel, this.#extensionUri, this.#index, this.#diagnostics);
    this.#previews.set(key, preview);
    preview.onDidClose(() => this.#previews.delete(key));
    this.#opened.fire(preview);
    return preview;
  }

  dispose(): void {
    for (const preview of [...this.#previews.values()]) preview.dispose();
    this.#opened.dispose();
  }
}
