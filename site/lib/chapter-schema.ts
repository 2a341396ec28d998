/**
 * The front matter every chapter must have (documented in site/content.config.ts).
 * Its own module, free of Astro's virtual modules, so that the VS Code
 * extension (vscode/) checks a chapter's front matter with the very schema
 * the build uses.
 */
import { z } from 'astro/zod';

export const chapterSchema = z.object({
  title: z.string(),
  description: z.string(),
  order: z.number().int(),
});
