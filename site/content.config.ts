/**
 * Chapters of the book: every `*.mdx` file in the top-level `content/` folder.
 *
 * Front matter of a chapter:
 * - `title` (string, required): the chapter's heading, in the contents and in prev/next links.
 * - `description` (string, required): one sentence shown under the title on the contents page
 *   and used as the page's meta description.
 * - `order` (integer, required): the chapter's position in the book. Chapters are listed and
 *   linked in increasing `order`; two chapters may not share one (the build fails). Leave gaps
 *   (1, 2, 3 … 99) so a chapter can be slotted in without renumbering.
 * - `part` (integer, optional): the part of the book the chapter belongs to, 1 or 2, whose
 *   title (`PART_TITLES` in site/lib/chapter-schema.ts) heads it on the contents page: 1 for
 *   the paper's examples (orders 1–9), 2 for the geometry of phase space and the road to chaos
 *   (orders 20–29). Pages outside the parts (the playground, the teachers' guide, the about
 *   page) leave it out and are listed after them, under no heading.
 * - `slug` (string, optional): the URL segment, `/<slug>/`. Defaults to the file name
 *   without `.mdx` (this is the glob loader's own rule).
 *
 * A fenced block marked ```` ```js cell ```` inside a chapter is a live code cell
 * (site/lib/remark-cells.mjs).
 */
import { defineCollection } from 'astro:content';
import { glob } from 'astro/loaders';
import { chapterSchema } from './lib/chapter-schema';

/**
 * PHASEBOOK_CONTENT_DIR builds the book from another folder of chapters: the
 * tests build broken chapters, and edit copies of chapters under the dev
 * server, without touching content/.
 */
const CONTENT_DIR = process.env.PHASEBOOK_CONTENT_DIR || './content';

const chapters = defineCollection({
  loader: glob({ pattern: '**/*.mdx', base: CONTENT_DIR }),
  schema: chapterSchema,
});

export const collections = { chapters };
