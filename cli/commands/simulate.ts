/**
 * `phasebook simulate`: one trajectory, or a dataset of many (listed, from a
 * file, sampled in a box, on an energy surface, on a grid), written as CSV,
 * JSON, NPZ or Parquet, on every core, or one shard of it.
 */
import { basename, extname } from 'node:path';
import { DEFAULT_DT, InputError, MAX_SEED, methodChoice, stateNames } from '../../core/index.ts';
import { number, numberList, parseArgs, positive, wholeNumber, type ParsedArgs } from '../options/args.ts';
import { SIMULATE } from '../options/commands.ts';
import { prepareRun, type PreparedRun } from '../dataset/prepare.ts';
import { executeRun } from '../dataset/execute.ts';
import { datasetWriter } from '../dataset/write.ts';
import { readInitialFile } from '../options/initial-file.ts';
import { modelRecipe, userCodeOf } from '../model/model.ts';
import { refuseSameFile } from '../output/same-file.ts';
import { Interrupted, InterruptGuard } from '../interrupt.ts';
import { fileSink, stdoutSink, type Sink } from '../output/sink.ts';
import { parameters } from '../options/parameters.ts';
import { parseBox, parseGrid } from '../options/ranges.ts';
import type { ParquetLayout } from '../formats/parquet-dataset.ts';
import type { Format, RunSpec, SetSpec } from '../dataset/spec.ts';
import { usageLine } from '../options/usage.ts';

const FORMATS: readonly Format[] = ['csv', 'json', 'npz', 'parquet'];

export interface SimulateArguments {
  spec: RunSpec;
  output?: string;
  /** --initial-file, which the output must not replace */
  initialFile?: string;
  /** threads; undefined: every core for a run large enough to repay them */
  workers?: number;
  cache: boolean;
  force: boolean;
}

/** The format: --format, else the output's extension, else CSV. */
function formatOf(given: string | undefined, output: string | undefined): Format {
  if (given !== undefined) {
    if (!FORMATS.includes(given as Format)) throw new InputError(`--format must be csv, json, npz or parquet, not "${given}"`);
    return given as Format;
  }
  const ext = output === undefined ? '' : extname(output).slice(1).toLowerCase();
  return FORMATS.includes(ext as Format) ? (ext as Format) : 'csv';
}

/** `i/n` with 1 ≤ i ≤ n. */
function parseShard(text: string): { index: number; of: number } {
  const m = /^\s*(-?\d+)\s*\/\s*(-?\d+)\s*$/.exec(text);
  if (!m) throw new InputError(`--shard takes i/n (shard i of n, from 1/n to n/n), not "${text}"`);
  const index = Number(m[1]);
  const of = Number(m[2]);
  if (!(of >= 1)) throw new InputError(`--shard ${text}: the number of shards must be at least 1`);
  if (index < 1 || index > of) throw new InputError(`--shard ${text}: the shard number runs from 1 to ${of}`);
  return { index, of };
}

/** The options as given: a value, or the error that names a missing one with the usage. */
function reader(args: ParsedArgs) {
  const value = (name: string) => args.values.get(name);
  const required = (name: string) => {
    const v = value(name);
    if (v === undefined) throw new InputError(`--${name} is required (usage: ${usageLine(SIMULATE)})`);
    return v;
  };
  return { value, required };
}

/** H or the vector field, the state's names and the parameters. */
function modelOptions(args: ParsedArgs) {
  const { value, required } = reader(args);
  const hamiltonian = value('hamiltonian');
  const vectorField = value('vector-field');
  if (hamiltonian === undefined && vectorField === undefined) required('hamiltonian');
  const dof = wholeNumber(required('dof'), '--dof');
  const list = (name: string) => value(name)?.split(',').map((s) => s.trim());
  const coordinates = list('coordinates');
  const momenta = list('momenta');
  const { names } = stateNames(dof, coordinates, momenta);
  const { values: params, expressions } = parameters(args.lists.get('param') ?? [], names);
  return { hamiltonian, vectorField, dof, coordinates, momenta, names, params, paramExpressions: Object.keys(expressions).length ? expressions : undefined };
}

