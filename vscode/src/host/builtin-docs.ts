/**
 * Markdown for the builtins and their options, shared by completion and
 * hover: the signature TypeScript prints, then the book's own comment.
 */
import * as vscode from 'vscode';
import type { CatalogueEntry, CatalogueOption } from '../analyzer/catalogue.ts';
import type { ChapterCell } from '../analyzer/cells.ts';

export function entryMarkdown(entry: CatalogueEntry): vscode.MarkdownString {
  const markdown = new vscode.MarkdownString();
  markdown.appendCodeblock(entry.signature, 'typescript');
  if (entry.doc) markdown.appendMarkdown(`\n${entry.doc}\n`);
  const options = entry.parameters.flatMap((p) => p.options ?? []);
  if (options.length) markdown.appendMarkdown(`\nOptions: ${options.map((o) => `\`${o.name}${o.optional ? '?' : ''}\``).join(', ')}\n`);
  return markdown;
}

export function optionMarkdown(option: CatalogueOption, owner: string): vscode.MarkdownString {
  const markdown = new vscode.MarkdownString();
  markdown.appendCodeblock(`(option of ${owner}) ${option.name}${option.optional ? '?' : ''}: ${option.type}`, 'typescript');
  if (option.doc) markdown.appendMarkdown(`\n${option.doc}\n`);
  if (option.options?.length) markdown.appendMarkdown(`\nOptions: ${option.options.map((o) => `\`${o.name}\``).join(', ')}\n`);
  return markdown;
}

/** A cell, shown by its first lines. */
export function cellMarkdown(cell: ChapterCell): vscode.MarkdownString {
  const markdown = new vscode.MarkdownString(`cell \`${cell.name ?? cell.id}\`, line ${cell.fenceLine + 2}\n`);
  const lines = cell.source.split('\n');
  markdown.appendCodeblock(lines.slice(0, 8).join('\n') + (lines.length > 8 ? '\n…' : ''), 'javascript');
  return markdown;
}

/** How an owner is named in docs: `simulator`, `simulator › timePlot`. */
export function ownerLabel(callee: string, path: readonly string[]): string {
  return [callee, ...path].join(' › ');
}
