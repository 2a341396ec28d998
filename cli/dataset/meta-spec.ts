/**
 * The run a dataset file's meta describes, read as data from whoever made
 * the file: `phasebook reproduce` runs it again. Every field is checked for
 * its type and its range before any of it is used, and a field that fails
 * is named in one line with the file, instead of surfacing later as an
 * internal error (a dt of "x" once said "too many steps to count").
 *
 * A meta's code is only text here: whether an H or a vector field may run
 * is decided once it is compiled (model.ts, userCodeOf).
 */
import { checkName, InputError, MAX_SEED, methodChoice, stateNames } from '../../core/index.ts';
import type { Format, RunSpec, SetSpec } from './spec.ts';

const FORMATS: readonly Format[] = ['csv', 'json', 'npz', 'parquet'];

type Fields = Record<string, unknown>;

const isObject = (v: unknown): v is Fields => typeof v === 'object' && v !== null && !Array.isArray(v);
const isFinite = (v: unknown): v is number => typeof v === 'number' && Number.isFinite(v);
const isWhole = (v: unknown, least: number): v is number => typeof v === 'number' && Number.isSafeInteger(v) && v >= least;

/** Reads the fields of one meta, each error naming the file. */
class MetaReader {
  constructor(
    private readonly meta: Fields,
    private readonly path: string,
  ) {}

  bad(what: string): InputError {
    return new InputError(`${this.path}: its meta ${what}, so it cannot be run again`);
  }

  has(key: string): boolean {
    return Object.hasOwn(this.meta, key) && this.meta[key] !== undefined && this.meta[key] !== null;
  }

  raw(key: string): unknown {
    return Object.hasOwn(this.meta, key) ? this.meta[key] : undefined;
  }

  string(key: string): string {
    const v = this.raw(key);
    if (typeof v !== 'string') throw this.bad(`has no text for ${key}`);
    return v;
  }

  finite(key: string): number {
    const v = this.raw(key);
    if (!isFinite(v)) throw this.bad(`gives ${key} as ${shown(v)}, not a finite number`);
    return v;
  }

  whole(key: string, least: number): number {
    const v = this.raw(key);
    if (!isWhole(v, least)) throw this.bad(`gives ${key} as ${shown(v)}, not a whole number ≥ ${least}`);
    return v;
  }

  strings(key: string): string[] | undefined {
    if (!this.has(key)) return undefined;
    const v = this.raw(key);
    if (!Array.isArray(v) || !v.every((s) => typeof s === 'string')) throw this.bad(`gives ${key} as ${shown(v)}, not a list of names`);
    return v as string[];
  }
}

/** A value from a meta, short, for a message. */
function shown(value: unknown): string {
  if (value === undefined) return 'nothing';
  const text = JSON.stringify(value) ?? String(value);
  return text.length > 40 ? `${text.slice(0, 40)}…` : text;
}

/** The spec `meta` describes; `path` names the file in every message. */
export function specFromMeta(meta: unknown, path: string): RunSpec {
  if (!isObject(meta)) throw new InputError(`${path}: its meta is not an object`);
  const read = new MetaReader(meta, path);
  const vectorField = read.has('vectorField') ? read.string('vectorField') : undefined;
  const hamiltonianText = read.has('hamiltonian') || vectorField === undefined ? read.string('hamiltonian') : '';
  const dof = read.whole('dof', 1);
  const coordinates = read.strings('coordinates');
  const momenta = read.strings('momenta');
  const recorded = read.strings('names');
  // The state names, which the meta also lists: a dof must come with that many names, so no meta asks for more than it holds.
  if (recorded === undefined || recorded.length !== 2 * dof) throw read.bad(`lists ${recorded?.length ?? 'no'} state names for ${dof} degree(s) of freedom`);
  let names: string[];
  try {
    names = stateNames(dof, coordinates, momenta).names;
  } catch (error) {
    throw read.bad(`names the state wrongly (${(error as Error).message})`);
  }
  if (names.some((name, i) => name !== recorded[i])) throw read.bad(`lists the state as ${recorded.join(', ')}, not ${names.join(', ')}`);

  const params = parameters(read);
  const dt = read.finite('dt');
  if (!(dt > 0)) throw read.bad(`gives dt as ${dt}, not a positive number`);
  const t0 = read.finite('t0');
  const tEnd = read.finite('tEnd');
  if (tEnd < t0) throw read.bad(`ends at tEnd = ${tEnd}, before t0 = ${t0}`);
  const every = read.whole('every', 1);
  let times: number[] | undefined;
  if (read.has('times')) {
    const v = read.raw('times');
    if (!Array.isArray(v) || v.length === 0 || !v.every(isFinite)) throw read.bad(`gives times as ${shown(v)}, not a list of finite numbers`);
    times = v as number[];
  }
  let method: ReturnType<typeof methodChoice>;
  try {
    method = methodChoice(read.raw('method') ?? 'rk38', read.raw('rtol') ?? undefined, read.raw('atol') ?? undefined);
  } catch (error) {
    throw read.bad(`names its method wrongly (${(error as Error).message})`);
  }
  const derivatives = read.raw('derivatives');
  if (typeof derivatives !== 'boolean') throw read.bad(`gives derivatives as ${shown(derivatives)}, not true or false`);
  const format = read.raw('format');
  if (!FORMATS.includes(format as Format)) throw read.bad(`gives the format as ${shown(format)}`);
  const layout = read.has('layout') ? read.raw('layout') : 'long';
  if (layout !== 'long' && layout !== 'wide') throw read.bad(`gives the layout as ${shown(layout)}`);
  let paramExpressions: Record<string, string> | undefined;
  if (read.has('paramExpressions')) {
    const v = read.raw('paramExpressions');
    if (!isObject(v) || !Object.values(v).every((s) => typeof s === 'string')) throw read.bad('gives paramExpressions that are not texts');
    paramExpressions = v as Record<string, string>;
  }

  return {
    hamiltonian: vectorField !== undefined && hamiltonianText === '' ? undefined : hamiltonianText,
    vectorField,
    dof,
    params,
    paramExpressions,
    coordinates,
    momenta,
    dt,
    ...(method.name === 'rk38' ? {} : { method }),
    t0,
    tEnd,
    every,
    times,
    set: initialSet(read, names),
    derivatives,
    format: format as Format,
    layout,
    shard: shard(read),
  };
}

