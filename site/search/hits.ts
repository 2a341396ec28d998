/**
 * What the search box shows of Pagefind's results: for each chapter that
 * matches, the few sections where the words are densest, each a link to its
 * heading with an excerpt. Pagefind splits a page into sections at every
 * heading that has an id (each of the book's does); the text before the
 * first heading is a section under the chapter's own title.
 */
import type { PageHit, SectionHit } from './protocol.ts';

/** The part of a Pagefind sub-result read here. */
export interface PagefindSection {
  readonly title?: string;
  readonly url?: string;
  readonly excerpt?: string;
  readonly locations?: readonly number[];
}

/** The part of a Pagefind result's data() read here. */
export interface PagefindPage {
  readonly url?: string;
  readonly excerpt?: string;
  readonly meta?: { readonly title?: string };
  readonly sub_results?: readonly PagefindSection[];
}

/** Sections shown per chapter: enough to choose from, few enough that the second chapter is in view. */
export const SECTIONS_PER_PAGE = 3;

const text = (value: unknown, fallback = ''): string => (typeof value === 'string' ? value : fallback);

export function pageHit(page: PagefindPage, sectionsPerPage = SECTIONS_PER_PAGE): PageHit {
  const url = text(page.url, '#');
  const title = text(page.meta?.title, url);
  const found = (page.sub_results ?? [])
    .map((section, order) => ({ section, order, weight: section.locations?.length ?? 0 }))
    .filter(({ weight }) => weight > 0);
  const best = found
    .sort((a, b) => b.weight - a.weight || a.order - b.order)
    .slice(0, sectionsPerPage)
    .sort((a, b) => a.order - b.order);
  const sections: SectionHit[] = best.map(({ section }) => ({
    title: text(section.title, title),
    url: text(section.url, url),
    excerpt: text(section.excerpt),
  }));
  if (!sections.length) sections.push({ title, url, excerpt: text(page.excerpt) });
  return { title, url, sections };
}
