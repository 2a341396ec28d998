/**
 * "Phasebook: New chapter": copies the book's template
 * (templates/chapter.mdx) into its content/ folder under a name made from
 * the title the author gives, with the next order no chapter uses, and
 * opens it. Tests (and other extensions) may pass the title as an argument.
 */
import * as vscode from 'vscode';
import { chapterFromTemplate, fileNameFor, nextFreeOrder } from '../analyzer/new-chapter.ts';
import { EXCLUDE_GLOB } from './chapter-files.ts';
import type { ChapterIndex } from './chapter-index.ts';

export const NEW_CHAPTER = 'phasebook.newChapter';
const TEMPLATE_GLOB = '**/templates/chapter.mdx';

/** The template of the book the author is working in: beside the active file's book if there are several. */
async function findTemplate(): Promise<vscode.Uri | undefined> {
  const templates = await vscode.workspace.findFiles(TEMPLATE_GLOB, EXCLUDE_GLOB, 20);
  const active = vscode.window.activeTextEditor?.document.uri.toString() ?? '';
  const root = (t: vscode.Uri) => t.toString().replace(/templates\/chapter\.mdx$/, '');
  return templates.find((t) => active.startsWith(root(t))) ?? templates[0];
}

export async function newChapter(index: ChapterIndex, args?: { title?: string }): Promise<vscode.Uri | undefined> {
  const template = await findTemplate();
  if (!template) {
    void vscode.window.showErrorMessage('Phasebook: no templates/chapter.mdx in this workspace, so there is nothing to copy a chapter from.');
    return undefined;
  }
  const title = args?.title ?? (await vscode.window.showInputBox({ prompt: 'Title of the new chapter', placeHolder: 'The pendulum', validateInput: (v) => (v.trim() ? null : 'A chapter needs a title') }));
  if (!title?.trim()) return undefined;
  const content = vscode.Uri.joinPath(template, '..', '..', 'content');
  const target = vscode.Uri.joinPath(content, fileNameFor(title.trim()));
  try {
    await vscode.workspace.fs.stat(target);
    void vscode.window.showErrorMessage(`Phasebook: ${vscode.workspace.asRelativePath(target)} exists already; choose another title.`);
    return undefined;
  } catch {
    // No such file: the name is free.
  }
  await index.ready;
  const book = content.toString().replace(/\/?$/, '/');
  const orders = index.chapters().flatMap((c) => (c.book === book && c.analysis.frontMatter.order ? [c.analysis.frontMatter.order.value] : []));
  const text = new TextDecoder().decode(await vscode.workspace.fs.readFile(template));
  let chapter: string;
  try {
    chapter = chapterFromTemplate(text, title.trim(), nextFreeOrder(orders));
  } catch (error) {
    void vscode.window.showErrorMessage(`Phasebook: ${vscode.workspace.asRelativePath(template)}: ${(error as Error).message}`);
    return undefined;
  }
  await vscode.workspace.fs.writeFile(target, new TextEncoder().encode(chapter));
  await vscode.window.showTextDocument(target);
  return target;
}
