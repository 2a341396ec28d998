/**
 * Parses a reader's edited cell in the browser. This module (and acorn, which
 * the Observable parser is built on) is the `parser` chunk: it is imported
 * dynamically on the first Run of changed source, never on page load —
 * the author's cells arrive pre-parsed from the build.
 */
import { parseCell } from '@observablehq/parser';
import { describeCell, type CellSpec } from './spec.ts';

/**
 * True for a parse that ran out of stack: acorn reads nested expressions by
 * recursion, and a sum of thousands of terms (a 100 kB H written out) nests
 * that deep.
 */
function tooDeep(error: unknown): boolean {
  return (error instanceof RangeError && /call stack/i.test(error.message)) || (error instanceof SyntaxError && /Not enough stack space/.test(error.message));
}

/** Throws a SyntaxError whose message ends in "(line:column)". */
export function parseSource(source: string): CellSpec {
  try {
    return describeCell(parseCell(source));
  } catch (error) {
    if (!tooDeep(error)) throw error;
    throw new SyntaxError(
      `this cell nests too deeply to be read (${source.length} characters): a sum of thousands of terms is a tree that deep; group the terms in parentheses, or give H as a string`,
    );
  }
}
