/**
 * Code far from the view arrives plain, with its highlighting as data, and
 * is coloured as it comes near. A chapter's cells hold thousands of tokens;
 * a span for each, in the HTML, made the page's DOM a third larger and its
 * style and layout slower to match, for code the reader may never scroll to.
 * The build (site/lib/highlight-js.mjs) writes the runs of a `<code>` in
 * `data-tokens`: space-separated, each a length in UTF-16 units, followed by
 * `.classes` (joined by `.`) when the run is a token. The text itself is
 * always there, so find in page, search and screen readers see the code at
 * once; only its colour waits.
 */
export const TOKENS_ATTRIBUTE = 'data-tokens';

/** How far ahead of the view code is coloured: a screen, so that scrolling never shows it plain. */
const AHEAD = '100% 0px';

/**
 * The runs `runs` (a `data-tokens` value) cut `text` into, each with its classes ('' for plain text);
 * null if they do not add up to the text exactly (a page edited by hand, a stale cache), so that code is left
 * plain, never coloured wrong.
 */
export function readRuns(runs: string, text: string): Array<{ text: string; classes: string }> | null {
  const pieces: Array<{ text: string; classes: string }> = [];
  let at = 0;
  for (const run of runs.split(' ')) {
    if (!run) continue;
    const [length, ...classes] = run.split('.');
    const size = Number(length);
    if (!Number.isInteger(size) || size <= 0 || at + size > text.length) return null;
    pieces.push({ text: text.slice(at, at + size), classes: classes.join(' ') });
    at += size;
  }
  return at === text.length ? pieces : null;
}

/** Replaces the plain text of `code` with the spans of its runs, once; code without runs is left as it is. */
export function colourCode(code: Element): void {
  const runs = code.getAttribute(TOKENS_ATTRIBUTE);
  if (runs === null) return;
  code.removeAttribute(TOKENS_ATTRIBUTE);
  const pieces = readRuns(runs, code.textContent ?? '');
  if (!pieces) return;
  const parts = new DocumentFragment();
  for (const { text, classes } of pieces) {
    if (!classes) {
      parts.append(text);
      continue;
    }
    const span = document.createElement('span');
    span.className = classes;
    span.textContent = text;
    parts.append(span);
  }
  code.replaceChildren(parts);
}

/** Colours the code of `root` that waits for it as it comes near the view, and all of it before printing. */
export function colourCodeWhenNear(root: ParentNode): void {
  const waiting = () => root.querySelectorAll(`code[${TOKENS_ATTRIBUTE}]`);
  if (typeof IntersectionObserver === 'undefined') {
    waiting().forEach(colourCode);
    return;
  }
  const observer = new IntersectionObserver(
    (entries) => {
      for (const entry of entries) {
        if (!entry.isIntersecting) continue;
        observer.unobserve(entry.target);
        colourCode(entry.target);
      }
    },
    { rootMargin: AHEAD },
  );
  waiting().forEach((code) => observer.observe(code));
  addEventListener('beforeprint', () => waiting().forEach(colourCode));
}
