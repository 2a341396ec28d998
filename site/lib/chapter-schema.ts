/**
 * The front matter every chapter must have (documented in site/content.config.ts).
 * Its own module, free of Astro's virtual modules, so that the VS Code
 * extension (vscode/) checks a chapter's front matter with the very schema
 * the build uses.
 */
import { z } from 'astro/zod';

/** The book's parts, by number: the contents page heads each part's chapters with its title. */
export const PART_TITLES: Readonly<Record<number, string>> = {
  1: 'The paper’s examples',
  2: 'The geometry of phase space and the road to chaos',
};

export const chapterSchema = z.object({
  title: z.string(),
  description: z.string(),
  order: z.number().int(),
  part: z
    .number()
    .int()
    .refine((n) => Object.hasOwn(PART_TITLES, n), { message: `part must be one of ${Object.keys(PART_TITLES).join(', ')}` })
    .optional(),
});
