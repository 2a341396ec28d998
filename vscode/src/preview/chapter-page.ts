/**
 * The previewed chapter in the webview: renders each new text of the
 * chapter into its blocks, gives each cell a PreviewCell in one notebook
 * with the book's builtins and widgets (widgets/catalogue.ts, with no build
 * data: models compile and formulas typeset here, as for a reader's edit),
 * and keeps every cell whose code is unchanged — its value, its widget and
 * the widget's state — across renders.
 */
import { pageContext, createLibrary } from '../../../widgets/index.ts';
import { createBuiltins, currentCellSignal, Notebook } from '../../../cells/index.ts';
import type { CellReport, CheckResult, PreviewMessage } from '../shared/messages.ts';
import { BlockList } from './block-list.ts';
import { readChecks } from './checks.ts';
import { PreviewCell } from './preview-cell.ts';
import { ChapterRenderer, type RenderedCell } from './render.ts';

/** Cell states are reported at most this often (a simulator's cells settle together). */
const REPORT_DELAY_MS = 100;

export class ChapterPage {
  readonly blocks: BlockList;
  readonly #post: (message: PreviewMessage) => void;
  readonly #notebook: Notebook;
  readonly #renderer = new ChapterRenderer();
  readonly #cells = new Map<string, PreviewCell>();
  #lines = new Map<string, RenderedCell>();
  #version = -1;
  #reportTimer: ReturnType<typeof setTimeout> | undefined;

  constructor(article: HTMLElement, post: (message: PreviewMessage) => void) {
    this.#post = post;
    this.blocks = new BlockList(article);
    this.#notebook = new Notebook(createBuiltins(article, createLibrary(pageContext([]), currentCellSignal)));
  }

  render(version: number, text: string): void {
    this.#version = version;
    const rendered = this.#renderer.render(text);
    this.#lines = new Map(rendered.cells);
    const { made } = this.blocks.apply(rendered.blocks);
    const report = { kept: [] as string[], created: [] as string[], changed: [] as string[], removed: [] as string[] };
    const present = new Set<string>();
    for (const figure of made.flatMap((wrapper) => [...wrapper.querySelectorAll<HTMLElement>('figure[data-cell]')])) {
      const id = figure.dataset.cell ?? '';
      present.add(id);
      const live = this.#cells.get(id);
      if (live) {
        report[live.adopt(figure) === 'kept' ? 'kept' : 'changed'].push(id);
      } else {
        this.#cells.set(id, new PreviewCell(figure, this.#notebook, () => this.#scheduleReport()));
        report.created.push(id);
      }
    }
    for (const [id, cell] of this.#cells) {
      if (present.has(id)) continue;
      if (rendered.cells.has(id) && cell.root.isConnected) {
        report.kept.push(id);
        continue;
      }
      cell.dispose();
      this.#cells.delete(id);
      report.removed.push(id);
    }
    this.#post({ type: 'rendered', version, ...report });
    this.#scheduleReport();
  }

  /** The line (from 0) of a cell's opening fence in the text last rendered. */
  lineOf(id: string): number | undefined {
    return this.#lines.get(id)?.line;
  }

  /** Runs one cell (by id) or all, and brings it into view. */
  run(id: string | null): void {
    const cells = id === null ? [...this.#cells.values()] : [this.#cells.get(id)].filter((c) => c !== undefined);
    for (const cell of cells) cell.run();
    cells[0]?.root.scrollIntoView({ block: 'nearest' });
    for (const cell of cells) {
      cell.root.classList.remove('pb-preview-ran');
      void cell.root.offsetWidth;
      cell.root.classList.add('pb-preview-ran');
    }
  }

  checks(ids: readonly string[], timeoutMs: number): Promise<CheckResult[]> {
    return readChecks(this.#cells, ids, timeoutMs);
  }

  /** Every cell's state and own error, with its lines, for the host's runtime diagnostics. */
  #scheduleReport(): void {
    clearTimeout(this.#reportTimer);
    this.#reportTimer = setTimeout(() => {
      const cells: CellReport[] = [...this.#cells].flatMap(([id, cell]) => {
        const lines = this.#lines.get(id);
        return lines ? [{ id, line: lines.line, endLine: lines.endLine, state: cell.state, ...(cell.error ? { error: cell.error } : {}) }] : [];
      });
      this.#post({ type: 'cells', version: this.#version, cells });
    }, REPORT_DELAY_MS);
  }
}
