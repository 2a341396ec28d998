import './book.css';
import type { Model } from '../core/types.ts';

type Katex = typeof import('katex');
let katex: Promise<Katex> | undefined;
// KaTeX's renderer is large and only cells that typeset a live H need it; the page's own math is rendered at build time.
const loadKatex = () => (katex ??= import('katex').then((m) => (m as unknown as { default?: Katex }).default ?? m));

/** LaTeX typeset into an element (display math by default). */
export async function tex(source: string, options: { display?: boolean } = {}): Promise<HTMLElement> {
  const { renderToString } = await loadKatex();
  const root = document.createElement(options.display === false ? 'span' : 'div');
  root.className = 'pb-tex';
  root.innerHTML = renderToString(String(source), { displayMode: options.display !== false, throwOnError: false, output: 'html' });
  return root;
}

/**
 * H and the Hamilton equations the core derived from it, typeset: what the
 * reader wrote, and what the simulator integrates.
 */
export async function equations(model: Model | Promise<Model>): Promise<HTMLElement> {
  const m = await model;
  const root = document.createElement('div');
  root.className = 'pb-equations';
  root.dataset.widget = 'equations';
  if (!m.latex) {
    root.textContent = `This model's ${m.route === 'js-stencil' ? 'H is an opaque function' : 'equations are given directly'}, so there is nothing to typeset.`;
    root.dataset.ready = '';
    return root;
  }
  const { hamiltonian, equations: eqs } = m.latex;
  const body = `\\begin{aligned} ${hamiltonian.replace('=', '&=')} \\\\ ${eqs.map((e) => e.replace(/ = /, ' &= ')).join(' \\\\ ')} \\end{aligned}`;
  root.append(await tex(body));
  const note = document.createElement('p');
  note.className = 'pb-equations-note';
  note.textContent = m.accuracy.charAt(0).toUpperCase() + m.accuracy.slice(1) + '.';
  root.append(note);
  root.dataset.ready = '';
  return root;
}
