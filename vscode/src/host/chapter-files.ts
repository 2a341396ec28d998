/**
 * Which files are chapters. The book makes a chapter of every `.mdx` file
 * under the project's top-level `content/` folder (site/content.config.ts),
 * and takes new chapters from its top-level `templates/chapter.mdx`. In a
 * workspace, a book is therefore a workspace folder's own `content/`: a
 * `content/` folder deeper down (the extension's test fixtures in a fork,
 * a dependency's files) is not the book, and its files are not chapters.
 * Each workspace folder of a multi-root workspace may be a book.
 *
 * Everything here goes through the workspace's file system (no file
 * search), so that it works alike in the desktop and in the web hosts.
 */
import * as vscode from 'vscode';

/** A book's chapters, relative to its workspace folder (the glob of site/content.config.ts, under content/). */
export const CHAPTERS_IN_FOLDER = 'content/**/*.mdx';
/** The book's template, relative to its workspace folder. */
export const TEMPLATE_IN_FOLDER = 'templates/chapter.mdx';

/** A workspace folder's `content/`, the book's chapters' folder. */
export function contentOf(folder: vscode.WorkspaceFolder): vscode.Uri {
  return vscode.Uri.joinPath(folder.uri, 'content');
}

/** The book of a workspace folder as the index names it: its content/ folder's URI, ending in `/`. */
export function bookOfFolder(folder: vscode.WorkspaceFolder): string {
  const content = contentOf(folder);
  return content.with({ path: `${content.path}/` }).toString();
}

/** The book a chapter belongs to (its workspace folder's content/), or null when the file is not a chapter. */
export function bookOf(uri: vscode.Uri): string | null {
  const folder = vscode.workspace.getWorkspaceFolder(uri);
  if (!folder || !uri.path.endsWith('.mdx')) return null;
  return uri.path.startsWith(`${contentOf(folder).path}/`) ? bookOfFolder(folder) : null;
}

/** Every `.mdx` file under a folder, at any depth; none when the folder does not exist. */
export async function mdxFilesUnder(folder: vscode.Uri): Promise<vscode.Uri[]> {
  let entries: [string, vscode.FileType][];
  try {
    entries = await vscode.workspace.fs.readDirectory(folder);
  } catch {
    return [];
  }
  const found = await Promise.all(
    entries.map(async ([name, type]) => {
      const uri = vscode.Uri.joinPath(folder, name);
      if (type & vscode.FileType.Directory) return mdxFilesUnder(uri);
      return type & vscode.FileType.File && name.endsWith('.mdx') ? [uri] : [];
    }),
  );
  return found.flat();
}

/** An MDX file open in an editor: a chapter, the template, or a draft kept elsewhere. */
export function isMdx(document: vscode.TextDocument): boolean {
  return document.languageId === 'mdx' || document.uri.path.endsWith('.mdx');
}
