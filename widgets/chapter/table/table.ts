/**
 * table({columns, rows, caption}): a table of numbers for a chapter, styled
 * by the book (book.css), so a cell holds only what the table shows.
 *
 * - Numbers are shown as the inspector shows them (table-format.ts).
 * - A highlighted column is the one the text asks the reader to watch.
 * - On a narrow screen the table keeps every column and scrolls sideways
 *   inside its box, which then says so (shadows at the edge that has more)
 *   and becomes a focusable, named region, so a keyboard can scroll it.
 * - `rows` (and `caption`) may be functions: the table reads them again every
 *   `refresh` seconds and updates in place, keeping the reader's scroll
 *   position (it never narrows, and a reader scrolled to its end stays
 *   there), until it leaves the page (a live readout of a simulator).
 */
import { cellText, checkRows, headerText, resolveColumns, type ResolvedColumn, type TableOptions } from './table-format.ts';

export type { TableColumnOptions, TableOptions } from './table-format.ts';

const OPTION_KEYS = new Set(['columns', 'rows', 'caption', 'label', 'refresh']);

function headerRow(columns: readonly ResolvedColumn[]): HTMLTableRowElement {
  const tr = document.createElement('tr');
  for (const c of columns) {
    const th = document.createElement('th');
    th.scope = 'col';
    th.textContent = headerText(c);
    if (c.highlight) th.classList.add('pb-highlight');
    tr.append(th);
  }
  return tr;
}

function bodyRows(rows: readonly (readonly unknown[])[], columns: readonly ResolvedColumn[]): HTMLTableRowElement[] {
  return rows.map((row) => {
    const tr = document.createElement('tr');
    columns.forEach((c, i) => {
      const value = row[i];
      // A row's name in the first column heads the row, for a screen reader.
      const heading = i === 0 && typeof value === 'string';
      const td = document.createElement(heading ? 'th' : 'td');
      if (heading) td.setAttribute('scope', 'row');
      td.textContent = cellText(value, c);
      if (typeof value === 'number') td.classList.add('pb-number');
      if (c.highlight) td.classList.add('pb-highlight');
      tr.append(td);
    });
    return tr;
  });
}

/** Makes the box a focusable, named region while its table is wider than it, and back when not. */
function markScrolling(box: HTMLElement, name: string): void {
  const overflows = box.scrollWidth > box.clientWidth + 1;
  if (overflows === box.hasAttribute('data-scrollable')) return;
  box.toggleAttribute('data-scrollable', overflows);
  if (overflows) {
    box.tabIndex = 0;
    box.setAttribute('role', 'region');
    box.setAttribute('aria-label', `${name}, scrolls sideways`);
  } else {
    box.removeAttribute('tabindex');
    box.removeAttribute('role');
    box.removeAttribute('aria-label');
  }
}

export function table(options: TableOptions): HTMLElement {
  if (typeof options !== 'object' || options === null) throw new Error("table: give an options object, e.g. table({columns: ['x', 'y'], rows: [[1, 2]]})");
  const extra = Object.keys(options).filter((k) => !OPTION_KEYS.has(k));
  if (extra.length) throw new Error(`table: no option ${extra.map((k) => `'${k}'`).join(', ')} (it takes ${[...OPTION_KEYS].join(', ')})`);
  const columns = resolveColumns(options.columns);
  const live = typeof options.rows === 'function' || typeof options.caption === 'function';
  const refresh = options.refresh ?? 0.25;
  if (!(typeof refresh === 'number' && refresh >= 0.05 && refresh <= 3600)) throw new Error('table: refresh must be a number of seconds from 0.05 to 3600');
  const read = () => ({
    rows: checkRows(typeof options.rows === 'function' ? options.rows() : options.rows, columns),
    caption: typeof options.caption === 'function' ? String(options.caption()) : options.caption,
  });
  const first = read();

  const box = document.createElement('div');
  box.className = 'pb-table';
  box.dataset.widget = 'table';
  box.dataset.ready = '';
  const el = document.createElement('table');
  const caption = document.createElement('caption');
  const head = document.createElement('thead');
  const body = document.createElement('tbody');
  head.append(headerRow(columns));
  el.append(...(first.caption !== undefined ? [caption] : []), head, body);
  box.append(el);
  const name = options.label ?? first.caption ?? `Table of ${columns.map((c) => c.label).join(', ')}`;

  /** The widest the live table has been laid out, px: it never narrows again (see keepPlace). */
  let widest = 0;
  /**
   * A live table's numbers change width as they change (5e-14, then 4.7e-12), and a narrower table would
   * pull back a reader scrolled to its end (the browser clamps the scroll position), a wider one push the
   * last column out of view. So the table only ever widens, which keeps any scroll position, and a reader
   * at the end stays at the end.
   */
  const keepPlace = (atEnd: boolean) => {
    const width = el.getBoundingClientRect().width;
    if (width > widest) {
      widest = width;
      el.style.minWidth = `${width}px`;
    }
    if (atEnd) box.scrollLeft = box.scrollWidth;
  };
  const show = ({ rows, caption: text }: ReturnType<typeof read>) => {
    const atEnd = box.scrollLeft > 0 && box.scrollLeft + box.clientWidth >= box.scrollWidth - 1;
    if (text !== undefined) caption.textContent = text;
    body.replaceChildren(...bodyRows(rows, columns));
    if (live) keepPlace(atEnd);
  };
  show(first);

  if (typeof ResizeObserver !== 'undefined') new ResizeObserver(() => markScrolling(box, name)).observe(box);

  if (live) {
    let seen = false;
    let unseen = 0;
    const tick = () => {
      if (box.isConnected) seen = true;
      // The cell was re-run or the page left it (or it never showed the table, after a minute): stop reading.
      else if (seen || ++unseen * refresh > 60) return;
      try {
        show(read());
      } catch (error) {
        const note = document.createElement('p');
        note.className = 'pb-error';
        note.textContent = `table stopped: ${error instanceof Error ? error.message : String(error)}`;
        box.after(note);
        return;
      }
      setTimeout(tick, refresh * 1000);
    };
    setTimeout(tick, refresh * 1000);
  }
  return box;
}
