/**
 * Hover inside cells: an option's type and comment, a builtin's signature
 * and comment, or the cell that defines a name.
 */
import * as vscode from 'vscode';
import { cellAt, codeStart } from '../analyzer/cell-at.ts';
import { optionsAt } from '../analyzer/catalogue.ts';
import { codeContext } from '../analyzer/code-context.ts';
import { catalogue } from './catalogue-data.ts';
import { cellMarkdown, entryMarkdown, optionMarkdown, ownerLabel } from './builtin-docs.ts';
import type { ChapterIndex } from './chapter-index.ts';

export class CellHover implements vscode.HoverProvider {
  readonly #index: ChapterIndex;

  constructor(index: ChapterIndex) {
    this.#index = index;
  }

  provideHover(document: vscode.TextDocument, position: vscode.Position): vscode.Hover | undefined {
    const analysis = this.#index.analysisOf(document);
    const range = document.getWordRangeAtPosition(position, /[A-Za-z_$][\w$]*/);
    if (!range) return undefined;
    const cell = cellAt(analysis, document.offsetAt(position));
    if (!cell) return undefined;
    const word = document.getText(range);
    const code = codeContext(document.getText().slice(codeStart(analysis, cell), document.offsetAt(range.start)));
    if (code.kind === 'none') return undefined;
    if (code.kind === 'key') {
      const { callee, argument, path } = code.owner;
      const option = optionsAt(catalogue, callee, argument, path).find((o) => o.name === word);
      if (option) return new vscode.Hover(optionMarkdown(option, ownerLabel(callee, path)), range);
    }
    const definer = analysis.cells.find((c) => c.name === word);
    if (definer && definer !== cell) return new vscode.Hover(cellMarkdown(definer), range);
    const entry = catalogue.builtins.find((b) => b.name === word);
    if (entry && !definer) return new vscode.Hover(entryMarkdown(entry), range);
    return undefined;
  }
}
