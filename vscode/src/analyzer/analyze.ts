/**
 * Checks one chapter as the book would build and run it, without running
 * anything: its front matter, its MDX, and each cell's syntax, name and
 * the names it reads; and finds its exercises. Pure: the caller passes the
 * text and the names that builtins provide, and gets problems at file
 * offsets.
 */
import { parseCell } from '@observablehq/parser';
import { findCells, type ChapterCell } from './cells.ts';
import { findExercises, type ChapterExercise } from './exercises.ts';
import { splitChapter, type ChapterText } from './chapter-text.ts';
import { parseChapterTree } from './chapter-tree.ts';
import { checkFrontMatter, type FrontMatterCheck } from './front-matter.ts';
import { LineIndex } from './positions.ts';
import type { Problem } from './problems.ts';

export interface ChapterAnalysis {
  readonly chapter: ChapterText;
  readonly lines: LineIndex;
  readonly frontMatter: FrontMatterCheck;
  readonly cells: readonly ChapterCell[];
  /** The ```exercise fences, each with its declaration or the parser's refusal. */
  readonly exercises: readonly ChapterExercise[];
  /** Problems of this file alone; duplicate orders need the workspace (orders.ts). */
  readonly problems: readonly Problem[];
}

/** A reference as the parser gives it: an identifier with its offsets in the cell's source. */
interface ParsedReference {
  readonly name?: string;
  readonly start: number;
  readonly end: number;
}

/** "SyntaxError: Unexpected token (2:7)" → line 2 (from 1), column 7 (from 0), as acorn counts. */
const PARSER_PLACE = /\((\d+):(\d+)\)$/;

/** The character at `at`, or the one before it when `at` is the end of its line (an error at the end of input). */
function oneCharacter(lines: LineIndex, at: number): { start: number; end: number } {
  const { line } = lines.position(at);
  if (at < lines.lineEnd(line)) return { start: at, end: at + 1 };
  return { start: Math.max(lines.offset(line, 0), at - 1), end: at };
}

function syntaxProblem(cell: ChapterCell, error: string, lines: LineIndex): Problem {
  const place = PARSER_PLACE.exec(error);
  if (place) {
    const [line, column] = [Number(place[1]) - 1, Number(place[2])];
    const offset = cell.source.split('\n').slice(0, line).reduce((sum, text) => sum + text.length + 1, 0) + column;
    return { code: 'cell-syntax', severity: 'error', message: error, ...oneCharacter(lines, cell.toFile(Math.min(offset, cell.source.length))) };
  }
  // A cell the book does not support (an import, viewof) has no position: the whole first line.
  const start = cell.toFile(0);
  return { code: 'cell-syntax', severity: 'error', message: error, start, end: cell.toFile(cell.source.split('\n')[0].length) };
}

function firstLine(cell: ChapterCell): { start: number; end: number } {
  return { start: cell.toFile(0), end: cell.toFile(cell.source.split('\n')[0].length) };
}

/** Each reference to `name` in the cell (the parser's own positions), or the first line when none is found. */
function referencesTo(cell: ChapterCell, name: string): { start: number; end: number }[] {
  try {
    const references = parseCell(cell.source).references as unknown as readonly ParsedReference[];
    const found = references.filter((r) => r.name === name);
    if (found.length) return found.map((r) => ({ start: cell.toFile(r.start), end: cell.toFile(r.end) }));
  } catch {
    // It parsed a moment ago; a failure now changes nothing about the problem.
  }
  return [firstLine(cell)];
}

function cellProblems(cells: readonly ChapterCell[], builtins: ReadonlySet<string>, lines: LineIndex): Problem[] {
  const problems: Problem[] = [];
  const defined = new Map<string, ChapterCell[]>();
  for (const cell of cells) if (cell.name) defined.set(cell.name, [...(defined.get(cell.name) ?? []), cell]);

  for (const cell of cells) {
    if (cell.error) {
      problems.push(syntaxProblem(cell, cell.error, lines));
      continue;
    }
    if (!cell.spec) continue;
    if (!cell.name) {
      problems.push({
        code: 'unnamed-cell',
        severity: 'warning',
        message: 'This cell has no name: a reader’s saved edit is kept under the cell’s name, so name it (`name = …`) to keep readers’ edits when cells are added or moved.',
        ...firstLine(cell),
      });
    } else {
      const others = (defined.get(cell.name) ?? []).filter((other) => other !== cell);
      if (others.length) {
        problems.push({
          code: 'duplicate-name',
          severity: 'error',
          message: `\`${cell.name}\` is defined by ${others.length + 1} cells; the page fails all of them ("${cell.name} is defined more than once").`,
          ...firstLine(cell),
          related: others.map((other) => ({ ...firstLine(other), message: `\`${cell.name}\` is also defined here` })),
        });
      }
    }
    for (const input of cell.spec.inputs) {
      if (defined.has(input) || builtins.has(input)) continue;
      for (const range of referencesTo(cell, input)) {
        problems.push({ code: 'unknown-name', severity: 'error', message: `\`${input}\` is not defined: no cell defines it and the book has no builtin of that name.`, ...range });
      }
    }
  }
  return problems;
}

export function analyzeChapter(text: string, builtins: ReadonlySet<string>): ChapterAnalysis {
  const chapter = splitChapter(text);
  const lines = new LineIndex(text);
  const frontMatter = checkFrontMatter(chapter);
  const { tree, mdxError } = parseChapterTree(chapter.body);
  const cells = findCells(tree, lines);
  const exercises = findExercises(tree, text);
  const problems: Problem[] = [...frontMatter.problems];
  if (mdxError) problems.push({ code: 'mdx-syntax', severity: 'error', message: mdxError.message, ...oneCharacter(lines, mdxError.offset) });
  problems.push(...cellProblems(cells, builtins, lines));
  return { chapter, lines, frontMatter, cells, exercises, problems };
}
