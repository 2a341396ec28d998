/**
 * What typeset math looks like, shared by the build (which typesets the
 * equations a chapter's cells show, ahead of the reader) and the page (which
 * typesets only what the build could not know, such as a reader's new H).
 * No DOM and no KaTeX here: only the LaTeX, KaTeX's options and the markup
 * around its output, so both halves produce identical HTML.
 */

/** LaTeX of H and of Hamilton's equations, as a model carries it. */
export interface ModelLatex {
  readonly hamiltonian: string;
  readonly equations: readonly string[];
}

/** KaTeX's options for a display (block) or inline formula. */
export function katexOptions(display: boolean) {
  return { displayMode: display, throwOnError: false, output: 'html' } as const;
}

/** The key of a typeset formula in a page's table of typeset HTML. */
export function typesetKey(source: string, display: boolean): string {
  return `${display ? 'display' : 'inline'}:${source}`;
}

/** H and Hamilton's equations as one aligned block, `H = …` first. */
export function equationsLatex(latex: ModelLatex): string {
  const lines = [latex.hamiltonian.replace('=', '&='), ...latex.equations.map((e) => e.replace(/ = /, ' &= '))];
  return `\\begin{aligned} ${lines.join(' \\\\ ')} \\end{aligned}`;
}

/** The sentence under the equations: how exact they are, from the model's accuracy. */
export function accuracyNote(accuracy: string): string {
  return `${accuracy.charAt(0).toUpperCase()}${accuracy.slice(1)}.`;
}

function escapeHtml(text: string): string {
  return text.replace(/[&<>"']/g, (c) => `&#${c.charCodeAt(0)};`);
}

/**
 * A typeset formula's element, `<div class="pb-tex">` (display) or `<span>`.
 * It carries its LaTeX, so that a formula the build put on the page can be
 * found there by a cell that shows it again (see tex.ts), and read by tools.
 */
export function texHtml(typeset: string, display: boolean, source: string): string {
  const tag = display ? 'div' : 'span';
  return `<${tag} class="pb-tex" data-tex-source="${escapeHtml(source)}">${typeset}</${tag}>`;
}

/** The whole `equations(model)` widget as markup, from its LaTeX, the typeset block and the accuracy note. */
export function equationsHtml(source: string, typesetBlock: string, accuracy: string): string {
  return `<div class="pb-equations" data-widget="equations" data-ready="">${texHtml(typesetBlock, true, source)}`
    + `<p class="pb-equations-note">${escapeHtml(accuracyNote(accuracy))}</p></div>`;
}
