/**
 * Pagefind's excerpts are HTML of one shape: the page's text with `<` and
 * `>` escaped, and the words that matched inside `<mark>`. They are read
 * here into plain pieces, which the page shows as text, never as HTML: an
 * excerpt is the book's own text, but a formula's TeX is full of `<` and
 * `&`, and text set as text cannot become markup.
 */

export interface ExcerptPiece {
  readonly text: string;
  readonly marked: boolean;
}

const ESCAPES: Record<string, string> = { '&lt;': '<', '&gt;': '>' };

export function excerptPieces(excerpt: string): ExcerptPiece[] {
  const pieces: ExcerptPiece[] = [];
  let marked = false;
  for (const part of String(excerpt).split(/(<\/?mark>)/)) {
    if (part === '<mark>' || part === '</mark>') {
      marked = part === '<mark>';
      continue;
    }
    const text = part.replace(/&[lg]t;/g, (escape) => ESCAPES[escape] ?? escape);
    if (!text) continue;
    const last = pieces.at(-1);
    if (last && last.marked === marked) pieces[pieces.length - 1] = { text: last.text + text, marked };
    else pieces.push({ text, marked });
  }
  return pieces;
}
