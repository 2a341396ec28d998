/**
 * Parses a reader's edited cell in the browser. This module (and acorn, which
 * the Observable parser is built on) is the `parser` chunk: it is imported
 * dynamically on the first Run of changed source, never on page load —
 * the author's cells arrive pre-parsed from the build.
 */
import { parseCell } from '@observablehq/parser';
import { describeCell, type CellSpec } from './spec.ts';

/** Throws a SyntaxError whose message ends in "(line:column)". */
export function parseSource(source: string): CellSpec {
  return describeCell(parseCell(source));
}
