/**
 * Finding the cell behind an error that no cell's promise carries: an
 * exception thrown in a cell's timer or event handler, a promise it let
 * fail, a request the page's Content-Security-Policy blocked. cell-definition.ts
 * names each cell's code `cell:<id>` (sourceURL), so its frames in a stack,
 * and a CSP report's source file, say which cell it was.
 */

const CELL_FRAME = /\bcell:([^\s:)]+)/;

/** How long after a cell's code ran a report without a source is still taken to be its. */
const RECENT_MS = 2000;

let lastRun: { id: string; at: number } | null = null;

/** cell-definition.ts calls this each time a cell's code starts running. */
export function noteCellRun(id: string): void {
  lastRun = { id, at: performance.now() };
}

/**
 * The cell whose code ran last, if that was a moment ago: a blocked image or
 * beacon is reported by the browser without a source file, and is most
 * likely the doing of the code that just ran.
 */
export function recentCell(): string | null {
  return lastRun && performance.now() - lastRun.at < RECENT_MS ? lastRun.id : null;
}

/** The id of the cell named in a stack trace or a source file, or null. */
export function cellOfSource(text: string | null | undefined): string | null {
  const match = text ? CELL_FRAME.exec(text) : null;
  if (!match) return null;
  try {
    return decodeURIComponent(match[1]);
  } catch {
    return null;
  }
}

/** The stack of a thrown value, when it has one. */
export function stackOf(value: unknown): string | undefined {
  return value instanceof Error ? value.stack : undefined;
}

/** The line under a cell for a request the book's policy blocked. */
export function blockedMessage(url: string, directive: string): string {
  const what = directive.startsWith('img') ? 'an image' : directive.startsWith('script') ? 'a script' : directive.startsWith('font') ? 'a font' : 'a request';
  const where = /^https?:/.test(url) ? ` to ${new URL(url).host}` : url && url !== 'inline' ? ` (${url})` : '';
  return `Blocked: ${what}${where}. Cells may only reach this book's own site (its Content-Security-Policy, ${directive}).`;
}
