import type { RecordLayout } from '../../core/index.ts';
import type { Extent } from './extent.ts';
import { spread } from './series.ts';

/** One line on a plane plot: the record columns of its x and y, and its colour group. */
export interface Track {
  x: number;
  y: number;
  group: number;
}

/** A pair of record series drawn as (x, y): state names such as 'q0', or exact columns such as 'q0[3]'. */
export type Pair = readonly [string, string];

/** An extent as plot options take it. */
export interface ExtentOption {
  x: readonly [number, number];
  y: readonly [number, number];
}

export function toExtent(option: ExtentOption | undefined, what: string): Extent | undefined {
  if (option === undefined) return undefined;
  const [x0, x1] = option.x ?? [];
  const [y0, y1] = option.y ?? [];
  if (![x0, x1, y0, y1].every(Number.isFinite) || !(x1 > x0) || !(y1 > y0)) {
    throw new Error(`${what} must be {x: [lo, hi], y: [lo, hi]} with lo < hi, not ${JSON.stringify(option)}`);
  }
  return { x0, x1, y0, y1 };
}

/**
 * Most trajectories of a batch a plane view draws: the paper's 1000-particle
 * beam in full; of a larger batch an evenly spread sample, which the view
 * says it shows (finding, tracing and fading 100 000 tracks took minutes).
 */
export const MAX_PLANE_TRACKS = 2000;

/** Column positions by header name, built once per record layout: looking each of 10⁵ names up in a list of 3·10⁵ was quadratic. */
const indexes = new WeakMap<readonly string[], Map<string, number>>();

function columnNamed(columns: readonly string[], name: string): number {
  let index = indexes.get(columns);
  if (!index) indexes.set(columns, (index = new Map(columns.map((c, i) => [c, i]))));
  return index.get(name) ?? -1;
}

/** The trajectories a plane view draws of a batch of `count`: all, or an even sample of MAX_PLANE_TRACKS. */
export function drawnTrajectories(count: number): number[] {
  return [...spread(count, MAX_PLANE_TRACKS)].sort((a, b) => a - b);
}

/**
 * The record columns a name stands for: a series of the layout, in every
 * trajectory (or the trajectories `which`), or one column by the name its
 * export header gives it (`q0[3]`, trajectory 3's q0).
 */
export function columnsOf(layout: RecordLayout, name: string, which?: readonly number[]): number[] {
  const series = layout.series.find((s) => s.name === name);
  if (series) return which ? which.map((j) => series.columns[j]) : [...series.columns];
  const exact = columnNamed(layout.columns, name);
  if (exact > 0) return [exact];
  const { columns } = layout;
  const shown = columns.slice(1, 9).join(', ') + (columns.length > 9 ? ', …' : '');
  throw new Error(`no series named “${name}”; the record has ${shown}`);
}

/** One track per trajectory for a pair: x and y columns matched trajectory by trajectory. */
export function tracksOf(layout: RecordLayout, pair: Pair, group: (j: number) => number): Track[] {
  const count = layout.trajectories;
  const which = count > 1 ? drawnTrajectories(count) : undefined;
  const xs = columnsOf(layout, pair[0], which);
  const ys = columnsOf(layout, pair[1], which);
  if (xs.length !== ys.length) {
    throw new Error(`“${pair[0]}” is ${xs.length} series and “${pair[1]}” is ${ys.length}; a pair needs as many of each`);
  }
  return xs.map((x, k) => ({ x, y: ys[k], group: group(which ? which[k] : k) }));
}

/** A plane view's title for a batch: how many trajectories, and how many of them it draws. */
export function batchTitle(count: number): string | undefined {
  if (count <= 1) return undefined;
  const drawn = Math.min(count, MAX_PLANE_TRACKS);
  return drawn < count ? `${drawn.toLocaleString('en')} of ${count.toLocaleString('en')} trajectories shown` : `${count} trajectories`;
}

/**
 * The bodies of a configuration space by default: consecutive coordinates
 * paired as (x, y), (q0, q1), (q2, q3), …; an odd last one is left out.
 */
export function defaultBodies(names: readonly string[], dof: number): Pair[] {
  if (dof < 2) {
    throw new Error('this model has one coordinate, so its motion is along a line: a time plot or the phase portrait shows it better');
  }
  const bodies: Pair[] = [];
  for (let i = 0; i + 1 < dof; i += 2) bodies.push([names[i], names[i + 1]]);
  return bodies;
}

/** The phase-plane pairs (q_i, p_i): all degrees of freedom by default, or the chosen indices or pairs. */
export function phasePairs(names: readonly string[], dof: number, chosen?: readonly (number | Pair)[]): Pair[] {
  const indices = chosen ?? Array.from({ length: dof }, (_, i) => i);
  return indices.map((c) => {
    if (typeof c !== 'number') return c;
    if (!Number.isInteger(c) || c < 0 || c >= dof) throw new Error(`pair ${c} does not exist: the model has degrees of freedom 0 … ${dof - 1}`);
    return [names[c], names[dof + c]] as const;
  });
}

/** An axis title for the pairs sharing it: the one name, or the names listed. */
export function axisTitle(names: readonly string[], generic: string): string {
  const unique = [...new Set(names)];
  if (unique.length === 1) return unique[0];
  const list = unique.length <= 3 ? unique.join(', ') : `${unique.slice(0, 2).join(', ')}, …`;
  return `${generic} (${list})`;
}
