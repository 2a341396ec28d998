import type { Table } from './record.ts';

/** A function of time and state: H, an action I = H/ω, an angular momentum… */
export type StateFunction = (t: number, x: Float64Array, offset: number) => number;

/**
 * Evaluates `f` at every row of a table whose columns are t, then the state
 * (as a simulation records them), into `out`.
 */
export function evaluateAlong(table: Table, f: StateFunction, out = new Float64Array(table.rows)): Float64Array {
  const { data, rows } = table;
  const width = table.columns.length;
  for (let r = 0; r < rows; r++) out[r] = f(data[r * width], data, r * width + 1);
  return out;
}

/**
 * The largest relative departure of a conserved quantity from its first
 * value, max |I − I₀| / |I₀| (absolute when I₀ = 0, where a ratio means
 * nothing).
 */
export function relativeDrift(values: ArrayLike<number>, from = 0, to = values.length): number {
  let worst = 0;
  for (let i = from; i < to; i++) worst = Math.max(worst, relativeChange(values[i], values[from]));
  return worst;
}

/** |h − h0| / |h0|, or |h − h0| when h0 = 0 (where a ratio means nothing). */
export function relativeChange(h: number, h0: number): number {
  const change = Math.abs(h - h0);
  return h0 === 0 ? change : change / Math.abs(h0);
}
