/**
 * Cells a reader adds to a chapter ("add a cell `lambda = …`", as the
 * adiabatic-invariants chapter asks). An added cell is made from a
 * chapter cell's own markup (the build's, remark-cells.mjs), emptied: one
 * way to build a cell, whichever made it. It runs, saves, and is offered
 * after a freeze like any cell; its Reset deletes it. The list of added
 * cells and where they go is kept with the reader's edits (storage.ts).
 */
import type { CellSpec } from './spec.ts';

/** The spec of an empty cell: what an added cell is before the reader types. */
const EMPTY: CellSpec = { name: null, inputs: [], async: false, generator: false, body: [0, 0], block: false, loops: [] };

/** A fresh id for an added cell: never a chapter cell's (those are names or cell-N). */
export function addedCellId(): string {
  const bytes = new Uint8Array(4);
  crypto.getRandomValues(bytes);
  return `added-${Array.from(bytes, (b) => b.toString(16).padStart(2, '0')).join('')}`;
}

/** An empty cell with id `id`, built from `template` (any cell of the page), not yet on the page. */
export function addedCellElement(template: HTMLElement, id: string): HTMLElement {
  const root = template.cloneNode(true) as HTMLElement;
  for (const attribute of [...root.attributes]) {
    if (attribute.name.startsWith('data-cell')) root.removeAttribute(attribute.name);
  }
  root.id = `cell-${id}`;
  root.dataset.cell = id;
  root.dataset.cellHash = 'added';
  root.dataset.cellSpec = JSON.stringify(EMPTY);
  root.toggleAttribute('data-cell-added', true);
  // The build's code, or an editor the template had mounted, gives way to an empty <pre>.
  const host = root.querySelector('.cell-editor');
  const code = template.querySelector('pre.cell-code')?.cloneNode(false) as HTMLElement | null;
  const inner = document.createElement('code');
  inner.className = template.querySelector('pre.cell-code > code')?.className ?? '';
  if (host) host.replaceChildren(...(code ? [code] : []));
  code?.append(inner);
  code?.setAttribute('aria-label', 'Code cell of your own');
  for (const selector of ['[data-cell-output]', '[data-cell-error]', '[data-cell-notice]', '[data-cell-status]', '[data-cell-activity]']) {
    root.querySelector(selector)?.replaceChildren();
  }
  root.querySelector<HTMLElement>('[data-cell-error]')!.hidden = true;
  root.querySelector<HTMLElement>('[data-cell-notice]')!.hidden = true;
  const reset = root.querySelector<HTMLButtonElement>('[data-cell-reset]');
  if (reset) {
    reset.textContent = 'Delete';
    reset.title = 'Delete this cell of yours';
    reset.disabled = false;
  }
  return root;
}
