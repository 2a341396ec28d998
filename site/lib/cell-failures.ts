/**
 * The build's report on a chapter's cells: a cell that fails when the build
 * runs it (precompile.ts) would fail in every reader's page, so the build
 * fails too, with one line per cell — `file:line: cell name: message`, the
 * form editors and terminals turn into a link.
 *
 * A chapter can mark a cell whose failure is the lesson (```` ```js cell fails ````):
 * the build passes over its failure, and fails if it does not fail. Every cell
 * must have a name, since a reader's saved edit is kept under it.
 *
 * The report is gathered here, chapter by chapter as the MDX compiler reaches
 * each one, and read by the integration in fail-loudly.mjs once all are done.
 */
import type { BuildOutcome } from './precompile.ts';

/** The fence's word that marks a cell whose failure is the lesson. */
export const FAILS_MARK = 'fails';

/** One cell of a chapter, as the report needs it. */
export interface ReportedCell {
  /** The cell's id on the page: its name, or `cell-N`. */
  readonly id: string;
  /** The line of its fence in the chapter file. */
  readonly line: number;
  readonly named: boolean;
  /** Marked ```` ```js cell fails ````: it must fail. */
  readonly failureIsTheLesson: boolean;
  /** The parser's message when the source is not a cell at all. */
  readonly syntaxError?: string;
}

/** What is wrong with a chapter's cells, one line each; none when all is well. */
export function chapterProblems(file: string, cells: readonly ReportedCell[], outcomes: ReadonlyMap<string, BuildOutcome>): string[] {
  return cells.flatMap((cell) => {
    const where = `${file}:${cell.line}: cell ${cell.id}`;
    const problems: string[] = [];
    if (!cell.named) problems.push(`${where} has no name; start it with one (\`name = …\`), under which a reader's edit is saved`);
    const outcome = cell.syntaxError !== undefined ? { kind: 'failed' as const, message: cell.syntaxError } : outcomes.get(cell.id);
    if (cell.failureIsTheLesson) {
      if (outcome?.kind === 'ran') problems.push(`${where} is marked "${FAILS_MARK}" but ran without an error`);
      if (outcome?.kind === 'page only') problems.push(`${where} is marked "${FAILS_MARK}" but runs only in the page, so the build cannot see it fail`);
    } else if (outcome?.kind === 'failed') {
      problems.push(`${where}: ${outcome.message}`);
    }
    return problems;
  });
}

/**
 * The problems of every chapter compiled so far, by what reported them and the file: a chapter
 * compiled again replaces its own. Its cells (remark-cells.mjs) and its exercises
 * (remark-exercises.mjs) report apart, so that one clearing its problems does not clear the other's.
 */
const problemsByFile = new Map<string, readonly string[]>();
const listeners = new Set<(file: string, problems: readonly string[]) => void>();

/** What reports a chapter's problems. */
export type Reporter = 'cells' | 'exercises';

/** Records a chapter's problems (none clears it), and tells whoever listens. */
export function reportChapter(file: string, problems: readonly string[], reporter: Reporter = 'cells'): void {
  const key = `${reporter} ${file}`;
  if (problems.length) problemsByFile.set(key, problems);
  else problemsByFile.delete(key);
  for (const listener of listeners) listener(file, problems);
}

/** Every problem recorded, chapter by chapter in the order they were compiled. */
export function recordedProblems(): string[] {
  return [...problemsByFile.values()].flat();
}

/** Calls `listener` on every chapter reported from now on (the dev server prints them); returns the way to stop. */
export function onChapterReport(listener: (file: string, problems: readonly string[]) => void): () => void {
  listeners.add(listener);
  return () => listeners.delete(listener);
}
