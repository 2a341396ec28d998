/**
 * The chapter's front matter checked against the book's schema
 * (site/lib/chapter-schema.ts, the one site/content.config.ts gives Astro), so
 * a missing description or a fractional order shows while typing rather
 * than as a failed build.
 */
import { chapterSchema } from '../../../site/lib/chapter-schema.ts';
import type { ChapterText } from './chapter-text.ts';
import type { Problem } from './problems.ts';

export interface FrontMatterCheck {
  readonly problems: Problem[];
  /** The chapter's `order` when it is valid, with the range of its line, for the workspace-wide check. */
  readonly order: { readonly value: number; readonly start: number; readonly end: number } | null;
  readonly title: string | null;
}

/** The range of `key: …` in the YAML, or of the opening `---` when the key is absent. */
function keyRange(chapter: ChapterText, key: string): { start: number; end: number } {
  const front = chapter.frontMatter;
  if (!front) return { start: 0, end: 0 };
  const escaped = key.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
  const match = new RegExp(`^${escaped}\\s*:.*$`, 'm').exec(front.raw);
  if (!match) return { start: Math.max(0, front.start - 3), end: front.start };
  return { start: front.start + match.index, end: front.start + match.index + match[0].length };
}

export function checkFrontMatter(chapter: ChapterText): FrontMatterCheck {
  const front = chapter.frontMatter;
  if (!front) {
    return {
      problems: [{
        code: 'front-matter',
        severity: 'error',
        message: 'A chapter starts with front matter: a line `---`, then `title:`, `description:` and `order:`, then `---` (see templates/chapter.mdx).',
        start: 0,
        end: chapter.text.indexOf('\n') === -1 ? chapter.text.length : chapter.text.indexOf('\n'),
      }],
      order: null,
      title: null,
    };
  }
  if (front.error) {
    const problem: Problem = { code: 'front-matter', severity: 'error', message: `Front matter is not valid YAML: ${front.error.message}`, start: front.error.offset, end: front.error.offset + 1 };
    return { problems: [problem], order: null, title: null };
  }
  const result = chapterSchema.safeParse(front.data ?? {});
  const problems: Problem[] = [];
  if (!result.success) {
    for (const issue of result.error.issues) {
      const key = String(issue.path[0] ?? '');
      const missing = issue.code === 'invalid_type' && issue.received === 'undefined';
      const message = missing
        ? `Front matter has no \`${key}\`, which every chapter needs (expected ${issue.expected}).`
        : `Front matter \`${key}\`: ${issue.message}.`;
      problems.push({ code: 'front-matter', severity: 'error', message, ...keyRange(chapter, key) });
    }
  }
  // Each field on its own, so a valid order is compared with the other chapters' even when the title is missing.
  const data = front.data ?? {};
  const order = chapterSchema.shape.order.safeParse(data.order);
  const title = chapterSchema.shape.title.safeParse(data.title);
  return {
    problems,
    order: order.success ? { value: order.data, ...keyRange(chapter, 'order') } : null,
    title: title.success ? title.data : null,
  };
}
