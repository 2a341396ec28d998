/**
 * Loads the heavy halves of the cell machinery only when they are needed:
 * the editor (CodeMirror, ~130 kB gzip) on the first interaction with a cell
 * (hover fetches it, focus mounts it), the parser (acorn, ~40 kB gzip) on
 * the first Run of changed source. Nothing of either loads before the reader
 * does something: a page that is only read never pays for them.
 */

import { explainLoadFailure } from './load-failure.ts';

let editorModule: Promise<typeof import('./editor.ts')> | null = null;
let parserModule: Promise<typeof import('./cell-source.ts')> | null = null;

export function loadEditor(): Promise<typeof import('./editor.ts')> {
  return (editorModule ??= import('./editor.ts').catch((error: unknown) => {
    // The next attempt fetches again: the connection may be back.
    editorModule = null;
    throw explainLoadFailure(error, 'The editor');
  }));
}

export function loadParser(): Promise<typeof import('./cell-source.ts')> {
  return (parserModule ??= import('./cell-source.ts').catch((error: unknown) => {
    parserModule = null;
    throw explainLoadFailure(error, 'The code that reads an edited cell');
  }));
}