/** The step, the span and the sample times, and the method. */
function timeOptions(args: ParsedArgs) {
  const { value } = reader(args);
  const dt = positive(value('dt') ?? String(DEFAULT_DT), '--dt');
  const t0 = number(value('t0') ?? '0', '--t0');
  const timesText = value('times');
  if (timesText !== undefined && (value('t-end') !== undefined || value('every') !== undefined)) {
    throw new InputError('--times lists the output times: give it without --t-end and --every');
  }
  const times = timesText === undefined ? undefined : numberList(timesText, '--times');
  const tEnd = times ? times[times.length - 1] : number(value('t-end') ?? String(t0 + 10), '--t-end');
  if (tEnd < t0) throw new InputError(value('t0') === undefined ? `--t-end must not be negative, not ${tEnd}` : `--t-end ${tEnd} is before --t0 ${t0}`);
  const every = wholeNumber(value('every') ?? '1', '--every');
  const tolerance = (name: string) => (value(name) === undefined ? undefined : number(value(name)!, `--${name}`));
  const methodName = value('method') ?? 'rk38';
  if (methodName !== 'adaptive' && (value('rtol') !== undefined || value('atol') !== undefined)) {
    throw new InputError('--rtol and --atol are tolerances of --method adaptive');
  }
  const method = methodChoice(methodName, tolerance('rtol'), tolerance('atol'));
  return { dt, t0, tEnd, every, times, method };
}

/** Where the output goes and in what form, and how the run is shared out. */
function outputOptions(args: ParsedArgs) {
  const { value } = reader(args);
  const output = value('output');
  const format = formatOf(value('format'), output);
  const layout = value('layout') ?? 'long';
  if (layout !== 'long' && layout !== 'wide') throw new InputError(`--layout must be long or wide, not "${layout}"`);
  if (value('layout') !== undefined && format !== 'parquet') throw new InputError('--layout applies to --format parquet only');
  const shardText = value('shard');
  const shard = shardText === undefined ? undefined : parseShard(shardText);
  if (shard && format === 'csv') throw new InputError('--shard writes a part for phasebook merge, which checks the parts by the meta a CSV cannot hold: give --format npz, parquet or json');
  const workersText = value('workers');
  const workers = workersText === undefined ? undefined : wholeNumber(workersText, '--workers');
  return { output, format, layout: layout as ParquetLayout, shard, workers };
}

/** The arguments of `phasebook simulate`, checked: the run's spec and how to carry it out. */
export function parseSimulate(argv: readonly string[]): SimulateArguments {
  const args = parseArgs(argv, SIMULATE);
  const { names, ...model } = modelOptions(args);
  const { method, ...time } = timeOptions(args);
  const { output, workers, ...out } = outputOptions(args);
  const set = setSpec(args.values, names, model.params);
  const spec: RunSpec = {
    ...model,
    ...time,
    ...(method.name === 'rk38' ? {} : { method }),
    ...out,
    set,
    derivatives: args.flags.has('derivatives'),
  };
  return { spec, output, initialFile: args.values.get('initial-file'), workers, cache: !args.flags.has('no-cache'), force: args.flags.has('force') };
}

