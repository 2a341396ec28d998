/**
 * The book's reading order. Chapters declare it (front matter `order`), so
 * the contents page and the previous/next links never depend on file names.
 */
import { getCollection } from 'astro:content';

/** What the site needs of a chapter entry (site/content.config.ts). */
export interface Chapter {
  /** URL segment: the chapter lives at `/<id>/`. */
  readonly id: string;
  readonly data: { readonly title: string; readonly description: string; readonly order: number; readonly part?: number };
}

/** Sorts by `order`; two chapters claiming one place is an authoring error that fails the build. */
export function orderChapters<T extends Chapter>(chapters: readonly T[]): T[] {
  const sorted = [...chapters].sort((a, b) => a.data.order - b.data.order);
  sorted.forEach((chapter, i) => {
    const previous = sorted[i - 1];
    if (previous && previous.data.order === chapter.data.order) {
      throw new Error(`Chapters "${previous.id}" and "${chapter.id}" both have order ${chapter.data.order}`);
    }
  });
  return sorted;
}

/** Every chapter, in reading order. */
export async function listChapters(): Promise<Chapter[]> {
  const entries: Chapter[] = await getCollection('chapters');
  return orderChapters(entries);
}

/** The site's root URL, `/` or the base path it is served under (PHASEBOOK_BASE), ending in `/`. */
export const HOME: string = import.meta.env.BASE_URL.replace(/\/?$/, '/');

/** Root-absolute URL of a chapter, with the trailing slash the site uses. */
export function chapterHref(chapter: Chapter): string {
  return `${HOME}${chapter.id}/`;
}