/** The parameters: names a generated stepper can use, and finite values. */
function parameters(read: MetaReader): Record<string, number> {
  const v = read.raw('params');
  if (!isObject(v)) throw read.bad('has no params object');
  const params: Record<string, number> = {};
  for (const [name, value] of Object.entries(v)) {
    try {
      checkName(name, 'parameter');
    } catch (error) {
      throw read.bad(`has a parameter whose name ${(error as Error).message}`);
    }
    if (!isFinite(value)) throw read.bad(`gives the parameter ${name} as ${shown(value)}, not a finite number`);
    params[name] = value;
  }
  return params;
}

/** The set of initial states, every component of the state given its range. */
function initialSet(read: MetaReader, names: readonly string[]): SetSpec {
  const set = read.raw('initialSet');
  if (!isObject(set)) throw read.bad('has no initialSet');
  const dim = names.length;
  if (set.kind === 'given') {
    const values = read.raw('initial');
    if (!Array.isArray(values) || values.length === 0 || values.length % dim !== 0 || !values.every(isFinite)) {
      throw read.bad(`gives the initial states as ${shown(values)}, not whole states of ${dim} finite numbers`);
    }
    const file = set.file;
    if (file !== undefined && typeof file !== 'string') throw read.bad('names the initial file wrongly');
    return file === undefined ? { kind: 'given', values } : { kind: 'given', values, file };
  }
  if (set.kind === 'grid') {
    const axes = ranges(read, set.axes, names, 3, 'grid');
    for (const name of names) if (!isWhole(axes[name][2], 1)) throw read.bad(`gives the grid of ${name} ${shown(axes[name][2])} points`);
    return { kind: 'grid', axes: axes as Record<string, [number, number, number]> };
  }
  if (set.kind === 'sample') {
    if (!isWhole(set.count, 1)) throw read.bad(`samples ${shown(set.count)} trajectories`);
    if (!isWhole(set.seed, 0) || set.seed > MAX_SEED) throw read.bad(`gives the seed as ${shown(set.seed)}`);
    const box = ranges(read, set.box, names, 2, 'box') as Record<string, [number, number]>;
    if (set.energy === undefined) return { kind: 'sample', count: set.count, seed: set.seed, box };
    const energy = set.energy as Fields;
    const momenta = names.slice(dim / 2);
    if (!isObject(energy) || !isFinite(energy.value) || typeof energy.solveFor !== 'string' || !momenta.includes(energy.solveFor)) {
      throw read.bad(`gives the energy as ${shown(energy)}, not a value and a momentum to solve for`);
    }
    return { kind: 'sample', count: set.count, seed: set.seed, box, energy: { value: energy.value, solveFor: energy.solveFor } };
  }
  throw read.bad(`gives the initial set's kind as ${shown(set.kind)}`);
}

/** A range of `size` finite numbers for each state name, and for nothing else. */
function ranges(read: MetaReader, value: unknown, names: readonly string[], size: number, what: string): Record<string, number[]> {
  if (!isObject(value)) throw read.bad(`has no ${what}`);
  const out: Record<string, number[]> = {};
  for (const name of names) {
    const range = Object.hasOwn(value, name) ? value[name] : undefined;
    if (!Array.isArray(range) || range.length !== size || !range.every(isFinite)) throw read.bad(`gives the ${what} of ${name} as ${shown(range)}`);
    out[name] = range;
  }
  const stray = Object.keys(value).find((key) => !names.includes(key));
  if (stray !== undefined) throw read.bad(`gives a ${what} for ${shown(stray)}, which is not in the state`);
  return out;
}

/** Which slice of the set the file holds, if it is a shard. */
function shard(read: MetaReader): RunSpec['shard'] {
  if (!read.has('shard')) return undefined;
  const v = read.raw('shard');
  if (!isObject(v) || !isWhole(v.of, 1) || !isWhole(v.index, 1) || v.index > v.of) throw read.bad(`gives the shard as ${shown(v)}`);
  return { index: v.index, of: v.of };
}
