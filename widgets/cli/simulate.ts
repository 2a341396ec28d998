import { csvHeader, csvRows } from '../core/csv.ts';
import { InputError } from '../core/errors.ts';
import { exportMeta } from '../core/export-meta.ts';
import { jsonHead, jsonRows, jsonTail, type ExportMeta } from '../core/json.ts';
import { DEFAULT_DT, Simulation } from '../core/simulation.ts';
import { number, numberList, params, parseArgs, positive, wholeNumber } from './args.ts';
import { Interrupted, InterruptGuard } from './interrupt.ts';
import { checkEvaluates, simulationModel } from './model.ts';
import { fileSink, stdoutSink, type Sink } from './output.ts';
import { pacedRun } from './paced-run.ts';
import { progressBar } from './progress.ts';
import { checkRunSize, runSize } from './run-size.ts';

export const SIMULATE_USAGE = `phasebook simulate --hamiltonian H --dof N --initial v1,…,v2N [--param name=value]…
                   [--dt 5e-4] [--t-end 10] [--every 1] [--format csv|json] [--output FILE] [--no-cache] [--force]
  phasebook simulate --vector-field '(t, x, dxdt) => { … }' [--hamiltonian '(t, x) => …'] --dof N …`;

/** Rows the record holds between writes: enough to amortise a write, few enough to keep memory flat. */
const ROWS_PER_BLOCK = 4096;

export async function simulate(argv: readonly string[]): Promise<void> {
  const args = parseArgs(argv, {
    hamiltonian: 'value',
    'vector-field': 'value',
    dof: 'value',
    initial: 'value',
    param: 'list',
    dt: 'value',
    't-end': 'value',
    every: 'value',
    format: 'value',
    output: 'value',
    'no-cache': 'flag',
    force: 'flag',
  });
  const required = (name: string) => {
    const v = args.values.get(name);
    if (v === undefined) throw new InputError(`--${name} is required (usage: ${SIMULATE_USAGE.split('\n')[0]} …)`);
    return v;
  };
  const hamiltonian = args.values.get('hamiltonian');
  const vectorField = args.values.get('vector-field');
  if (hamiltonian === undefined && vectorField === undefined) required('hamiltonian');
  const dof = wholeNumber(required('dof'), '--dof');
  const initial = numberList(required('initial'), '--initial');
  const dt = positive(args.values.get('dt') ?? String(DEFAULT_DT), '--dt');
  const tEnd = number(args.values.get('t-end') ?? '10', '--t-end');
  if (tEnd < 0) throw new InputError(`--t-end must not be negative, not ${tEnd}`);
  const every = wholeNumber(args.values.get('every') ?? '1', '--every');
  const format = args.values.get('format') ?? 'csv';
  if (format !== 'csv' && format !== 'json') throw new InputError(`--format must be csv or json, not "${format}"`);
  const values = params(args.lists.get('param') ?? []);
  if (initial.length !== 2 * dof) {
    throw new InputError(`--initial has ${initial.length} values; ${dof} degree(s) of freedom need ${2 * dof} (q's then p's)`);
  }

  const model = await simulationModel({ dof, hamiltonian, vectorField, params: values, cache: !args.flags.has('no-cache') });
  checkEvaluates(model, initial);
  const simulation = new Simulation(model, { initial, dt, every, capacity: ROWS_PER_BLOCK + 1 });
  const size = runSize({ tEnd, dt, every, columns: simulation.record.width, format });
  checkRunSize(size, args.flags.has('force'));
  const meta = exportMeta(simulation);
  if (vectorField !== undefined) {
    // The field is what was integrated; H, when given, only fills its column.
    meta.hamiltonian = hamiltonian ?? '';
    meta.vectorField = vectorField;
  }
  const output = args.values.get('output');
  const guard = new InterruptGuard();
  const sink: Sink = output ? fileSink(output, guard) : stdoutSink();
  try {
    await write(simulation, size.steps, format, meta, sink, guard.signal);
    sink.commit();
  } catch (error) {
    sink.abandon();
    if (error instanceof Interrupted) {
      throw new Interrupted(error.signal, ` at t = ${simulation.t.toPrecision(6)} of ${tEnd}; ${output ?? 'the output'} was not written`);
    }
    throw error;
  }
}

async function write(simulation: Simulation, steps: number, format: string, meta: ExportMeta, sink: Sink, signal: AbortSignal): Promise<void> {
  const { record } = simulation;
  const progress = progressBar();
  sink.write(format === 'csv' ? csvHeader(record.columns) : jsonHead(meta, record.columns));
  let first = true;
  const flush = () => {
    for (const { data, from, to } of record.slices()) {
      if (format === 'csv') sink.write(csvRows(data, record.width, from, to));
      else {
        sink.write(jsonRows(data, record.width, from, to, first));
        if (to > from) first = false;
      }
    }
    record.clear();
  };
  try {
    await pacedRun(simulation, steps, {
      flush,
      progress: () => progress.update(simulation.steps / steps, `t = ${simulation.t.toPrecision(6)}`),
      signal,
    });
    if (format === 'json') sink.write(jsonTail());
  } finally {
    // Before any message, so that it starts on a clean line.
    progress.done();
  }
}
