/**
 * The book's parts on the contents page: chapters in reading order, cut
 * wherever their front matter's `part` changes (site/content.config.ts).
 * Free of Astro's virtual modules, so it is unit-tested in Node.
 */

/** What grouping needs of a chapter. */
interface InPart {
  readonly data: { readonly part?: number };
}

/** A run of chapters in reading order that share a part (`part` undefined: pages outside the parts). */
export interface PartRun<T extends InPart> {
  readonly part: number | undefined;
  readonly chapters: readonly T[];
}

/**
 * Cuts chapters already in reading order into runs of one part each, so that
 * the contents page heads each part where its chapters' orders place it, and
 * the pages outside the parts (the playground, the teachers' guide, the
 * about page) stay where their orders put them.
 */
export function runsOfParts<T extends InPart>(ordered: readonly T[]): PartRun<T>[] {
  const runs: { part: number | undefined; chapters: T[] }[] = [];
  for (const chapter of ordered) {
    const last = runs.at(-1);
    if (last && last.part === chapter.data.part) last.chapters.push(chapter);
    else runs.push({ part: chapter.data.part, chapters: [chapter] });
  }
  return runs;
}

/** The part's number as the contents page heads it: Part I, Part II … */
export function romanPart(part: number): string {
  const numerals: [number, string][] = [[10, 'X'], [9, 'IX'], [5, 'V'], [4, 'IV'], [1, 'I']];
  let rest = part;
  let text = '';
  for (const [value, numeral] of numerals) {
    while (rest >= value) {
      text += numeral;
      rest -= value;
    }
  }
  return text;
}
