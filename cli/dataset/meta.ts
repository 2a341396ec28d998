/**
 * The meta a dataset file carries: everything needed to make it again
 * (`phasebook reproduce`), and to tell whether shards belong together
 * (`phasebook merge`). It keeps the keys of the single-run export (core's
 * exportMeta) first, in their order, and adds the run's span (tEnd, steps,
 * samples, and times when listed), the set of initial states, the number of
 * trajectories, and for a shard which slice it is. Nothing in it depends on
 * the machine, the time or the number of workers: the same run writes the
 * same meta.
 */
import { type ExportMeta, methodMeta, VERSION } from '../../core/index.ts';
import type { ModelFacts } from '../model/model-facts.ts';
import type { RunSpec, SetSpec } from './spec.ts';

export interface DatasetMeta extends ExportMeta {
  tEnd: number;
  steps: number;
  samples: number;
  times?: number[];
  /** trajectories in this file */
  count: number;
  /** trajectories in the whole set */
  trajectories: number;
  initialSet: { kind: SetSpec['kind']; file?: string; [key: string]: unknown };
  derivatives: boolean;
  columns: string[];
  format: string;
  layout?: string;
  shard?: { index: number; of: number; first: number };
}

export interface MetaInputs {
  spec: RunSpec;
  model: ModelFacts;
  steps: number;
  samples: number;
  columns: string[];
  total: number;
  first: number;
  count: number;
}

export function datasetMeta({ spec, model, steps, samples, columns, total, first, count }: MetaInputs): DatasetMeta {
  const params: Record<string, number> = {};
  model.paramNames.forEach((name, i) => (params[name] = model.params[i]));
  const meta: Record<string, unknown> = {};
  // The field is what was integrated; H, when given, only fills its column.
  meta.hamiltonian = spec.vectorField !== undefined ? (spec.hamiltonian ?? '') : model.source;
  if (spec.vectorField !== undefined) meta.vectorField = spec.vectorField;
  meta.params = params;
  if (spec.paramExpressions && Object.keys(spec.paramExpressions).length) meta.paramExpressions = spec.paramExpressions;
  meta.dof = model.dof;
  meta.dt = spec.dt;
  Object.assign(meta, methodMeta(model.method));
  meta.every = spec.every;
  meta.t0 = spec.t0;
  meta.tEnd = spec.tEnd;
  meta.steps = steps;
  meta.samples = samples;
  if (spec.times) meta.times = spec.times;
  if (spec.set.kind === 'given') meta.initial = spec.set.values;
  meta.route = model.route;
  meta.names = [...model.names];
  if (spec.coordinates) meta.coordinates = spec.coordinates;
  if (spec.momenta) meta.momenta = spec.momenta;
  meta.derived = model.hasHamiltonian ? ['H'] : [];
  meta.derivatives = spec.derivatives;
  meta.columns = columns;
  meta.version = VERSION;
  meta.count = count;
  meta.trajectories = total;
  meta.initialSet = setDescription(spec.set);
  meta.format = spec.format;
  if (spec.format === 'parquet') meta.layout = spec.layout;
  if (spec.shard) meta.shard = { index: spec.shard.index, of: spec.shard.of, first };
  return meta as unknown as DatasetMeta;
}

/** The set as the meta describes it; listed values are in `initial`, not repeated here. */
function setDescription(set: SetSpec): DatasetMeta['initialSet'] {
  if (set.kind === 'given') return set.file === undefined ? { kind: 'given' } : { kind: 'given', file: set.file };
  return { ...set };
}

/** The meta of the whole set that shards with this meta make: no shard, and the set's count. */
export function unshardedMeta(meta: DatasetMeta): DatasetMeta {
  const whole = { ...meta, count: meta.trajectories };
  delete whole.shard;
  return whole;
}
