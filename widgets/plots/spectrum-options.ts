import type { SpanOption } from './spectrum-rows.ts';

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
