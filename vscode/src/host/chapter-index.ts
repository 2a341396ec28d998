/**
 * Every chapter of the workspace, analysed, with its diagnostics published:
 * chapters read from each workspace folder's content/ at start-up (and as
 * files and folders come and go), an open
 * chapter from its editor's text as the author types (debounced), and any
 * other open MDX file (the template, a draft) on its own. Duplicate orders
 * are checked across the chapters of each book.
 */
import * as vscode from 'vscode';
import { analyzeChapter, type ChapterAnalysis } from '../analyzer/analyze.ts';
import { duplicateOrders, type ChapterOrder } from '../analyzer/orders.ts';
import type { Problem } from '../analyzer/problems.ts';
import { builtins } from './catalogue-data.ts';
import { bookOf, CHAPTERS_IN_FOLDER, contentOf, isMdx, mdxFilesUnder } from './chapter-files.ts';
import { toDiagnostic } from './problem-diagnostics.ts';

/** How long typing must pause before a chapter is analysed again. */
const TYPING_DELAY_MS = 250;

/**
 * The analysis of a text, never an exception: a chapter the analyzer cannot
 * take (a bug of ours, not of the chapter) gets one problem saying so, and
 * the other chapters and features carry on.
 */
function safeAnalysis(text: string): ChapterAnalysis {
  try {
    return analyzeChapter(text, builtins);
  } catch (error) {
    const empty = analyzeChapter('', builtins);
    const message = `Phasebook could not analyse this file: ${(error as Error)?.message ?? String(error)}`;
    return { ...empty, problems: [{ code: 'mdx-syntax', severity: 'error', message, start: 0, end: 0 }] };
  }
}

interface Entry {
  readonly uri: vscode.Uri;
  /** The book (content/ folder) of a chapter; null for another MDX file. */
  readonly book: string | null;
  readonly analysis: ChapterAnalysis;
  /** The editor's version the analysis is of; null when it was read from disk. */
  readonly version: number | null;
}

export class ChapterIndex implements vscode.Disposable {
  readonly #entries = new Map<string, Entry>();
  readonly #collection: vscode.DiagnosticCollection;
  readonly #timers = new Map<string, ReturnType<typeof setTimeout>>();
  readonly #changed = new vscode.EventEmitter<vscode.Uri>();
  readonly #disposables: vscode.Disposable[] = [];
  /** A watcher on each workspace folder's chapters, by the folder's URI. */
  readonly #watchers = new Map<string, vscode.FileSystemWatcher>();
  /** Resolves once the workspace's chapters have been read for the first time. */
  readonly ready: Promise<void>;

  /** Fires after a file's analysis (and diagnostics) changed. */
  readonly onDidChange = this.#changed.event;

