/**
 * "Phasebook: New chapter": copies the book's template
 * (templates/chapter.mdx) into its content/ folder under a name made from
 * the title the author gives, with the next order no chapter uses, and
 * opens it. Tests (and other extensions) may pass the title as an argument.
 *
 * The book is a workspace folder (chapter-files.ts): the template is read
 * from the folder's root through the workspace's file system, never found
 * by file search, which VS Code for the web may not offer.
 */
import * as vscode from 'vscode';
import { chapterFromTemplate, fileNameFor, nextFreeOrder } from '../analyzer/new-chapter.ts';
import { bookOfFolder, contentOf, TEMPLATE_IN_FOLDER } from './chapter-files.ts';
import type { ChapterIndex } from './chapter-index.ts';

export const NEW_CHAPTER = 'phasebook.newChapter';

async function exists(uri: vscode.Uri): Promise<boolean> {
  try {
    await vscode.workspace.fs.stat(uri);
    return true;
  } catch {
    return false;
  }
}

/** The workspace folder of the book the author is working in: the active file's if it has a template, else the first that has one. */
async function findBook(): Promise<{ folder: vscode.WorkspaceFolder; template: vscode.Uri } | undefined> {
  const folders = vscode.workspace.workspaceFolders ?? [];
  const active = vscode.window.activeTextEditor?.document.uri;
  const activeFolder = active && vscode.workspace.getWorkspaceFolder(active);
  const ordered = activeFolder ? [activeFolder, ...folders.filter((f) => f !== activeFolder)] : folders;
  for (const folder of ordered) {
    const template = vscode.Uri.joinPath(folder.uri, TEMPLATE_IN_FOLDER);
    if (await exists(template)) return { folder, template };
  }
  return undefined;
}

export async function newChapter(index: ChapterIndex, args?: { title?: string }): Promise<vscode.Uri | undefined> {
  const book = await findBook();
  if (!book) {
    void vscode.window.showErrorMessage(`Phasebook: no workspace folder has ${TEMPLATE_IN_FOLDER}, so there is nothing to copy a chapter from.`);
    return undefined;
  }
  const { folder, template } = book;
  const title = args?.title ?? (await vscode.window.showInputBox({ prompt: 'Title of the new chapter', placeHolder: 'The pendulum', validateInput: (v) => (v.trim() ? null : 'A chapter needs a title') }));
  if (!title?.trim()) return undefined;
  const target = vscode.Uri.joinPath(contentOf(folder), fileNameFor(title.trim()));
  if (await exists(target)) {
    void vscode.window.showErrorMessage(`Phasebook: ${vscode.workspace.asRelativePath(target)} exists already; choose another title.`);
    return undefined;
  }
  await index.ready;
  const orders = index.chapters().flatMap((c) => (c.book === bookOfFolder(folder) && c.analysis.frontMatter.order ? [c.analysis.frontMatter.order.value] : []));
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
