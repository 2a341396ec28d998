/** "Run cell" and "Run all" above each cell's opening fence; both run in the chapter's preview. */
import * as vscode from 'vscode';
import type { ChapterIndex } from './chapter-index.ts';

export const RUN_CELL = 'phasebook.runCell';
export const RUN_ALL = 'phasebook.runAll';

export class CellLenses implements vscode.CodeLensProvider {
  readonly #index: ChapterIndex;
  readonly #changed = new vscode.EventEmitter<void>();
  readonly onDidChangeCodeLenses = this.#changed.event;

  constructor(index: ChapterIndex) {
    this.#index = index;
    index.onDidChange(() => this.#changed.fire());
  }

  provideCodeLenses(document: vscode.TextDocument): vscode.CodeLens[] {
    return this.#index.analysisOf(document).cells.flatMap((cell) => {
      const range = new vscode.Range(cell.fenceLine, 0, cell.fenceLine, 0);
      return [
        new vscode.CodeLens(range, { title: '$(play) Run cell', command: RUN_CELL, arguments: [document.uri, cell.id], tooltip: `Run ${cell.name ?? 'this cell'} in the preview` }),
        new vscode.CodeLens(range, { title: 'Run all', command: RUN_ALL, arguments: [document.uri], tooltip: 'Run every cell of the chapter in the preview' }),
      ];
    });
  }
}
