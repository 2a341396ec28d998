/**
 * `phasebook spectrum`: the strongest lines of one column's spectrum, for
 * one trajectory of any file phasebook writes (formats/samples-read.ts).
 */
import { checkWindowName, findPeaks, InputError, spectrum } from '../../core/index.ts';
import { number, parseArgs, wholeNumber } from '../options/args.ts';
import { SPECTRUM } from '../options/commands.ts';
import { openSamples, type Samples } from '../formats/samples-read.ts';
import { usageLine } from '../options/usage.ts';

export async function spectrumCommand(argv: readonly string[]): Promise<string> {
  const args = parseArgs(argv, SPECTRUM);
  const input = args.values.get('input');
  const name = args.values.get('column');
  if (!input) throw new InputError(`--input is required (usage: ${usageLine(SPECTRUM)})`);
  if (!name) throw new InputError('--column is required: name the series to analyse, e.g. --column q');
  const window = validWindow(args.values.get('window') ?? 'hamming');
  const top = wholeNumber(args.values.get('top') ?? '5', '--top');
  const format = args.values.get('format') ?? 'text';
  if (format !== 'text' && format !== 'json') throw new InputError(`--format must be text or json, not "${format}"`);
  const bound = (name: string, fallback: number) => {
    const text = args.values.get(name);
    return text === undefined ? fallback : number(text, `--${name}`);
  };
  const from = bound('from', -Infinity);
  const to = bound('to', Infinity);
  if (to < from) throw new InputError(`--to (${to}) is before --from (${from})`);

  const samples = await openSamples(input);
  let times: number[];
  let series: number[];
  try {
    ({ times, series } = await seriesOf(samples, input, name, args.values.get('trajectory'), from, to));
  } finally {
    samples.close();
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

/**
 * The samples of `name` in [from, to], of the one trajectory the file holds
 * or the one --trajectory J picks (a dataset holds several, numbered).
 */
async function seriesOf(samples: Samples, input: string, name: string, given: string | undefined, from: number, to: number) {
  const c = samples.columns.indexOf(name);
  if (c < 0) throw new InputError(`no column "${name}" in ${input}; it has ${samples.columns.join(', ')}`);
  if (!samples.columns.includes('t')) throw new InputError(`${input} has no t column`);
  if (!samples.numbered && given !== undefined) throw new InputError(`${input} has no trajectory column: it holds one trajectory`);
  const j = given === undefined ? undefined : wholeNumber(given, '--trajectory', 0);
  // A dataset's meta says how many it holds: no need to read them all to know that one must be chosen.
  if (j === undefined && samples.count !== undefined && samples.count > 1) throw severalIn(input, samples.count);
  const ids = new Set<number>();
  const times: number[] = [];
  const series: number[] = [];
  let unfit: { time: number; value: number } | undefined;
  await samples.each(c, (trajectory, time, value) => {
    ids.add(trajectory);
    if ((j !== undefined && trajectory !== j) || !(time >= from && time <= to)) return;
    if (!Number.isFinite(value)) unfit ??= { time, value };
    times.push(time);
    series.push(value);
  });
  // Which trajectory is said before what is wrong with its samples.
  if (j === undefined && ids.size > 1) throw severalIn(input, ids.size);
  if (j !== undefined && !ids.has(j)) throw new InputError(`${input} has no trajectory ${j}`);
  if (unfit) throw new InputError(`${name} is ${unfit.value} at t = ${unfit.time} in ${input}; a spectrum needs finite samples (narrow --from/--to to leave it out)`);
  return { times, series };
}

const severalIn = (input: string, count: number) => new InputError(`${input} holds ${count} trajectories: choose one with --trajectory J`);

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
