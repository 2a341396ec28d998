/**
 * Starts the live cells of a chapter page. Imported by
 * src/components/Cells.astro on pages that have cells.
 *
 * Finds the chapter root (`[data-chapter="<slug>"]`) and its cells
 * (`[data-cell]`, see src/lib/remark-cells.mjs), defines them all in one
 * notebook, and sets `data-cells-ready` on <body> once every cell has shown
 * its first value or error. Editors load later (lazy.ts).
 */
import { createBuiltins } from './builtins.ts';
import { LiveCell } from './cell.ts';
import { scheduleIdle } from './lazy.ts';
import { Notebook } from './runtime.ts';
import { EditStore } from './storage.ts';
import { CellView } from './view.ts';

function markReady(cells: readonly LiveCell[]): void {
  document.body.dataset.cellsReady = '';
  document.dispatchEvent(new CustomEvent('phasebook:cells-ready'));
  scheduleIdle(cells.map((cell) => () => cell.mountWhenIdle()));
}

function boot(): void {
  const root = document.querySelector<HTMLElement>('[data-chapter]');
  if (!root) return;
  const store = new EditStore(root.dataset.chapter ?? '');
  const notebook = new Notebook(createBuiltins(root));
  const elements = [...root.querySelectorAll<HTMLElement>('[data-cell]')];

  let waiting = elements.length;
  const cells: LiveCell[] = [];
  const onFirstResult = () => {
    waiting -= 1;
    if (waiting === 0) markReady(cells);
  };
  for (const element of elements) {
    try {
      cells.push(new LiveCell(new CellView(element), notebook, store, onFirstResult));
    } catch (error) {
      // Markup the build did not produce (hand-edited HTML?): skip this cell, keep the others.
      console.error(error);
      onFirstResult();
    }
  }
  if (elements.length === 0) markReady(cells);
  for (const cell of cells) void cell.start();
}

boot();
