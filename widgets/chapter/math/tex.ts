/**
 * Typeset math for cells: `tex(latex)` and `equations(model)`. A formula the
 * build already typeset (page-data.ts) is taken from the page's table; only
 * a new one, such as the equations of a reader's own H, loads KaTeX.
 */
import type { Model } from '../../../core/index.ts';
import { equationsHtml, equationsLatex, katexOptions, texHtml, typesetKey } from './typeset.ts';

type Katex = typeof import('katex');
let katex: Promise<Katex> | undefined;
const loadKatex = () => (katex ??= import('katex').then((m) => (m as unknown as { default?: Katex }).default ?? m));

/** One element from markup that makes exactly one. */
function element(markup: string): HTMLElement {
  const template = document.createElement('template');
  template.innerHTML = markup;
  return template.content.firstElementChild as HTMLElement;
}

/** A formula the build typeset into a cell's output (see typeset.ts texHtml), by its LaTeX. */
function onPage(source: string, display: boolean): string | undefined {
  for (const found of document.querySelectorAll<HTMLElement>(`${display ? 'div' : 'span'}.pb-tex[data-tex-source]`)) {
    if (found.dataset.texSource === source) return found.innerHTML;
  }
  return undefined;
}

/** The book's typesetting, with the page's table of what the build typeset. */
export function typesetting(table: ReadonlyMap<string, string>) {
  /** KaTeX's HTML for `source`: from the table or the page when the build typeset it, else from KaTeX. */
  async function typeset(source: string, display: boolean): Promise<string> {
    const known = table.get(typesetKey(source, display)) ?? onPage(source, display);
    if (known !== undefined) return known;
    const { renderToString } = await loadKatex();
    return renderToString(source, katexOptions(display));
  }

  /** LaTeX typeset into an element (display math by default). */
  async function tex(source: string, options: { display?: boolean } = {}): Promise<HTMLElement> {
    const display = options.display !== false;
    const text = String(source);
    return element(texHtml(await typeset(text, display), display, text));
  }

  /**
   * H and the Hamilton equations the core derived from it, typeset: what the
   * reader wrote, and what the simulator integrates.
   */
  async function equations(model: Model | Promise<Model>): Promise<HTMLElement> {
    const m = await model;
    if (!m.latex) {
      const root = document.createElement('div');
      root.className = 'pb-equations';
      root.dataset.widget = 'equations';
      root.textContent = `This model's ${m.route === 'js-stencil' ? 'H is an opaque function' : 'equations are given directly'}, so there is nothing to typeset.`;
      root.dataset.ready = '';
      return root;
    }
    const source = equationsLatex(m.latex);
    return element(equationsHtml(source, await typeset(source, true), m.accuracy));
  }

  return { tex, equations };
}
