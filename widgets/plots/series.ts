/**
 * Which record columns a time plot draws, grouped into legend entries. For
 * one trajectory every column but t is its own entry (q, p, H, I …). For a
 * batch of M trajectories the columns `q0[j]` of all j form one entry drawn
 * in one colour, and at most `maxLines` trajectories per entry are drawn,
 * evenly spread over the batch, so a 1000-particle beam stays cheap to plot.
 */

export interface SeriesGroup {
  /** the legend label: the column name without its [j] suffix */
  name: string;
  /** record columns drawn for this entry */
  columns: number[];
}

export interface SeriesPlan {
  groups: SeriesGroup[];
  /** trajectories drawn per group, and in the batch */
  drawn: number;
  count: number;
}

const INDEXED = /^(.*)\[(\d+)\]$/;

/**
 * Groups the columns of a record (column 0 is t). `only` restricts the
 * groups to those names, in the record's order; an unknown name throws.
 */
export function planSeries(columns: readonly string[], maxLines = 100, only?: readonly string[]): SeriesPlan {
  const byName = new Map<string, { column: number; index: number }[]>();
  for (let c = 1; c < columns.length; c++) {
    const match = INDEXED.exec(columns[c]);
    const name = match ? match[1] : columns[c];
    const index = match ? Number(match[2]) : 0;
    if (!byName.has(name)) byName.set(name, []);
    byName.get(name)!.push({ column: c, index });
  }
  if (only) {
    for (const name of only) {
      if (!byName.has(name)) throw new Error(`timePlot: no series named "${name}"; the record has ${[...byName.keys()].join(', ')}`);
    }
  }
  let count = 0;
  for (const entries of byName.values()) count = Math.max(count, entries.length);
  const chosen = spread(count, Math.max(1, Math.floor(maxLines)));
  const groups: SeriesGroup[] = [];
  for (const [name, entries] of byName) {
    if (only && !only.includes(name)) continue;
    groups.push({ name, columns: entries.filter((e) => chosen.has(e.index)).map((e) => e.column) });
  }
  return { groups, drawn: chosen.size, count };
}

/** At most n indices out of 0 … count−1, evenly spaced, always including the first and last. */
export function spread(count: number, n: number): Set<number> {
  const out = new Set<number>();
  if (count <= n) {
    for (let j = 0; j < count; j++) out.add(j);
    return out;
  }
  if (n === 1) return out.add(0);
  for (let i = 0; i < n; i++) out.add(Math.round((i * (count - 1)) / (n - 1)));
  return out;
}
