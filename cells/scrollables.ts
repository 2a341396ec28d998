/**
 * Boxes that scroll sideways (display math, a cell's output wider than the
 * column on a phone) must be reachable by keyboard, or a keyboard reader
 * cannot see their end. Only boxes that do overflow become focusable: a tab
 * stop on every formula would be noise. Checked after the first paint,
 * whenever the column's width changes, when fonts finish loading, and when
 * prose that was not laid out comes near the view.
 *
 * A cell's code is not among them: the build makes every code box focusable
 * and names it (site/lib/remark-cells.mjs), wide or not, since it is also
 * the editor's stand-in. Measuring it too laid out each far code box for
 * nothing, a forced layout apiece.
 */
const SCROLLERS = '.katex-display, .cell-output';

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

/** Whether `box` is wider inside than it shows: a read of the layout. */
function overflows(box: HTMLElement): boolean {
  return box.scrollWidth > box.clientWidth + 1;
}

/** Makes `box` focusable and named if it is `wide`, or undoes that if it no longer is: writes only. */
function apply(box: HTMLElement, wide: boolean): void {
  if (wide === box.hasAttribute('data-scrollable')) return;
  box.toggleAttribute('data-scrollable', wide);
  if (wide) {
    box.tabIndex = 0;
    // A named region: a span or div may carry a name only with a role.
    if (!box.hasAttribute('role')) box.setAttribute('role', 'region');
    if (!box.hasAttribute('aria-label')) {
      box.setAttribute('aria-label', labelOf(box));
      box.dataset.scrollLabelled = '';
    }
  } else {
    box.removeAttribute('tabindex');
    if (box.getAttribute('role') === 'region') box.removeAttribute('role');
    if (box.dataset.scrollLabelled !== undefined) box.removeAttribute('aria-label');
  }
}

/**
 * Boxes far from the view still need their marks: a keyboard reader tabs
 * through the page without bringing each formula into view first. Asking
 * for their content's geometry lays that content out for the reading, a few
 * milliseconds each, so it is done a few at a time while the page is idle,
 * and once: after the fonts have settled, since a width read in a fallback
 * face would have to be read again. A box that comes near the view later is
 * checked again anyway (contentvisibilityautostatechange).
 */
const hidden = new Set<HTMLElement>();

/**
 * Marks `boxes`: every width is read before any box is changed. Reading
 * after each change made the browser lay out the whole chapter once per
 * box (120 ms of a page's start on this machine, four times that on a slow
 * phone). A box whose content is not laid out joins the idle pass if
 * `queueFar` holds it; otherwise it is left for when it comes near the view.
 */
function markAll(boxes: readonly HTMLElement[], queueFar: ReadonlySet<HTMLElement>): void {
  const shown: HTMLElement[] = [];
  for (const box of boxes) {
    if (laidOut(box)) shown.push(box);
    else if (queueFar.has(box)) hidden.add(box);
  }
  const wide = shown.map(overflows);
  shown.forEach((box, i) => apply(box, wide[i]));
  if (hidden.size) markHiddenWhenIdle();
}

/** What is inside `box`: the box may be a block skipped far from the view itself, so its content is asked. */
function contentOf(box: HTMLElement): Element {
  return box.firstElementChild ?? box;
}

/**
 * Whether the content of `box` is laid out now: not in prose or code far
 * from the view (global.css), which measures as if it held nothing.
 */
function laidOut(box: HTMLElement): boolean {
  return contentOf(box).checkVisibility?.({ contentVisibilityAuto: true } as CheckVisibilityOptions) ?? true;
}

/** Whether a box far from the view overflows: its content is laid out for the reading, on its own. */
function overflowsFar(box: HTMLElement): boolean {
  contentOf(box).getBoundingClientRect();
  return overflows(box);
}

function markHidden(deadline: { timeRemaining(): number }): void {
  // Reads first, writes after: a change between two reads would make the second lay out the page's style again.
  // One box at least each time, even when the browser gives no idle time before the timeout.
  const read: [HTMLElement, boolean][] = [];
  for (const box of hidden) {
    hidden.delete(box);
    if (box.isConnected) read.push([box, overflowsFar(box)]);
    if (deadline.timeRemaining() < 2) break;
  }
  for (const [box, wide] of read) apply(box, wide);
  if (hidden.size) markHiddenWhenIdle();
}

let idleAsked = false;

function markHiddenWhenIdle(): void {
  if (idleAsked) return;
  idleAsked = true;
  const run = (deadline: { timeRemaining(): number }) => {
    idleAsked = false;
    markHidden(deadline);
  };
  // Fonts that have not settled yet would change what the idle pass reads: it waits for them.
  void (document.fonts?.ready ?? Promise.resolve()).then(() => {
    if (typeof requestIdleCallback === 'function') requestIdleCallback(run, { timeout: 2000 });
    else setTimeout(() => run({ timeRemaining: () => 8 }), 50);
  });
}

/** The boxes to mark after the next frame; those in `queueFar` join the idle pass if they are far from the view. */
const pending = new Set<HTMLElement>();
const pendingFar = new Set<HTMLElement>();

/**
 * Marks `box` just after the next frame is painted, together with every box
 * asked for until then. The layout is fresh at that moment, so reading it
 * costs nothing, and a page's start does not wait for a layout of its own.
 * `far`: a box far from the view is measured in the idle pass; without it,
 * only when it comes near.
 */
export function markSoon(box: HTMLElement, { far = true }: { far?: boolean } = {}): void {
  if (pending.size === 0) requestAnimationFrame(() => setTimeout(flush, 0));
  pending.add(box);
  if (far) pendingFar.add(box);
}

function flush(): void {
  const boxes = [...pending].filter((box) => box.isConnected);
  const far = new Set(pendingFar);
  pending.clear();
  pendingFar.clear();
  markAll(boxes, far);
}

/** Marks the overflowing boxes of `root` after the first paint, after every change of its width, and when fonts arrive. */
export function watchScrollables(root: HTMLElement): void {
  const all = () => root.querySelectorAll<HTMLElement>(SCROLLERS).forEach((box) => markSoon(box));
  all();
  // A face requested by the first layout (KaTeX's, the code font's) may still be used if it arrives within
  // font-display: optional's short wait, after this first check: the text it sets is wider, and may overflow.
  // Only the boxes laid out now are read again: the idle pass over the far ones waits for the fonts, and a
  // far box is read again when it comes near the view.
  document.fonts?.addEventListener?.('loadingdone', () =>
    root.querySelectorAll<HTMLElement>(SCROLLERS).forEach((box) => markSoon(box, { far: false })),
  );
  // Prose far from the view is not laid out (global.css, content-visibility), so its boxes measure nothing until
  // it is first shown. The event does not bubble; it reaches the root on the way down.
  root.addEventListener(
    'contentvisibilityautostatechange',
    (event) => {
      const block = event.target;
      if ((event as Event & { skipped?: boolean }).skipped || !(block instanceof HTMLElement)) return;
      if (block.matches(SCROLLERS)) markSoon(block);
      block.querySelectorAll<HTMLElement>(SCROLLERS).forEach((box) => markSoon(box));
    },
    { capture: true },
  );
  if (typeof ResizeObserver !== 'undefined') {
    // The width comes from the observer, which reports it after layout; asking the root would force one now.
    let width: number | undefined;
    new ResizeObserver(([entry]) => {
      const changed = width !== undefined && entry.contentRect.width !== width;
      width = entry.contentRect.width;
      if (changed) all();
    }).observe(root);
  }
}
