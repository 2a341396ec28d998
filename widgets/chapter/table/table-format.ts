/**
 * Numbers and columns for book tables (chapter/table/table.ts), and the checks on
 * what a chapter writes: pure, so unit-tested in Node.
 *
 * Numbers show as the inspectors show them (cells/inspect.ts): the
 * shortest form that reads back to the value rounded to the column's
 * significant digits, so 3.5999999999999996 shows as 3.6 and the text still
 * parses as a number (`Number(cell.textContent)`).
 */

/** One column of a table. */
export interface TableColumnOptions {
  /** the header, e.g. 'energy H' */
  label: string;
  /** shown after the header in brackets, e.g. 'rad' */
  unit?: string;
  /** significant digits of the numbers in this column (default 12, as the inspector) */
  digits?: number;
  /** marks the column the text asks the reader to watch */
  highlight?: boolean;
}

export interface TableOptions {
  /** the columns in order: a header string or {label, unit, digits, highlight} */
  columns: readonly (string | TableColumnOptions)[];
  /** the rows, each a list of cells in column order; or a function returning them, read again every `refresh` seconds */
  rows: readonly (readonly unknown[])[] | (() => readonly (readonly unknown[])[]);
  /** a caption above the table, e.g. 't = 1.25'; or a function read with the rows */
  caption?: string | (() => string);
  /** what the table holds, for a screen reader (default: the caption, or the headers) */
  label?: string;
  /** seconds between readings of `rows` when it is a function (default 0.25); the table updates in place while on the page */
  refresh?: number;
}

export interface ResolvedColumn {
  label: string;
  unit: string | null;
  digits: number;
  highlight: boolean;
}

/** Significant digits of a number shown without a column's own choice (as cells/inspect.ts). */
export const DEFAULT_DIGITS = 12;

/**
 * A number for display: rounded to `digits` significant digits, then the
 * shortest text that reads back to that (−0 as '-0'; NaN and infinities by
 * name, as the inspector shows them).
 */
export function displayNumber(value: number, digits = DEFAULT_DIGITS): string {
  if (Object.is(value, -0)) return '-0';
  if (!Number.isFinite(value) || Number.isInteger(value)) return String(value);
  return String(Number(value.toPrecision(Math.min(100, Math.max(1, Math.round(digits))))));
}

/**
 * A cell's text: numbers formatted, null and undefined empty, anything else
 * as a string. A number that is not one shows as a dash and an infinite one
 * as ∞: a reader is never shown "NaN" (the chapter's text says why a value
 * is missing).
 */
export function cellText(value: unknown, column: ResolvedColumn): string {
  if (typeof value === 'number' && Number.isNaN(value)) return '—';
  if (value === Infinity || value === -Infinity) return value > 0 ? '∞' : '−∞';
  if (typeof value === 'number') return displayNumber(value, column.digits);
  if (typeof value === 'bigint') return String(value);
  if (value === null || value === undefined) return '';
  return String(value);
}

const COLUMN_KEYS = new Set(['label', 'unit', 'digits', 'highlight']);

export function resolveColumns(columns: unknown): ResolvedColumn[] {
  if (!Array.isArray(columns) || columns.length === 0) throw new Error("table: columns must be a list of headers, e.g. ['quantity', {label: 'change', highlight: true}]");
  return columns.map((c, i) => {
    if (typeof c === 'string') return { label: c, unit: null, digits: DEFAULT_DIGITS, highlight: false };
    if (typeof c !== 'object' || c === null || typeof (c as { label?: unknown }).label !== 'string') {
      throw new Error(`table: columns[${i}] must be a header or {label, unit, digits, highlight}`);
    }
    const extra = Object.keys(c).filter((k) => !COLUMN_KEYS.has(k));
    if (extra.length) throw new Error(`table: columns[${i}] has no option ${extra.map((k) => `'${k}'`).join(', ')}`);
    const { label, unit, digits, highlight } = c as TableColumnOptions;
    if (digits !== undefined && !(Number.isInteger(digits) && digits >= 1 && digits <= 17)) throw new Error(`table: columns[${i}].digits must be a whole number from 1 to 17`);
    return { label, unit: unit === undefined ? null : String(unit), digits: digits ?? DEFAULT_DIGITS, highlight: highlight === true };
  });
}

/** Checks rows against the columns: a list of lists, none longer than the header. */
export function checkRows(rows: unknown, columns: readonly ResolvedColumn[]): readonly (readonly unknown[])[] {
  if (!Array.isArray(rows)) throw new Error('table: rows must be a list of rows, each a list of cells');
  rows.forEach((row, i) => {
    if (!Array.isArray(row)) throw new Error(`table: rows[${i}] must be a list of cells`);
    if (row.length > columns.length) throw new Error(`table: rows[${i}] has ${row.length} cells but there are ${columns.length} columns`);
  });
  return rows as unknown[][];
}

/** A header with its unit: 'deflection (rad)'. */
export function headerText(column: ResolvedColumn): string {
  return column.unit ? `${column.label} (${column.unit})` : column.label;
}
