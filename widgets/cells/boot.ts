/**
 * Starts the live cells of a chapter page. Imported by
 * src/components/Cells.astro on pages that have cells.
 *
 * Finds the chapter root (`[data-chapter="<slug>"]`) and its cells
 * (`[data-cell]`, see src/lib/remark-cells.mjs), and defines them in one
 * notebook as they are wanted (schedule.ts): the cells near the view and
 * what they read at once, the rest as the reader scrolls. `data-cells-ready`
 * on <body> says that every cell wanted at first has shown its first value
 * or error, `data-cells-complete` that every cell of the page has. Editors load when the reader first touches a
 * cell (lazy.ts). The build's compiled models and typeset equations come
 * from the page's data element (book/page-data.ts).
 */
import { PAGE_DATA_ATTRIBUTE, pageContext } from '../book/page-data.ts';
import { createLibrary, prefetchWidgets } from '../library.ts';
import { createBuiltins } from './builtins.ts';
import { LiveCell } from './cell.ts';
import { Notebook } from './runtime.ts';
import { CellScheduler } from './schedule.ts';
import { EditStore } from './storage.ts';
import { CellView } from './view.ts';

function markReady(): void {
  document.body.dataset.cellsReady = '';
  document.dispatchEvent(new CustomEvent('phasebook:cells-ready'));
}

function markComplete(): void {
  document.body.dataset.cellsComplete = '';
}

function boot(): void {
  const root = document.querySelector<HTMLElement>('[data-chapter]');
  if (!root) return;
  const store = new EditStore(root.dataset.chapter ?? '');
  const data = [...document.querySelectorAll(`template[${PAGE_DATA_ATTRIBUTE}]`)].map((t) => t.getAttribute(PAGE_DATA_ATTRIBUTE));
  const page = pageContext(data, () => {
    document.dispatchEvent(new CustomEvent('phasebook:compiling'));
  });
  const notebook = new Notebook(createBuiltins(root, createLibrary(page)));
  const scheduler = new CellScheduler(markReady, markComplete, (cell) => prefetchWidgets(cell.root));
  const cells: LiveCell[] = [];
  for (const element of root.querySelectorAll<HTMLElement>('[data-cell]')) {
    try {
      const cell: LiveCell = new LiveCell(new CellView(element), notebook, store, {
        onFirstResult: () => scheduler.firstResult(cell),
        onDefine: (spec) => scheduler.wantInputs(spec.inputs),
      });
      cells.push(cell);
      scheduler.add(cell);
    } catch (error) {
      // Markup the build did not produce (hand-edited HTML?): skip this cell, keep the others.
      console.error(error);
    }
  }
  // A page being printed shows every cell's output.
  addEventListener('beforeprint', () => cells.forEach((cell) => scheduler.want(cell)));
  scheduler.watch(cells);
}

boot();
