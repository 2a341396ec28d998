/**
 * Completion inside cells: at a key of an options object passed to a
 * builtin, that builtin's options (from its TypeScript type, nested ones
 * included); at a place for a name, the chapter's other cells, the book's
 * builtins and the page's other names (Math's, `width`, `invalidation` …).
 */
import * as vscode from 'vscode';
import { cellAt, codeStart } from '../analyzer/cell-at.ts';
import { optionsAt } from '../analyzer/catalogue.ts';
import { codeContext } from '../analyzer/code-context.ts';
import { BROWSER_GLOBALS, JAVASCRIPT_GLOBALS } from '../../../cells/index.ts';
import { builtins, catalogue } from './catalogue-data.ts';
import { cellMarkdown, entryMarkdown, optionMarkdown, ownerLabel } from './builtin-docs.ts';
import type { ChapterIndex } from './chapter-index.ts';

const catalogueNames = new Set(catalogue.builtins.map((b) => b.name));
const globals = new Set<string>([...JAVASCRIPT_GLOBALS, ...BROWSER_GLOBALS]);
/** Builtins other than the catalogue and plain JavaScript: Math's members, html, width, now, invalidation … */
const pageNames = [...builtins].filter((name) => !catalogueNames.has(name) && !globals.has(name));

export const TRIGGER_CHARACTERS = ['{', ','];

export class CellCompletion implements vscode.CompletionItemProvider {
  readonly #index: ChapterIndex;

  constructor(index: ChapterIndex) {
    this.#index = index;
  }

  provideCompletionItems(document: vscode.TextDocument, position: vscode.Position, _token: vscode.CancellationToken, context: vscode.CompletionContext): vscode.CompletionItem[] {
    const analysis = this.#index.analysisOf(document);
    const offset = document.offsetAt(position);
    const cell = cellAt(analysis, offset);
    if (!cell) return [];
    const code = codeContext(document.getText().slice(codeStart(analysis, cell), offset));
    if (code.kind === 'key') {
      const { callee, argument, path } = code.owner;
      return optionsAt(catalogue, callee, argument, path)
        .filter((option) => !code.present.includes(option.name))
        .map((option) => {
          const item = new vscode.CompletionItem({ label: option.name, description: option.type }, vscode.CompletionItemKind.Property);
          item.detail = `${option.optional ? 'optional' : 'required'} option of ${ownerLabel(callee, path)}`;
          item.documentation = optionMarkdown(option, ownerLabel(callee, path));
          // Required options first, then the others, each in the type's order.
          item.sortText = `${option.optional ? 1 : 0}`;
          return item;
        });
    }
    // Typing `{` or `,` asks for options only; names come as the author types them.
    if (code.kind !== 'name' || context.triggerKind === vscode.CompletionTriggerKind.TriggerCharacter) return [];
    const items: vscode.CompletionItem[] = [];
    for (const other of analysis.cells) {
      if (!other.name || other === cell) continue;
      const item = new vscode.CompletionItem({ label: other.name, description: 'cell' }, vscode.CompletionItemKind.Variable);
      item.detail = `cell, line ${other.fenceLine + 2}`;
      item.documentation = cellMarkdown(other);
      item.sortText = `0${other.name}`;
      items.push(item);
    }
    for (const entry of catalogue.builtins) {
      const kind = entry.kind === 'class' ? vscode.CompletionItemKind.Class : vscode.CompletionItemKind.Function;
      const item = new vscode.CompletionItem({ label: entry.name, description: 'Phasebook' }, kind);
      item.detail = entry.signature;
      item.documentation = entryMarkdown(entry);
      item.sortText = `1${entry.name}`;
      items.push(item);
    }
    for (const name of pageNames) {
      const item = new vscode.CompletionItem(name, vscode.CompletionItemKind.Constant);
      item.detail = name in Math ? `Math.${name}` : 'builtin of the page';
      item.sortText = `2${name}`;
      items.push(item);
    }
    return items;
  }
}
