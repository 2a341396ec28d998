import type { TrajectoryRecord } from '../../../core/index.ts';

/** Which part of the record a spectrum is taken over: the latest `span` time units, a fixed [t0, t1], or all of it. */
export type SpanOption = number | readonly [number, number];

/** The rows a spectrum uses, and how they are thinned. */
export interface RowChoice {
  /** first row used */
  from: number;
  /** one past the last row used */
  to: number;
  /** each spectrum sample is the mean of this many consecutive rows */
  stride: number;
  /** (to − from) / stride */
  samples: number;
  /** time between spectrum samples: stride times the record's spacing */
  interval: number;
  /** the time the samples cover, samples × interval */
  duration: number;
}

/** Fewer samples than this make no useful spectrum: the 'not enough samples yet' state. */
export const MIN_SAMPLES = 64;

/** The part of a record `chooseRows` reads. */
export type TimedRows = Pick<TrajectoryRecord, 'length' | 'time' | 'range'>;

/** Rows [from, to) of the record within `span`. */
export function rowsInSpan(rows: TimedRows, span: SpanOption | undefined): [number, number] {
  const n = rows.length;
  if (n === 0) return [0, 0];
  if (typeof span === 'number') {
    const last = rows.time(n - 1);
    return rows.range(last - span, last);
  }
  return span ? rows.range(span[0], span[1]) : [0, n];
}

/**
 * Chooses rows for a spectrum over `span`, thinned by block means to at most
 * `maxSamples` (a mean over `stride` rows is a mild low-pass, so that the
 * thinning does not alias high frequencies onto the plot the way picking
 * every stride-th row would). Blocks are aligned to the newest row, which
 * is always used. Returns null when there are fewer than MIN_SAMPLES.
 */
export function chooseRows(rows: TimedRows, span: SpanOption | undefined, maxSamples: number): RowChoice | null {
  let [from, to] = rowsInSpan(rows, span);
  const available = to - from;
  if (available < MIN_SAMPLES) return null;
  const stride = Math.max(1, Math.ceil(available / Math.max(MIN_SAMPLES, maxSamples)));
  const samples = Math.floor(available / stride);
  from = to - samples * stride;
  const spacing = (rows.time(to - 1) - rows.time(from)) / (to - from - 1);
  if (!(spacing > 0)) return null;
  const interval = spacing * stride;
  return { from, to, stride, samples, interval, duration: samples * interval };
}

/**
 * Writes the chosen samples of `column` into out[0 … samples) (block means
 * when stride > 1) and returns a view of that many values. `out` must hold
 * at least `choice.samples`.
 */
export function gatherSamples(record: TrajectoryRecord, column: number, choice: RowChoice, out: Float64Array): Float64Array {
  const { from, to, stride } = choice;
  const width = record.width;
  let k = 0;
  let sum = 0;
  let inBlock = 0;
  for (const s of record.slices(from, to)) {
    for (let r = s.from; r < s.to; r++) {
      sum += s.data[r * width + column];
      if (++inBlock === stride) {
        out[k++] = sum / stride;
        sum = 0;
        inBlock = 0;
      }
    }
  }
  return out.subarray(0, k);
}

/** The options of spectrumView that can be wrong in a way worth a message of its own. */
export interface CheckedSpectrumOptions {
  window?: unknown;
  show?: unknown;
  span?: SpanOption;
  maxFrequency?: number;
  peaks?: number;
  refresh?: number;
  maxSamples?: number;
}

/** Throws a one-line message naming the first bad option of spectrumView, so a chapter's typo is reported where it is made. */
export function checkSpectrumOptions(o: CheckedSpectrumOptions): void {
  const fail = (what: string, value: unknown): never => {
    throw new Error(`spectrumView: ${what}, not ${JSON.stringify(value)}`);
  };
  if (o.window !== undefined && o.window !== 'hamming' && o.window !== 'none') fail(`window must be 'hamming' or 'none'`, o.window);
  if (o.show !== undefined && o.show !== 'magnitude' && o.show !== 'reim' && o.show !== 'both') fail(`show must be 'magnitude', 'reim' or 'both'`, o.show);
  const { span } = o;
  if (span !== undefined) {
    const ok = typeof span === 'number' ? span > 0 && Number.isFinite(span) : Array.isArray(span) && span.length === 2 && span[1] > span[0];
    if (!ok) fail('span must be a positive number of time units or [t0, t1] with t0 < t1', span);
  }
  if (o.maxFrequency !== undefined && !(o.maxFrequency > 0 && Number.isFinite(o.maxFrequency))) fail('maxFrequency must be a positive number', o.maxFrequency);
  if (o.peaks !== undefined && !(Number.isInteger(o.peaks) && o.peaks >= 0)) fail('peaks must be a whole number ≥ 0', o.peaks);
  if (o.refresh !== undefined && !(o.refresh >= 0)) fail('refresh must be a number of milliseconds ≥ 0', o.refresh);
  if (o.maxSamples !== undefined && !(Number.isInteger(o.maxSamples) && o.maxSamples >= 64)) fail('maxSamples must be a whole number ≥ 64', o.maxSamples);
}
