/**
 * Observable reads `name = { … }` as a named BLOCK, but a JavaScript parser
 * reads the braces as an object literal, so highlighting a block cell with
 * the plain JavaScript grammar mislabels `return`, `if`, … inside it.
 *
 * Both highlighters (the build's, site/lib/highlight-js.mjs, and the editor's,
 * cell-language.ts) therefore parse the cell with that one `=` read as `;`:
 * `name ; { … }` is an expression followed by a block statement, the same
 * length as the original, so token positions stay exact.
 */

/** `name =` then `{`, after any leading blank space or comments. */
const BLOCK_ASSIGNMENT = /^((?:\s|\/\/[^\n]*\n|\/\*[\s\S]*?\*\/)*[A-Za-z_$][\w$]*\s*)=\s*\{/;

/** How far into a cell to look for the header. */
export const BLOCK_HEADER_WINDOW = 512;

/** Offset of the `=` of a `name = { … }` cell, or -1 for any other cell. */
export function blockAssignmentAt(source: string): number {
  const match = BLOCK_ASSIGNMENT.exec(source.slice(0, BLOCK_HEADER_WINDOW));
  return match?.[1] === undefined ? -1 : match[1].length;
}

/** The text a JavaScript parser should see for highlighting `source`. */
export function asParsableBlock(source: string): string {
  const at = blockAssignmentAt(source);
  return at < 0 ? source : `${source.slice(0, at)};${source.slice(at + 1)}`;
}
