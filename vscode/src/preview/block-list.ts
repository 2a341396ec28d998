/**
 * The preview's blocks in the page, each in a wrapper that carries its
 * source lines. Applying a new list keeps every wrapper whose HTML is
 * unchanged (it is moved if need be, never rebuilt), makes the others from
 * their HTML and removes the rest, so prose edits leave the widgets of
 * unchanged cells exactly as they were.
 */
import type { Block } from './render.ts';

const html = new WeakMap<Element, string>();

export interface AppliedBlocks {
  /** The wrappers made from HTML in this application; cells inside them need adopting. */
  readonly made: readonly HTMLElement[];
  /** Wrappers taken out of the page; live cells inside them may be adopted by a made one. */
  readonly removed: readonly HTMLElement[];
}

function wrapper(block: Block): HTMLElement {
  const element = document.createElement('div');
  element.className = 'pb-block';
  element.innerHTML = block.html;
  html.set(element, block.html);
  return element;
}

export class BlockList {
  readonly #container: HTMLElement;

  constructor(container: HTMLElement) {
    this.#container = container;
  }

  /** The wrappers in page order, with their lines. */
  get wrappers(): HTMLElement[] {
    return [...this.#container.children].filter((e): e is HTMLElement => e instanceof HTMLElement && html.has(e));
  }

  apply(blocks: readonly Block[]): AppliedBlocks {
    const old = new Map<string, HTMLElement[]>();
    for (const element of this.wrappers) old.set(html.get(element)!, [...(old.get(html.get(element)!) ?? []), element]);
    const made: HTMLElement[] = [];
    const wanted = blocks.map((block) => {
      const kept = old.get(block.html)?.shift();
      const element = kept ?? wrapper(block);
      if (!kept) made.push(element);
      element.dataset.line = String(block.line);
      element.dataset.endLine = String(block.endLine);
      return element;
    });
    wanted.forEach((element, i) => {
      const at = this.#container.children[i] ?? null;
      if (at !== element) this.#container.insertBefore(element, at);
    });
    const removed: HTMLElement[] = [];
    while (this.#container.children.length > wanted.length) {
      const extra = this.#container.lastElementChild as HTMLElement;
      extra.remove();
      removed.push(extra);
    }
    return { made, removed };
  }
}