  constructor(collection: vscode.DiagnosticCollection) {
    this.#collection = collection;
    this.#disposables.push(
      this.#changed,
      vscode.workspace.onDidChangeWorkspaceFolders((event) => void this.#foldersChanged(event)),
      vscode.workspace.onDidOpenTextDocument((document) => this.#fromDocument(document)),
      vscode.workspace.onDidChangeTextDocument((event) => this.#typed(event.document)),
      vscode.workspace.onDidCloseTextDocument((document) => this.#closed(document)),
    );
    this.ready = this.#scan();
  }

  /** The analysis of an open document's current text, made now if the last one is older. */
  analysisOf(document: vscode.TextDocument): ChapterAnalysis {
    const known = this.#entries.get(document.uri.toString());
    if (known && known.version === document.version) return known.analysis;
    return this.#set(document.uri, safeAnalysis(document.getText()), document.version).analysis;
  }

  /** The analysis of a file the index knows (a chapter, or an open MDX file). */
  known(uri: vscode.Uri): ChapterAnalysis | undefined {
    return this.#entries.get(uri.toString())?.analysis;
  }

  /** Every chapter of every book in the workspace. */
  chapters(): { uri: vscode.Uri; book: string; analysis: ChapterAnalysis }[] {
    return [...this.#entries.values()].flatMap((e) => (e.book ? [{ uri: e.uri, book: e.book, analysis: e.analysis }] : []));
  }

  dispose(): void {
    for (const timer of this.#timers.values()) clearTimeout(timer);
    for (const watcher of this.#watchers.values()) watcher.dispose();
    for (const disposable of this.#disposables) disposable.dispose();
  }

  async #scan(): Promise<void> {
    for (const document of vscode.workspace.textDocuments) this.#fromDocument(document, false);
    await Promise.all((vscode.workspace.workspaceFolders ?? []).map((folder) => this.#readFolder(folder)));
    this.#publish();
  }

  /** Reads a workspace folder's chapters (its content/, by the file system: no file search) and watches them. */
  async #readFolder(folder: vscode.WorkspaceFolder): Promise<void> {
    const key = folder.uri.toString();
    if (!this.#watchers.has(key)) {
      const watcher = vscode.workspace.createFileSystemWatcher(new vscode.RelativePattern(folder, CHAPTERS_IN_FOLDER));
      watcher.onDidCreate((uri) => void this.#readFromDisk(uri));
      watcher.onDidChange((uri) => void this.#readFromDisk(uri));
      watcher.onDidDelete((uri) => this.#remove(uri));
      this.#watchers.set(key, watcher);
    }
    const uris = await mdxFilesUnder(contentOf(folder));
    await Promise.all(uris.map((uri) => this.#readFromDisk(uri, false)));
  }

  async #foldersChanged(event: vscode.WorkspaceFoldersChangeEvent): Promise<void> {
    for (const folder of event.removed) {
      this.#watchers.get(folder.uri.toString())?.dispose();
      this.#watchers.delete(folder.uri.toString());
      const inside = `${folder.uri.toString().replace(/\/$/, '')}/`;
      for (const entry of [...this.#entries.values()]) if (entry.uri.toString().startsWith(inside)) this.#remove(entry.uri);
    }
    await Promise.all(event.added.map((folder) => this.#readFolder(folder)));
    this.#publish();
  }

  #fromDocument(document: vscode.TextDocument, publish = true): void {
    if (!isMdx(document) || document.uri.scheme === 'git') return;
    this.analysisOf(document);
    if (publish) this.#publish(document.uri);
  }

  #typed(document: vscode.TextDocument): void {
    if (!isMdx(document)) return;
    const key = document.uri.toString();
    clearTimeout(this.#timers.get(key));
    this.#timers.set(key, setTimeout(() => {
      this.#timers.delete(key);
      this.#fromDocument(document);
    }, TYPING_DELAY_MS));
  }

  /** A closed chapter goes back to its file's text (its edits may have been discarded); another MDX file is forgotten. */
  #closed(document: vscode.TextDocument): void {
    if (!isMdx(document)) return;
    if (bookOf(document.uri)) void this.#readFromDisk(document.uri);
    else this.#remove(document.uri);
  }

  async #readFromDisk(uri: vscode.Uri, publish = true): Promise<void> {
    if (!bookOf(uri)) return;
    // An open document is the truth while it is open.
    if (vscode.workspace.textDocuments.some((d) => d.uri.toString() === uri.toString())) return;
    let text: string;
    try {
      text = new TextDecoder().decode(await vscode.workspace.fs.readFile(uri));
    } catch {
      this.#remove(uri);
      return;
    }
    this.#set(uri, safeAnalysis(text), null);
    if (publish) this.#publish(uri);
  }

  #set(uri: vscode.Uri, analysis: ChapterAnalysis, version: number | null): Entry {
    const entry = { uri, book: bookOf(uri), analysis, version };
    this.#entries.set(uri.toString(), entry);
    return entry;
  }

  #remove(uri: vscode.Uri): void {
    if (!this.#entries.delete(uri.toString())) return;
    this.#collection.delete(uri);
    this.#publish(uri);
  }

  /**
   * Publishes diagnostics: of `changed` (or every file), and of every
   * chapter of its book, whose duplicate-order problems may have changed.
   */
  #publish(changed?: vscode.Uri): void {
    const book = changed ? bookOf(changed) : null;
    const entries = [...this.#entries.values()];
    const books = new Map<string, ChapterOrder[]>();
    for (const e of entries) {
      const order = e.analysis.frontMatter.order;
      if (e.book && order) books.set(e.book, [...(books.get(e.book) ?? []), { file: e.uri.toString(), ...order }]);
    }
    const orders = new Map<string, Problem[]>();
    for (const chapters of books.values()) for (const [file, problems] of duplicateOrders(chapters)) orders.set(file, problems);
    const linesOf = (file: string) => this.#entries.get(file)?.analysis.lines;
    for (const entry of entries) {
      const key = entry.uri.toString();
      if (changed && key !== changed.toString() && (!book || entry.book !== book)) continue;
      const problems = [...entry.analysis.problems, ...(orders.get(key) ?? [])];
      this.#collection.set(entry.uri, problems.map((p) => toDiagnostic(p, entry.uri, entry.analysis.lines, linesOf)));
      this.#changed.fire(entry.uri);
    }
  }
}
