/**
 * A chapter's exercises: the fences marked ```` ```exercise ```` that the
 * book's build turns into exercises (site/lib/remark-exercises.mjs visits
 * the same code nodes of the same tree), each read by the book's own parser
 * (parseExercise), so a declaration the book refuses is refused here with
 * the same words, and a field or check the book adds is read here as the
 * book reads it.
 */
import type { Code, Parent, Root } from 'mdast';
import { KIND_NAMES, parseExercise, type Exercise } from '../../../widgets/index.ts';

export interface ChapterExercise {
  /** Position among the chapter's exercises, from 0. */
  readonly index: number;
  /**
   * A name for the exercise that lasts while it is edited: its id, which
   * the book keeps progress under; for a declaration that does not parse,
   * or repeats an id, its place among the exercises (`@2`, which no id can
   * be).
   */
  readonly key: string;
  /** The declaration, or why the book refuses it. */
  readonly parsed: { readonly exercise: Exercise } | { readonly error: string };
  /** What the Test Explorer shows: the title, and the kind as the page names it. */
  readonly label: string;
  readonly description: string;
  /** Offsets of the whole fence, opening to closing line. */
  readonly start: number;
  readonly end: number;
  /** Where `text` (a string value of the declaration, such as a wrong answer) is written in the fence, as JSON writes it; null when it is not found so. */
  locate(text: string): { start: number; end: number } | null;
}

function eachExerciseFence(parent: Parent, visit: (node: Code) => void): void {
  for (const child of parent.children) {
    if (child.type === 'code' && child.lang === 'exercise') visit(child);
    else if ('children' in child) eachExerciseFence(child, visit);
  }
}

/** `text` is the whole file (the tree's offsets are the file's: the front matter is blanked, not cut). */
export function findExercises(tree: Root, text: string): ChapterExercise[] {
  const found: ChapterExercise[] = [];
  const ids = new Set<string>();
  eachExerciseFence(tree, (node) => {
    const index = found.length;
    const start = node.position?.start.offset ?? 0;
    const end = node.position?.end.offset ?? start;
    let parsed: ChapterExercise['parsed'] = parseExercise(node.value);
    // The build refuses a repeated id in a chapter (progress is kept by id), and so does the test.
    if ('exercise' in parsed && ids.has(parsed.exercise.id)) parsed = { error: `the id ${parsed.exercise.id} is used twice in this chapter: progress is kept by id` };
    const key = 'exercise' in parsed ? parsed.exercise.id : `@${index + 1}`;
    if ('exercise' in parsed) ids.add(parsed.exercise.id);
    const fence = text.slice(start, end);
    const locate = (value: string) => {
      const at = fence.indexOf(JSON.stringify(value));
      return at < 0 ? null : { start: start + at, end: start + at + JSON.stringify(value).length };
    };
    const label = 'exercise' in parsed ? parsed.exercise.title : `Exercise ${index + 1}`;
    const description = 'exercise' in parsed ? KIND_NAMES[parsed.exercise.kind] : 'not readable';
    found.push({ index, key, parsed, label, description, start, end, locate });
  });
  return found;
}
