/**
 * Boxes that scroll sideways (display math, code wider than the column on a
 * phone) must be reachable by keyboard, or a keyboard reader cannot see
 * their end. Only boxes that do overflow become focusable: a tab stop on
 * every formula would be noise. Checked at start, whenever the column's
 * width changes, and when fonts finish loading.
 */
const SCROLLERS = '.katex-display, pre.cell-code, .cell-output';

/**
 * What a box that scrolls is called, for a screen reader: display math has
 * no name of its own. Regions need names that tell them apart, so each is
 * numbered by its place on the page.
 */
function labelOf(box: HTMLElement): string {
  const kind = box.matches('.katex-display') ? 'Formula' : 'Cell output';
  const index = [...document.querySelectorAll(box.matches('.katex-display') ? '.katex-display' : '.cell-output')].indexOf(box) + 1;
  return `${kind} ${index}, scrolls sideways`;
}

/** Makes `box` focusable and named if it overflows now, or undoes that if it no longer does. */
export function mark(box: HTMLElement): void {
  const overflows = box.scrollWidth > box.clientWidth + 1;
  if (overflows === box.hasAttribute('data-scrollable')) return;
  box.toggleAttribute('data-scrollable', overflows);
  if (overflows) {
    box.tabIndex = 0;
    // A named region: a span or div may carry a name only with a role. Code keeps the build's name and role.
    if (box.matches('pre.cell-code')) return;
    if (!box.hasAttribute('role')) box.setAttribute('role', 'region');
    if (!box.hasAttribute('aria-label')) {
      box.setAttribute('aria-label', labelOf(box));
      box.dataset.scrollLabelled = '';
    }
  } else if (!box.matches('pre.cell-code')) {
    // The build made code focusable on its own (it is also the editor's stand-in); the others were made so here.
    box.removeAttribute('tabindex');
    if (box.getAttribute('role') === 'region') box.removeAttribute('role');
    if (box.dataset.scrollLabelled !== undefined) box.removeAttribute('aria-label');
  }
}

/** Marks the overflowing boxes of `root` now, after every change of its width, and when fonts arrive. */
export function watchScrollables(root: HTMLElement): void {
  const all = () => root.querySelectorAll<HTMLElement>(SCROLLERS).forEach(mark);
  all();
  // A face requested by the first layout (KaTeX's, the code font's) may still be used if it arrives within
  // font-display: optional's short wait, after this first check: the text it sets is wider, and may overflow.
  document.fonts?.addEventListener?.('loadingdone', all);
  if (typeof ResizeObserver !== 'undefined') {
    let width = root.clientWidth;
    new ResizeObserver(() => {
      if (root.clientWidth === width) return;
      width = root.clientWidth;
      all();
    }).observe(root);
  }
}
