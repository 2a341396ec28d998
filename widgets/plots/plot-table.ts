import type { TableData } from './table-data.ts';

/** Milliseconds between refreshes of an open table (and of a plot's text alternative): slower than frames, fast enough to follow. */
export const TEXT_INTERVAL_MS = 500;

let serial = 0;

/**
 * A plot's data-table view: a "Table" toggle button (aria-expanded) and
 * the table it shows, an HTML <table> with a caption and column headers a
 * screen reader can walk. While open it is refreshed at most every half
 * second from `data()`, never per frame; closed, it costs nothing.
 */
export class PlotTable {
  readonly button: HTMLButtonElement;
  readonly element: HTMLDivElement;
  private readonly table: HTMLTableElement;
  private last = -Infinity;

  constructor(
    private readonly name: string,
    private readonly data: () => TableData | null,
  ) {
    const id = `pb-table-${++serial}`;
    this.button = document.createElement('button');
    this.button.type = 'button';
    this.button.className = 'pb-button pb-small pb-table-toggle';
    this.button.textContent = 'Table';
    this.button.setAttribute('aria-expanded', 'false');
    this.button.setAttribute('aria-controls', id);
    this.button.setAttribute('aria-label', `Show the ${name} as a table`);
    this.element = document.createElement('div');
    this.element.id = id;
    this.element.className = 'pb-plot-table';
    this.element.hidden = true;
    // Wide tables scroll sideways, so the box must be reachable by keyboard.
    this.element.tabIndex = 0;
    this.element.setAttribute('role', 'region');
    this.element.setAttribute('aria-label', `${name}: data table`);
    this.table = document.createElement('table');
    this.element.append(this.table);
    this.button.addEventListener('click', () => this.toggle());
  }

  get open(): boolean {
    return !this.element.hidden;
  }

  toggle(open = !this.open): void {
    this.element.hidden = !open;
    this.button.setAttribute('aria-expanded', String(open));
    this.button.setAttribute('aria-label', `${open ? 'Hide' : 'Show'} the ${this.name} as a table`);
    if (open) this.refresh(true);
  }

  /** Rewrites the table if it is open and was not rewritten in the last half second (or `force`). */
  refresh(force = false): void {
    if (!this.open) return;
    const now = performance.now();
    if (!force && now - this.last < TEXT_INTERVAL_MS) return;
    this.last = now;
    const data = this.data();
    if (!data) {
      this.table.replaceChildren(caption('Nothing to show yet.'));
      return;
    }
    const head = document.createElement('thead');
    const headRow = head.insertRow();
    for (const h of data.head) {
      const th = document.createElement('th');
      th.scope = 'col';
      th.textContent = h;
      headRow.append(th);
    }
    const body = document.createElement('tbody');
    for (const row of data.rows) {
      const tr = body.insertRow();
      row.forEach((cell, i) => {
        const td = document.createElement(i === 0 ? 'th' : 'td');
        if (i === 0) (td as HTMLTableCellElement).scope = 'row';
        td.textContent = cell;
        tr.append(td);
      });
    }
    this.table.replaceChildren(caption(data.caption), head, body);
  }
}

function caption(text: string): HTMLTableCaptionElement {
  const c = document.createElement('caption');
  c.textContent = text;
  return c;
}
