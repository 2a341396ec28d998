/**
 * Scrolling the preview with the editor and back. The host says which line
 * is at the top of the editor; the preview reports the line at its top as
 * the reader scrolls it, except while it follows the editor.
 */
import type { BlockList } from './block-list.ts';
import { lineAtOffset, offsetOfLine, type BlockBox } from './scroll-map.ts';

/** Scroll events within this time of following the editor are the preview's own. */
const FOLLOW_MS = 200;

export class ScrollSync {
  readonly #blocks: BlockList;
  #followingUntil = 0;
  #scheduled = false;

  constructor(blocks: BlockList, report: (line: number) => void) {
    this.#blocks = blocks;
    addEventListener('scroll', () => {
      if (performance.now() < this.#followingUntil || this.#scheduled) return;
      this.#scheduled = true;
      requestAnimationFrame(() => {
        this.#scheduled = false;
        const line = lineAtOffset(this.#boxes(), scrollY);
        if (line !== null) report(line);
      });
    }, { passive: true });
  }

  /** Shows `line` of the source at the top of the preview. */
  reveal(line: number): void {
    this.#followingUntil = performance.now() + FOLLOW_MS;
    scrollTo({ top: Math.max(0, offsetOfLine(this.#boxes(), line)), behavior: 'instant' });
  }

  #boxes(): BlockBox[] {
    return this.#blocks.wrappers.map((element) => {
      const box = element.getBoundingClientRect();
      return { line: Number(element.dataset.line), endLine: Number(element.dataset.endLine), top: box.top + scrollY, height: box.height };
    });
  }
}
