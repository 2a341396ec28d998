/**
 * The chapter's body as the book's MDX pipeline reads it: Markdown with
 * GitHub's extensions (Astro's default), MDX (JSX, `{…}` expressions and
 * comments) and remark-math (so braces inside `$…$` are math, not JSX).
 * An MDX syntax error fails the book's build; it is reported, and the body
 * is read again without MDX so that its cells can still be found.
 */
import type { Root } from 'mdast';
import remarkGfm from 'remark-gfm';
import remarkMath from 'remark-math';
import remarkMdx from 'remark-mdx';
import remarkParse from 'remark-parse';
import { unified } from 'unified';

export interface SyntaxProblem {
  readonly message: string;
  readonly offset: number;
}

export interface ChapterTree {
  readonly tree: Root;
  /** The MDX syntax error that makes the build fail, if any. */
  readonly mdxError: SyntaxProblem | null;
}

const mdx = unified().use(remarkParse).use(remarkMdx).use(remarkGfm).use(remarkMath).freeze();
const markdown = unified().use(remarkParse).use(remarkGfm).use(remarkMath).freeze();

interface ParseFailure {
  reason?: string;
  message?: string;
  place?: { offset?: number } | { start?: { offset?: number } };
  cause?: { message?: string };
}

function offsetOf(failure: ParseFailure): number {
  const place = failure.place;
  if (place && 'offset' in place && typeof place.offset === 'number') return place.offset;
  if (place && 'start' in place && typeof place.start?.offset === 'number') return place.start.offset;
  return 0;
}

function describe(failure: ParseFailure): string {
  const reason = failure.reason ?? failure.message ?? String(failure);
  const cause = failure.cause?.message;
  return cause && !reason.includes(cause) ? `${reason}: ${cause}` : reason;
}

export function parseChapterTree(body: string): ChapterTree {
  try {
    return { tree: mdx.parse(body), mdxError: null };
  } catch (thrown) {
    const failure = thrown as ParseFailure;
    return { tree: markdown.parse(body), mdxError: { message: `MDX: ${describe(failure)}`, offset: offsetOf(failure) } };
  }
}
