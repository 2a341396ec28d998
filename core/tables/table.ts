/**
 * A finished block of samples, detached from any ring buffer: what the
 * exporters write and the readers return. Row-major so that one row is one
 * contiguous run of numbers, which is also how every export format lays it out.
 */
export interface Table {
  /** Column names; for trajectories column 0 is "t". */
  columns: readonly string[];
  rows: number;
  /** rows × columns.length values, row-major. */
  data: Float64Array;
}

/**
 * Checks the column names an exporter or reader is about to commit to. Empty
 * or repeated names would make lookups by name ambiguous after a round trip,
 * so they are refused at the boundary rather than discovered later.
 * Returns a description of the first problem, or undefined if there is none.
 */
export function columnProblem(columns: readonly string[]): string | undefined {
  if (columns.length === 0) return 'no columns';
  const seen = new Set<string>();
  for (const name of columns) {
    if (name.length === 0) return 'empty column name';
    if (seen.has(name)) return `duplicate column name "${name}"`;
    seen.add(name);
  }
  return undefined;
}
