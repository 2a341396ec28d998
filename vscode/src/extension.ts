/**
 * Phasebook for VS Code: write and preview the book's chapters. One bundle
 * for the desktop (`main`) and the web (`browser`: github.dev,
 * vscode.dev), with no Node API, so both run the same code.
 *
 * It returns an API, used by its in-host tests and open to other
 * extensions: the chapter index, the previews and the theory checks.
 */
import * as vscode from 'vscode';
import { ChapterIndex } from './host/chapter-index.ts';
import { CellLenses, RUN_ALL, RUN_CELL } from './host/code-lens.ts';
import { CellCompletion, TRIGGER_CHARACTERS } from './host/completion.ts';
import { CellHover } from './host/hover.ts';
import { NEW_CHAPTER, newChapter } from './host/new-chapter-command.ts';
import { PREVIEW_VIEW_TYPE } from './host/preview/chapter-preview.ts';
import { PreviewManager } from './host/preview/preview-manager.ts';
import { TheoryTests } from './host/theory-tests.ts';
import { isMdx } from './host/chapter-files.ts';

const MDX: vscode.DocumentSelector = [{ language: 'mdx' }, { pattern: '**/*.mdx' }];

export interface PhasebookApi {
  readonly index: ChapterIndex;
  readonly previews: PreviewManager;
  readonly theoryTests: TheoryTests;
}

/** The chapter a command acts on: the one it names, else the active editor's, else the active preview's. */
function targetOf(uri: unknown, previews: PreviewManager): vscode.Uri | undefined {
  if (uri instanceof vscode.Uri) return uri;
  const editor = vscode.window.activeTextEditor;
  if (editor && isMdx(editor.document)) return editor.document.uri;
  return previews.active()?.document.uri;
}

export function activate(context: vscode.ExtensionContext): PhasebookApi {
  const diagnostics = vscode.languages.createDiagnosticCollection('phasebook');
  const runtimeDiagnostics = vscode.languages.createDiagnosticCollection('phasebook-preview');
  const index = new ChapterIndex(diagnostics);
  const previews = new PreviewManager(context.extensionUri, index, runtimeDiagnostics);
  const theoryTests = new TheoryTests(index, previews);
  /** Opens the chapter's preview (brought forward when `focus`), saying why when it cannot. */
  const preview = async (uri: unknown, focus: boolean) => {
    const target = targetOf(uri, previews);
    if (!target) return undefined;
    try {
      return await previews.open(target, focus);
    } catch (error) {
      void vscode.window.showWarningMessage(`Phasebook: ${(error as Error).message}.`);
      return undefined;
    }
  };
  const run = async (uri: unknown, cell: string | null) => (await preview(uri, false))?.run(cell);

  context.subscriptions.push(
    diagnostics,
    runtimeDiagnostics,
    index,
    previews,
    theoryTests,
    vscode.languages.registerCodeLensProvider(MDX, new CellLenses(index)),
    vscode.languages.registerCompletionItemProvider(MDX, new CellCompletion(index), ...TRIGGER_CHARACTERS),
    vscode.languages.registerHoverProvider(MDX, new CellHover(index)),
    vscode.commands.registerCommand('phasebook.openPreview', async (uri?: unknown) => void (await preview(uri, true))),
    vscode.commands.registerCommand(RUN_CELL, (uri: unknown, cell: string) => run(uri, cell)),
    vscode.commands.registerCommand(RUN_ALL, (uri: unknown) => run(uri, null)),
    vscode.window.registerWebviewPanelSerializer(PREVIEW_VIEW_TYPE, { deserializeWebviewPanel: (panel, state) => previews.revive(panel, state) }),
    vscode.commands.registerCommand(NEW_CHAPTER, (args?: { title?: string }) => newChapter(index, args)),
  );
  return { index, previews, theoryTests };
}

export function deactivate(): void {}
