/**
 * Boxes that scroll sideways (display math, code wider than the column on a
 * phone) must be reachable by keyboard, or a keyboard reader cannot see
 * their end. Only boxes that do overflow become focusable: a tab stop on
 * every formula would be noise. Checked at start and whenever the column's
 * width changes.
 */
const SCROLLERS = '.katex-display, pre.cell-code';

function mark(box: HTMLElement): void {
  const overflows = box.scrollWidth > box.clientWidth + 1;
  if (overflows === box.hasAttribute('data-scrollable')) return;
  box.toggleAttribute('data-scrollable', overflows);
  if (overflows) {
    box.tabIndex = 0;
    if (!box.hasAttribute('aria-label')) box.setAttribute('aria-label', box.matches('.katex-display') ? 'Formula, scrolls sideways' : 'Code, scrolls sideways');
    box.dataset.scrollLabelled = '';
  } else if (!box.matches('pre.cell-code')) {
    // The build made code focusable on its own (it is also the editor's stand-in); formulas were made so here.
    box.removeAttribute('tabindex');
    if (box.dataset.scrollLabelled !== undefined) box.removeAttribute('aria-label');
  }
}

/** Marks the overflowing boxes of `root` now and after every change of its width. */
export function watchScrollables(root: HTMLElement): void {
  const all = () => root.querySelectorAll<HTMLElement>(SCROLLERS).forEach(mark);
  all();
  if (typeof ResizeObserver !== 'undefined') {
    let width = root.clientWidth;
    new ResizeObserver(() => {
      if (root.clientWidth === width) return;
      width = root.clientWidth;
      all();
    }).observe(root);
  }
}
