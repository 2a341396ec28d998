/**
 * A chapter's text rendered as the book renders it, block by block: the
 * title from the front matter, then each top-level Markdown block as HTML,
 * math typeset by KaTeX (rehype-katex, as in astro.config.mjs) and each
 * cell as the build's own markup (site/lib/remark-cells.mjs renderCell), so
 * the book's cell machinery (cells/) runs on it unchanged.
 *
 * Blocks are rendered separately, with their source lines, so that the
 * preview can keep the blocks that did not change and scroll with the
 * editor; a block's HTML is cached by its source text.
 */
import type { Definition, Root, RootContent } from 'mdast';
import { toHtml } from 'hast-util-to-html';
import rehypeKatex from 'rehype-katex';
import remarkRehype from 'remark-rehype';
import remarkSmartypants from 'remark-smartypants';
import { unified } from 'unified';
import { assignCellIds, collectCells, renderCell } from '../../../site/lib/remark-cells.mjs';
import { splitChapter } from '../analyzer/chapter-text.ts';
import { parseChapterTree } from '../analyzer/chapter-tree.ts';
import { LineIndex } from '../analyzer/positions.ts';
import { prepareMdx } from './mdx-display.ts';

export interface Block {
  readonly html: string;
  /** Lines (from 0) of the file that the block comes from, first and last. */
  readonly line: number;
  readonly endLine: number;
}

export interface RenderedCell {
  readonly line: number;
  readonly endLine: number;
}

export interface RenderedChapter {
  readonly blocks: readonly Block[];
  /** Each cell's lines, by the id the page gives it. */
  readonly cells: ReadonlyMap<string, RenderedCell>;
}

const smartypants = unified().use(remarkSmartypants).freeze();
const toHast = unified().use(remarkRehype).use(rehypeKatex).freeze();

function escapeHtml(text: string): string {
  return text.replace(/[&<>"']/g, (c) => `&#${c.charCodeAt(0)};`);
}

/** Renders blocks, remembering the HTML of each block's source. */
export class ChapterRenderer {
  #cache = new Map<string, string>();

  render(text: string): RenderedChapter {
    const chapter = splitChapter(text);
    const lines = new LineIndex(text);
    const { tree, mdxError } = parseChapterTree(chapter.body);
    smartypants.runSync(tree);
    const cells = this.#replaceCells(tree);
    prepareMdx(tree);
    const definitions = tree.children.filter((node): node is Definition => node.type === 'definition');
    const cache = new Map<string, string>();
    const blocks: Block[] = [];

    const front = chapter.frontMatter;
    const title = front?.data && typeof front.data.title === 'string' ? front.data.title : null;
    const frontEnd = front ? lines.position(front.start + front.raw.length).line + 1 : 0;
    if (title) blocks.push({ html: `<h1>${escapeHtml(title)}</h1>`, line: 0, endLine: frontEnd });
    if (mdxError) {
      const { line } = lines.position(mdxError.offset);
      blocks.push({ html: `<p class="pb-preview-error">The book’s build fails on line ${line + 1}: ${escapeHtml(mdxError.message)}</p>`, line: 0, endLine: frontEnd });
    }
    for (const node of tree.children) {
      const start = node.position?.start.offset ?? 0;
      const end = node.position?.end.offset ?? start;
      const key = `${text.slice(start, end)}\u0000${cellIdsIn(node).join(' ')}\u0000${definitions.map((d) => `${d.identifier} ${d.url}`).join(' ')}`;
      const html = this.#cache.get(key) ?? toHtml(toHast.runSync({ type: 'root', children: [node, ...definitions] } as Root));
      cache.set(key, html);
      if (html.trim()) blocks.push({ html, line: lines.position(start).line, endLine: lines.position(end).line });
    }
    // Only the blocks of this text stay cached: the cache never outgrows the chapter.
    this.#cache = cache;
    return { blocks, cells };
  }

  /** Puts the build's cell markup in place of each cell fence, as remarkCells does; returns each cell's lines. */
  #replaceCells(tree: Root): Map<string, RenderedCell> {
    const found: Parameters<typeof collectCells>[1] = [];
    collectCells(tree, found);
    const ids = assignCellIds(found.map(({ analysis }) => ({ name: 'spec' in analysis ? analysis.spec.name : null })));
    const cells = new Map<string, RenderedCell>();
    found.forEach(({ parent, index, source, analysis }, i) => {
      const fence = parent.children[index];
      const element = renderCell(source, ids[i], analysis);
      parent.children[index] = {
        type: 'liveCell',
        position: fence.position,
        data: { hName: element.tagName, hProperties: element.properties, hChildren: element.children, cellId: ids[i] },
      } as unknown as RootContent;
      cells.set(ids[i], { line: (fence.position?.start.line ?? 1) - 1, endLine: (fence.position?.end.line ?? 1) - 1 });
    });
    return cells;
  }
}

/** The ids of the cells inside a block: its HTML depends on them. */
function cellIdsIn(node: RootContent): string[] {
  const data = (node as { data?: { cellId?: string } }).data;
  if (data?.cellId) return [data.cellId];
  return 'children' in node ? (node.children as RootContent[]).flatMap(cellIdsIn) : [];
}
