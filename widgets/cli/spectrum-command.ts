import { readFileSync } from 'node:fs';
import { checkWindowName, findPeaks, InputError, readTable, spectrum } from '../core/index.ts';
import { number, parseArgs, wholeNumber } from './args.ts';
import { SPECTRUM } from './commands.ts';
import { usageLine } from './usage.ts';

export function spectrumCommand(argv: readonly string[]): string {
  const args = parseArgs(argv, SPECTRUM);
  const input = args.values.get('input');
  const name = args.values.get('column');
  if (!input) throw new InputError(`--input is required (usage: ${usageLine(SPECTRUM)})`);
  if (!name) throw new InputError('--column is required: name the series to analyse, e.g. --column q');
  const window = validWindow(args.values.get('window') ?? 'hamming');
  const top = wholeNumber(args.values.get('top') ?? '5', '--top');
  const format = args.values.get('format') ?? 'text';
  if (format !== 'text' && format !== 'json') throw new InputError(`--format must be text or json, not "${format}"`);

  let bytes: Buffer;
  try {
    bytes = readFileSync(input);
  } catch (error) {
    throw new InputError(`cannot read ${input}: ${(error as NodeJS.ErrnoException).code ?? (error as Error).message}`);
  }
  checkText(bytes, input);
  const table = readTable(bytes.toString('utf8'), input);
  const width = table.columns.length;
  const c = table.columns.indexOf(name);
  if (c < 0) throw new InputError(`no column "${name}" in ${input}; it has ${table.columns.join(', ')}`);
  const t = table.columns.indexOf('t');
  if (t < 0) throw new InputError(`${input} has no t column`);
  const bound = (name: string, fallback: number) => {
    const text = args.values.get(name);
    return text === undefined ? fallback : number(text, `--${name}`);
  };
  const from = bound('from', -Infinity);
  const to = bound('to', Infinity);
  if (to < from) throw new InputError(`--to (${to}) is before --from (${from})`);

  const pick = trajectoryFilter(table, args.values.get('trajectory'), input);
  const series: number[] = [];
  const times: number[] = [];
  for (let r = 0; r < table.rows; r++) {
    const time = table.data[r * width + t];
    if (pick(r) && time >= from && time <= to) {
      const value = table.data[r * width + c];
      if (!Number.isFinite(value)) throw new InputError(`${name} is ${value} at t = ${time} in ${input}; a spectrum needs finite samples (narrow --from/--to to leave it out)`);
      times.push(time);
      series.push(table.data[r * width + c]);
    }
  }
  if (series.length < 4) throw new InputError(`only ${series.length} samples of ${name} lie in [${from}, ${to}]; a spectrum needs more`);
  const interval = (times[times.length - 1] - times[0]) / (times.length - 1);
  if (!(interval > 0)) throw new InputError(`the samples of ${name} do not advance in t; a spectrum needs a uniform series`);
  checkUniform(times, interval);
  const peaks = findPeaks(spectrum(series, interval, { window }), { top, refine: series, window });
  if (format === 'json') return JSON.stringify({ peaks }) + '\n';
  const lines = peaks.map(
    (p, i) =>
      `${String(i + 1).padStart(2)}  f = ${p.frequency.toPrecision(10)}  ω = ${(2 * Math.PI * p.frequency).toPrecision(10)}  amplitude = ${p.amplitude.toPrecision(6)}`,
  );
  return `${name}: ${series.length} samples, Δt = ${interval.toPrecision(6)}, ${window} window\n${lines.join('\n')}\n`;
}

function validWindow(name: string) {
  try {
    return checkWindowName(name);
  } catch {
    throw new InputError(`--window must be hamming or none, not "${name}"`);
  }
}

/** The FFT assumes equal spacing; a gap (a dropped stretch, a merged file) would fake frequencies. */
function checkUniform(times: readonly number[], interval: number): void {
  for (let i = 1; i < times.length; i++) {
    if (Math.abs(times[i] - times[i - 1] - interval) > 1e-6 * interval + 1e-12) {
      throw new InputError(`the samples are not equally spaced in t (at t = ${times[i - 1]}); a spectrum needs a uniform series`);
    }
  }
}

/**
 * A binary file (an NPZ or Parquet export, anything with NUL bytes) is said
 * to be one, rather than read as a CSV header of garbage.
 */
function checkText(bytes: Buffer, input: string): void {
  const head = bytes.subarray(0, 8192);
  const magic = head.subarray(0, 4).toString('latin1');
  const kind = magic === 'PAR1' ? 'a Parquet file' : magic === 'PK\x03\x04' ? 'a ZIP archive (an NPZ?)' : head.includes(0) ? 'binary' : undefined;
  if (kind) throw new InputError(`${input} is ${kind}; spectrum reads CSV or JSON text, such as simulate --format csv writes`);
}

/**
 * The rows of one trajectory of a long table (a `trajectory` column, as a
 * dataset of many writes): --trajectory J, needed when there are several.
 */
function trajectoryFilter(table: { columns: readonly string[]; rows: number; data: Float64Array }, given: string | undefined, input: string): (row: number) => boolean {
  const column = table.columns.indexOf('trajectory');
  const width = table.columns.length;
  if (column < 0) {
    if (given !== undefined) throw new InputError(`${input} has no trajectory column: it holds one trajectory`);
    return () => true;
  }
  const ids = new Set<number>();
  for (let r = 0; r < table.rows; r++) ids.add(table.data[r * width + column]);
  if (given === undefined) {
    if (ids.size > 1) throw new InputError(`${input} holds ${ids.size} trajectories: choose one with --trajectory J`);
    return () => true;
  }
  const j = wholeNumber(given, '--trajectory', 0);
  if (!ids.has(j)) throw new InputError(`${input} has no trajectory ${j}`);
  return (row) => table.data[row * width + column] === j;
}
