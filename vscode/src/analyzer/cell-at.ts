/**
 * The cell whose code contains a place in the file: strictly between its
 * opening and closing fence lines, where the code is.
 */
import type { ChapterAnalysis } from './analyze.ts';
import type { ChapterCell } from './cells.ts';

export function cellAt(analysis: Pick<ChapterAnalysis, 'cells' | 'lines'>, offset: number): ChapterCell | undefined {
  const { line } = analysis.lines.position(offset);
  return analysis.cells.find((cell) => cell.fenceLine < line && line < cell.endLine);
}

/** The file offset where a cell's code starts (the line after its opening fence). */
export function codeStart(analysis: Pick<ChapterAnalysis, 'lines'>, cell: ChapterCell): number {
  return analysis.lines.offset(cell.fenceLine + 1, 0);
}
