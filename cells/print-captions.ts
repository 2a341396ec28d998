/**
 * Captions for paper. On screen a widget is its own caption: it sits in its
 * cell, which the reader can edit. On paper the reader needs to know what
 * the figure is and where it lives, so each widget gets a caption (shown
 * only in print, site/styles/print.css): "Figure N. <its label>" and the
 * absolute address of its live cell, printed as text, to type or scan.
 *
 * Written just before printing, since only then are the widgets there and
 * the page's address known (a static host may be anywhere).
 */

/** The mark of a caption this module wrote. */
export const PRINT_CAPTION_CLASS = 'cell-print-caption';

/** Widgets that are figures: a typeset formula is part of the text, not a figure. */
const FIGURE = '[data-cell-output] [data-widget]:not([data-widget="equations"])';

/** What the widget calls itself: its label, as it gives it to screen readers or draws it. */
function labelOf(widget: HTMLElement, cell: HTMLElement): string {
  const label =
    widget.getAttribute('aria-label') ??
    widget.dataset.label ??
    widget.querySelector('[aria-label]')?.getAttribute('aria-label') ??
    widget.querySelector('figcaption, caption, strong')?.textContent;
  return label?.trim() || `Cell ${cell.dataset.cellName ?? cell.dataset.cell ?? ''}`.trim();
}

/**
 * Captions every cell of `root` that shows a figure, numbered in page order, with the absolute link to
 * the cell on `page` (the page's address); a cell no longer showing one loses its caption.
 */
export function captionFigures(root: ParentNode, page: string): void {
  let number = 0;
  for (const cell of root.querySelectorAll<HTMLElement>('[data-cell]')) {
    const old = [...cell.children].find((child) => child.classList.contains(PRINT_CAPTION_CLASS));
    const widget = cell.querySelector<HTMLElement>(FIGURE);
    if (!widget) {
      old?.remove();
      continue;
    }
    number++;
    const link = new URL(`#${cell.id}`, page).href;
    const caption = document.createElement('figcaption');
    caption.className = PRINT_CAPTION_CLASS;
    const anchor = document.createElement('a');
    anchor.href = link;
    anchor.textContent = link;
    caption.append(`Figure ${number}. ${labelOf(widget, cell)}. Live: `, anchor);
    if (old) old.replaceWith(caption);
    else cell.append(caption);
  }
}
