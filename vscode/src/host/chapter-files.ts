/**
 * Which files are chapters. The book makes a chapter of every `.mdx` file
 * under its top-level `content/` folder (site/content.config.ts); in a
 * workspace, any `content/` folder counts, and the chapters of one folder
 * form one book, whose orders must differ.
 */
import * as vscode from 'vscode';

/** Where chapters are searched for at start-up and watched. */
export const CHAPTER_GLOB = '**/content/**/*.mdx';
export const EXCLUDE_GLOB = '**/node_modules/**';

const CHAPTER_PATH = /^(.*\/content\/)(?:.*\/)?[^/]+\.mdx$/;

/** The book a chapter belongs to (its `content/` folder), or null when the file is not a chapter. */
export function bookOf(uri: vscode.Uri): string | null {
  const match = CHAPTER_PATH.exec(uri.path);
  if (!match || match[1].includes('/node_modules/')) return null;
  return uri.with({ path: match[1], query: '', fragment: '' }).toString();
}

/** An MDX file open in an editor: a chapter, the template, or a draft kept elsewhere. */
export function isMdx(document: vscode.TextDocument): boolean {
  return document.languageId === 'mdx' || document.uri.path.endsWith('.mdx');
}
