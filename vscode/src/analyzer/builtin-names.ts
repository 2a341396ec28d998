/**
 * Every name a cell may read without a cell defining it, as the page
 * resolves names (cells/builtins.ts, runtime.ts): the book's
 * catalogue, the standard JavaScript and browser globals, Math's members by
 * bare name, `html`, `width` and `now`, and the two names the Observable
 * runtime itself gives every cell.
 */
import { createBuiltins, BROWSER_GLOBALS, JAVASCRIPT_GLOBALS, mathByName } from '../../../cells/index.ts';
import type { Catalogue } from './catalogue.ts';

/** @observablehq/runtime's own builtins (src/module.js): a promise that resolves when the cell is redefined, and one for when it is in view. */
export const RUNTIME_NAMES = ['invalidation', 'visibility'] as const;

/**
 * The names. The page's builtins are taken from the page's own function,
 * called with a stand-in root element (it only keeps it for `width`); the
 * globals are listed whole, since the extension host lacks `document` and
 * the other browser globals that the page has.
 */
export function builtinNames(catalogue: Catalogue): Set<string> {
  const page = Object.keys(createBuiltins({} as Element, {}));
  return new Set<string>([
    ...page,
    ...JAVASCRIPT_GLOBALS,
    ...BROWSER_GLOBALS,
    ...Object.keys(mathByName()),
    ...RUNTIME_NAMES,
    ...catalogue.builtins.map((entry) => entry.name),
  ]);
}
