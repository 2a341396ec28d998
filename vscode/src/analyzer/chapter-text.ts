/**
 * A chapter file split into its front matter and its MDX body, as Astro
 * splits it: the body keeps the file's length (the front matter is blanked
 * with spaces), so every offset in the body is the same offset in the file.
 */
import { extractFrontmatter, parseFrontmatter } from './astro-frontmatter.ts';

export interface FrontMatter {
  /** Offset of the YAML text (just after the opening `---`). */
  readonly start: number;
  /** The YAML text. */
  readonly raw: string;
  /** The parsed mapping, or null when the YAML does not parse or is not a mapping. */
  readonly data: Readonly<Record<string, unknown>> | null;
  /** Why the YAML does not parse, at an offset in the file. */
  readonly error: { readonly message: string; readonly offset: number } | null;
}

export interface ChapterText {
  readonly text: string;
  /** The text with the front matter blanked: what MDX parses. */
  readonly body: string;
  /** Null when the file has no front matter at all. */
  readonly frontMatter: FrontMatter | null;
}

interface YamlError {
  reason?: string;
  message?: string;
  mark?: { position?: number };
}

/** Spaces for every character but line breaks, so lines and offsets stay put. */
function blank(text: string): string {
  return text.replace(/[^\r\n]/g, ' ');
}

export function splitChapter(text: string): ChapterText {
  const raw = extractFrontmatter(text);
  if (raw === undefined) return { text, body: text, frontMatter: null };
  const start = text.indexOf(raw);
  const whole = text.slice(0, start + raw.length + 3);
  const body = blank(whole) + text.slice(whole.length);
  try {
    const { frontmatter } = parseFrontmatter(text, { frontmatter: 'preserve' });
    const data = typeof frontmatter === 'object' && frontmatter !== null && !Array.isArray(frontmatter) ? frontmatter : null;
    return { text, body, frontMatter: { start, raw, data, error: null } };
  } catch (thrown) {
    const yaml = thrown as YamlError;
    const message = yaml.reason ?? yaml.message?.split('\n')[0] ?? String(thrown);
    const offset = start + Math.min(raw.length, Math.max(0, yaml.mark?.position ?? 0));
    return { text, body, frontMatter: { start, raw, data: null, error: { message, offset } } };
  }
}
