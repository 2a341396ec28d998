/**
 * The embed pages (site/pages/embed/[chapter]/[cell].astro): which cells of
 * a chapter can be embedded, and which cells each one needs beside it.
 * The graph comes from the build's parse of every cell (remark-cells.mjs,
 * front matter `cellGraph`).
 */

/** A cell as the build parsed it. */
export interface CellNode {
  readonly id: string;
  /** The name it defines, or null. */
  readonly name: string | null;
  /** The names it reads: other cells' and the builtins'. */
  readonly inputs: readonly string[];
  /** It calls a widget of the catalogue (widgets/catalogue.ts, WIDGET_NAMES). */
  readonly widget: boolean;
}

/** The cells that get an embed page: each that draws a widget. */
export function embeddableCells(graph: readonly CellNode[]): CellNode[] {
  return graph.filter((cell) => cell.widget);
}

/**
 * The ids of the cells `id` reads, directly or through others, in page
 * order: what must run beside it for its widget to draw. Names no cell
 * defines are builtins and need nothing.
 */
export function cellsUsedBy(graph: readonly CellNode[], id: string): string[] {
  const byName = new Map(graph.flatMap((cell) => (cell.name ? [[cell.name, cell] as const] : [])));
  const needed = new Set<string>();
  const visit = (cell: CellNode): void => {
    for (const input of cell.inputs) {
      const source = byName.get(input);
      if (!source || source.id === id || needed.has(source.id)) continue;
      needed.add(source.id);
      visit(source);
    }
  };
  const target = graph.find((cell) => cell.id === id);
  if (target) visit(target);
  return graph.filter((cell) => needed.has(cell.id)).map((cell) => cell.id);
}

/** The embed page of a cell, under the site's base (`/course/`): `/course/embed/<chapter>/<cell>/`. */
export function embedPath(base: string, chapter: string, cell: string): string {
  return `${base.replace(/\/?$/, '/')}embed/${chapter}/${cell}/`;
}

/**
 * The element that opens at `start` in `html`, whole: up to the close tag of
 * the same name that balances it (the book's own markup, which closes every
 * element it opens).
 */
function elementAt(html: string, start: number, tag: string): string {
  const tags = new RegExp(`<(/?)${tag}\\b[^>]*>`, 'gi');
  tags.lastIndex = start;
  let depth = 0;
  for (let m = tags.exec(html); m; m = tags.exec(html)) {
    depth += m[1] ? -1 : 1;
    if (depth === 0) return html.slice(start, m.index + m[0].length);
  }
  throw new Error(`embeds: <${tag}> at ${start} is never closed`);
}

/** The markup of the cell `id` (its `<figure data-cell>`), or null when the chapter has none. */
function cellMarkup(html: string, id: string): string | null {
  const at = html.search(new RegExp(`<figure\\b[^>]*\\sdata-cell="${id.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')}"`));
  return at < 0 ? null : elementAt(html, at, 'figure');
}

/** What an embed page takes of its chapter's rendered HTML: the widget's cell, the cells it reads, and the build's data for the page. */
export interface EmbedParts {
  readonly widget: string;
  readonly uses: string;
  readonly data: string;
}

/**
 * Cuts an embed page out of its chapter as the build rendered it: the
 * cell `id`, the cells in `uses` (in their order), and every `<template>`,
 * which in a chapter's markup holds the build's data for the page (the
 * compiled models, remark-cells.mjs).
 * The prose and every other cell are left out, so the page ships and runs
 * only what its widget needs.
 */
export function embedParts(html: string, id: string, uses: readonly string[]): EmbedParts {
  const widget = cellMarkup(html, id);
  if (widget === null) throw new Error(`embeds: the chapter has no cell "${id}"`);
  const data = [...html.matchAll(/<template\b/g)].map((m) => elementAt(html, m.index, 'template'));
  return { widget, uses: uses.map((used) => cellMarkup(html, used) ?? '').join(''), data: data.join('') };
}
