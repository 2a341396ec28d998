/**
 * Everything that decides the numbers of a `simulate` run, as plain data:
 * what the command line says, what a file's meta says to reproduce it, and
 * what shards must share to be merged.
 */
import type { MethodChoice } from '../../core/index.ts';
import type { ParquetLayout } from '../formats/parquet-dataset.ts';

export type Format = 'csv' | 'json' | 'npz' | 'parquet';

export type SetSpec =
  /** listed values, trajectory after trajectory: --initial, or --initial-file (named in `file`) */
  | { kind: 'given'; values: number[]; file?: string }
  /** --sample N --seed S --box …, optionally --energy E solved for one momentum */
  | { kind: 'sample'; count: number; seed: number; box: Record<string, [number, number]>; energy?: { value: number; solveFor: string } }
  /** --grid name=lo:hi:n,… */
  | { kind: 'grid'; axes: Record<string, [number, number, number]> };

export interface RunSpec {
  hamiltonian?: string;
  vectorField?: string;
  dof: number;
  params: Record<string, number>;
  /** parameters given as arithmetic, as written */
  paramExpressions?: Record<string, string>;
  coordinates?: string[];
  momenta?: string[];
  dt: number;
  /** --method (with --rtol, --atol); RK 3/8 when absent */
  method?: MethodChoice;
  t0: number;
  tEnd: number;
  every: number;
  /** output times, when listed; they replace every and t-end */
  times?: number[];
  set: SetSpec;
  derivatives: boolean;
  format: Format;
  layout: ParquetLayout;
  shard?: { index: number; of: number };
}

/** Trajectories [first, end) of shard i of n, the i-th of n near-equal contiguous slices. */
export function shardRange(total: number, shard: { index: number; of: number } | undefined): { first: number; end: number } {
  if (!shard) return { first: 0, end: total };
  return { first: Math.floor(((shard.index - 1) * total) / shard.of), end: Math.floor((shard.index * total) / shard.of) };
}
