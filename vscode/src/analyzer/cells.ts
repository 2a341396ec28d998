/**
 * A chapter's cells, found and parsed by the book's own code
 * (site/lib/remark-cells.mjs: the fences it turns into cells, the source it
 * hands the page, its parse and the ids the page gives them), placed in the
 * file so that problems inside a cell point at the right character.
 */
import type { Code, Root } from 'mdast';
import { assignCellIds, collectCells } from '../../../site/lib/remark-cells.mjs';
import type { CellSpec } from '../../../cells/index.ts';
import type { LineIndex } from './positions.ts';

export interface ChapterCell {
  /** Position among the chapter's cells, from 0. */
  readonly index: number;
  /** The id the page gives the cell: its name, `name-dupN`, or `cell-N`. */
  readonly id: string;
  readonly name: string | null;
  /** The source as the page runs it (leading blank lines and trailing space removed). */
  readonly source: string;
  /** The parse, or null when the source does not parse. */
  readonly spec: CellSpec | null;
  /** The parser's message, e.g. "SyntaxError: Unexpected token (1:7)". */
  readonly error: string | null;
  /** Offsets of the whole fence, opening to closing line. */
  readonly start: number;
  readonly end: number;
  /** Lines (from 0) of the opening and closing fence. */
  readonly fenceLine: number;
  readonly endLine: number;
  /** The file offset of an offset in {@link source}. */
  toFile(sourceOffset: number): number;
}

type Found = Parameters<typeof collectCells>[1][number];

/**
 * The file line (from 0) of the source's first line, and the fence's
 * indentation, which Markdown removes from each line of a fence inside a
 * list item. The source starts after the opening fence and the blank lines
 * the book drops.
 */
function placeCell(node: Code): { firstLine: number; indent: number } {
  const start = node.position?.start;
  const skipped = node.value.length - node.value.replace(/^\n+/, '').length;
  return { firstLine: (start?.line ?? 1) + skipped, indent: (start?.column ?? 1) - 1 };
}

export function findCells(tree: Root, lines: LineIndex): ChapterCell[] {
  const found: Found[] = [];
  collectCells(tree, found);
  const ids = assignCellIds(found.map(({ analysis }) => ({ name: 'spec' in analysis ? analysis.spec.name : null })));
  return found.map(({ parent, index, source, analysis }, i) => {
    const node = parent.children[index] as Code;
    const { firstLine, indent } = placeCell(node);
    const toFile = (sourceOffset: number): number => {
      const before = source.slice(0, Math.max(0, sourceOffset));
      const line = before.split('\n').length - 1;
      const character = before.length - (before.lastIndexOf('\n') + 1);
      return lines.offset(firstLine + line, indent + character);
    };
    const start = node.position?.start.offset ?? 0;
    const end = node.position?.end.offset ?? start;
    return {
      index: i,
      id: ids[i],
      name: 'spec' in analysis ? analysis.spec.name : null,
      source,
      spec: 'spec' in analysis ? analysis.spec : null,
      error: 'error' in analysis ? analysis.error : null,
      start,
      end,
      fenceLine: lines.position(start).line,
      endLine: lines.position(end).line,
      toFile,
    };
  });
}
