import type { RecordLayout } from '../../core/index.ts';

/**
 * Which record columns a time plot draws, grouped into legend entries: one
 * per series of the record's layout (q, p, H, I …). For a batch of M
 * trajectories an entry is that series' column in every trajectory, drawn
 * in one colour, and at most `maxLines` trajectories per entry are drawn,
 * evenly spread over the batch, so a 1000-particle beam stays cheap to plot.
 */

export interface SeriesGroup {
  /** the legend label: the series' name */
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

/**
 * The plan for a record's layout. `only` restricts the groups to those
 * names, in the record's order; an unknown name throws.
 */
export function planSeries(layout: Pick<RecordLayout, 'series' | 'trajectories'>, maxLines = 100, only?: readonly string[]): SeriesPlan {
  const names = layout.series.map((s) => s.name);
  for (const name of only ?? []) {
    if (!names.includes(name)) throw new Error(`timePlot: no series named "${name}"; the record has ${names.join(', ')}`);
  }
  const count = layout.trajectories;
  const chosen = [...spread(count, Math.max(1, Math.floor(maxLines)))];
  const groups = layout.series.filter((s) => !only || only.includes(s.name)).map((s) => ({ name: s.name, columns: chosen.map((j) => s.columns[j]) }));
  return { groups, drawn: chosen.length, count };
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