/** The set of initial states, from whichever one of --initial, --initial-file, --sample and --grid is given. */
function setSpec(values: Map<string, string>, names: readonly string[], params: Record<string, number>): SetSpec {
  const modes = ['initial', 'initial-file', 'sample', 'grid'].filter((m) => values.has(m));
  if (modes.length === 0) throw new InputError(`give the initial state: --initial v1,…,v${names.length}, or many with --initial-file, --sample or --grid`);
  if (modes.length > 1) throw new InputError(`give one of --initial, --initial-file, --sample and --grid, not ${modes.map((m) => `--${m}`).join(' and ')}`);
  const stray = (option: string, mode: string) => {
    if (values.has(option)) throw new InputError(`--${option} goes with --${mode}`);
  };
  if (!values.has('sample')) ['seed', 'box', 'energy', 'solve-for'].forEach((o) => stray(o, 'sample'));
  if (!values.has('energy')) stray('solve-for', 'energy');
  const mode = modes[0];
  if (mode === 'initial') {
    const initial = numberList(values.get('initial')!, '--initial');
    if (initial.length !== names.length) {
      throw new InputError(`--initial has ${initial.length} values; ${names.length / 2} degree(s) of freedom need ${names.length} (q's then p's)`);
    }
    return { kind: 'given', values: initial };
  }
  if (mode === 'initial-file') {
    const path = values.get('initial-file')!;
    return { kind: 'given', values: readInitialFile(path, names), file: basename(path) };
  }
  if (mode === 'grid') return { kind: 'grid', axes: parseGrid(values.get('grid')!, names, params) };
  const count = wholeNumber(values.get('sample')!, '--sample');
  const seed = wholeNumber(values.get('seed') ?? '0', '--seed', 0);
  if (seed > MAX_SEED) throw new InputError(`--seed must be at most ${MAX_SEED}, not ${seed}`);
  if (!values.has('box')) throw new InputError('--sample needs --box name=lo:hi,… for every component of the state');
  const box = parseBox(values.get('box')!, names, params);
  const energyText = values.get('energy');
  if (energyText === undefined) return { kind: 'sample', count, seed, box };
  const dof = names.length / 2;
  const solveFor = values.get('solve-for') ?? names[dof];
  if (!names.slice(dof).includes(solveFor)) throw new InputError(`--solve-for ${solveFor}: name a momentum (${names.slice(dof).join(', ')})`);
  return { kind: 'sample', count, seed, box, energy: { value: number(energyText, '--energy'), solveFor } };
}

export async function simulate(argv: readonly string[]): Promise<void> {
  const parsed = parseSimulate(argv);
  const { spec, output } = parsed;
  if (output === undefined && (spec.format === 'npz' || spec.format === 'parquet') && process.stdout.isTTY) {
    throw new InputError(`--format ${spec.format} is binary: give --output FILE, or send stdout to a file or a pipe`);
  }
  // Renamed onto its input, the output would replace the states it is computed from.
  if (output !== undefined && parsed.initialFile !== undefined) refuseSameFile(output, parsed.initialFile, '--output', '--initial-file');
  const guard = new InterruptGuard();
  // The output is checked, and its partial file made, before anything is compiled or computed.
  const sink: Sink = output ? fileSink(output, guard) : stdoutSink();
  let run: PreparedRun | undefined;
  const status = { steps: 0 };
  let writer: ReturnType<typeof datasetWriter> | undefined;
  try {
    const recipe = await modelRecipe({ ...spec, cache: parsed.cache });
    // The user's code runs in a sandbox, which a signal must stop too: the CLI hears it, whatever the output.
    if (userCodeOf(recipe)) guard.hold();
    run = await prepareRun(spec, recipe, { force: parsed.force, signal: guard.signal });
    writer = datasetWriter(run, sink, output);
    // Files kept aside (an NPZ's later arrays) must be removed on Ctrl-C even when stdout is the output.
    if (writer.keepsFiles) guard.hold();
    await executeRun(run, writer.writer, { workers: parsed.workers, signal: guard.signal, timeChunkRows: writer.timeChunkRows, status });
    sink.commit();
  } catch (error) {
    writer?.writer.abandon();
    sink.abandon();
    if (error instanceof Interrupted) throw new Interrupted(error.signal, interruptedAt(run, status.steps, output));
    throw error;
  } finally {
    await run?.model.close();
    guard.release();
  }
}

/** Where an interrupted run stopped, in its own terms: t for one trajectory, trajectories for many. */
function interruptedAt(run: PreparedRun | undefined, steps: number, output: string | undefined): string {
  const what = `${output ?? 'the output'} was not written`;
  if (!run) return `; ${what}`;
  const { shape, spec } = run;
  if (shape.count <= 1) return ` at t = ${(spec.t0 + steps * spec.dt).toPrecision(6)} of ${spec.tEnd}; ${what}`;
  return ` after ${Math.floor(steps / Math.max(1, run.steps))} of ${shape.count} trajectories; ${what}`;
}
