/**
 * The sections of a chapter, for its "On this page" lists: the h2 headings,
 * each with the h3 headings under it. Deeper headings are left to the text;
 * an h3 before any h2 stands on its own.
 */

/** A heading as Astro's render() lists it. */
export interface Heading {
  readonly depth: number;
  readonly slug: string;
  readonly text: string;
}

export interface Section {
  readonly id: string;
  readonly title: string;
  readonly subsections: readonly Section[];
}

export function sectionsOf(headings: readonly Heading[]): Section[] {
  const sections: { id: string; title: string; subsections: Section[] }[] = [];
  for (const { depth, slug, text } of headings) {
    const title = text.replace(/\s+/g, ' ').trim();
    if (!slug || !title) continue;
    if (depth === 2) sections.push({ id: slug, title, subsections: [] });
    else if (depth === 3) {
      const parent = sections.at(-1);
      if (parent) parent.subsections.push({ id: slug, title, subsections: [] });
      else sections.push({ id: slug, title, subsections: [] });
    }
  }
  return sections;
}
