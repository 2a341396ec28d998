import { ticks as linearTicks, tickStep } from 'd3-array';
import { tickFormat } from 'd3-scale';
import { minusSign } from '../controls/format.ts';
import type { Mapping, SignedKind } from './scale.ts';

/**
 * Which values an axis marks, and how it writes them.
 *
 * Tick values and labels that read at any magnitude, 1e-12 to 1e15, and for
 * tiny spans far from zero (1e9 … 1e9 + 1e-3): d3's 1-2-5 ticks with d3's
 * tickFormat for ordinary numbers, m×10ⁿ beyond 1e5 or under 1e-3, and, when
 * the ticks would need more than five significant digits to differ, labels
 * relative to a round offset shown once. The number of ticks is the largest
 * whose labels, measured, do not touch: side by side on an x axis, stacked
 * (and within the room left of the plot) on a y axis. Symlog axes get a
 * tick at every decade and a label at every decade that has room for one.
 */

/** Where the labels of one axis go, and how big they are. */
export interface LabelRoom {
  /** 'x': labels side by side along a horizontal axis; 'y': stacked beside a vertical one */
  along: 'x' | 'y';
  /** pixel (CSS) of a data value along the axis */
  position: (value: number) => number;
  /** length of the axis in CSS pixels */
  length: number;
  /** width of a label in CSS pixels (the canvas's measureText, or an estimate) */
  measure: (text: string) => number;
  /** font size in CSS pixels: how tall a stacked label is */
  font: number;
  /** y axis: the widest a label may be (the margin beside the plot) */
  room?: number;
}

export interface AxisLabels {
  /** tick values, increasing (grid lines and tick marks) */
  values: number[];
  /** a label per value; '' for a tick left unlabelled to make room */
  labels: string[];
  /** a value the labels are relative to (shown once, as `offsetText`); 0 when they are absolute */
  offset: number;
  /** the offset written out, '' when there is none */
  offsetText: string;
}

/** Horizontal room between neighbouring x labels, as a fraction of the font size. */
const X_GAP = 0.6;
/** Vertical room between stacked y labels, CSS pixels. */
const Y_GAP = 1;

/** Whether labels placed at `position(values)` keep clear of each other (and fit the room of a y axis). */
export function labelsFit(values: readonly number[], labels: readonly string[], room: LabelRoom): boolean {
  const placed: { at: number; width: number }[] = [];
  for (let i = 0; i < values.length; i++) {
    if (!labels[i]) continue;
    const width = room.measure(labels[i]);
    if (room.along === 'y' && room.room !== undefined && width > room.room) return false;
    placed.push({ at: room.position(values[i]), width });
  }
  placed.sort((a, b) => a.at - b.at);
  for (let i = 1; i < placed.length; i++) {
    const gap = placed[i].at - placed[i - 1].at;
    const needed = room.along === 'x' ? (placed[i].width + placed[i - 1].width) / 2 + X_GAP * room.font : room.font + Y_GAP;
    if (gap < needed) return false;
  }
  return true;
}

/**
 * Labels for a linear axis over [lo, hi]: the most ticks whose labels fit,
 * written out in full if they fit so, else relative to an offset.
 */
export function linearLabels(lo: number, hi: number, room: LabelRoom): AxisLabels {
  if (lo > hi) [lo, hi] = [hi, lo];
  if (!Number.isFinite(lo) || !Number.isFinite(hi)) return { values: [], labels: [], offset: 0, offsetText: '' };
  if (lo === hi) return formatLinear([lo], lo, hi);
  const spacing = room.along === 'x' ? 40 : room.font * 2;
  const most = Math.max(2, Math.min(60, Math.floor(room.length / spacing)));
  let fewest: AxisLabels | null = null;
  let previous = -1;
  for (let count = most; count >= 1; count--) {
    const values = linearTicks(lo, hi, count);
    if (values.length === 0 || values.length === previous) continue;
    // One tick does not tell a scale: when no two labels fit the room (a y label a little wider than the margin,
    // say, in a fallback font), the fewest two or more are given, squeezed by the drawing, rather than a lone "0".
    if (values.length < 2 && fewest !== null) break;
    // d3 may give more ticks than asked: no denser than about `spacing` apart, however narrow the labels
    if (values.length > 2 && Math.abs(room.position(values[1]) - room.position(values[0])) < 0.75 * spacing) continue;
    previous = values.length;
    const full = formatLinear(values, lo, hi);
    fewest = full;
    if (labelsFit(full.values, full.labels, room)) return full;
    const step = values.length > 1 ? values[1] - values[0] : hi - lo;
    // many digits alike at the front (1.0001e-12 … 1.0009e-12): the differences from an offset fit where the full values do not
    if (values.length > 1 && full.offset === 0 && Math.max(Math.abs(lo), Math.abs(hi)) / step >= 100) {
      const relative = offsetLabels(values, step);
      if (labelsFit(relative.values, relative.labels, room)) return relative;
    }
  }
  // Not even two ticks fit (a very short axis, or labels wider than the room): the fewest there are, two or
  // more if there can be, which the drawing squeezes.
  return fewest ?? { values: [], labels: [], offset: 0, offsetText: '' };
}

/** Significant digits beyond which ticks are labelled relative to an offset. */
const MAX_DIGITS = 5;

/**
 * Labels for linear tick values: d3's tickFormat for ordinary sizes,
 * m×10ⁿ for large and small ones, and offsets from a round value when the
 * step is tiny beside the values.
 */
export function formatLinear(values: readonly number[], lo: number, hi: number): AxisLabels {
  const step = values.length > 1 ? Math.abs(values[1] - values[0]) : Math.abs(tickStep(lo, hi, 1)) || Math.abs(lo) || 1;
  const largest = Math.max(...values.map(Math.abs));
  if (largest > 0 && largest / step >= 10 ** MAX_DIGITS) return offsetLabels(values, step);
  return { values: [...values], labels: plainLabels(values, step), offset: 0, offsetText: '' };
}

/** Labels without an offset: d3's in [1e-3, 1e5), else m×10ⁿ sharing the largest tick's exponent. */
function plainLabels(values: readonly number[], step: number): string[] {
  const largest = Math.max(...values.map(Math.abs));
  if (largest >= 1e5 || (largest > 0 && largest < 1e-3)) return values.map((v) => scientific(v, step));
  const n = values.length;
  const format = n > 1 ? tickFormat(values[0], values[n - 1], n - 1) : tickFormat(values[0] - step, values[0] + step, 2);
  return values.map((v) => minusSign(format(v)));
}

/** v as m×10ⁿ with its own exponent and the decimals the step needs: 2×10⁴, 1.5×10⁵, −2.5×10⁻¹². */
export function scientific(v: number, step: number): string {
  if (v === 0) return '0';
  let exponent = Math.floor(Math.log10(Math.abs(v)) + 1e-9);
  const digits = (e: number) => Math.max(0, Math.min(15, e - Math.floor(Math.log10(step) + 1e-9)));
  let mantissa = (v / 10 ** exponent).toFixed(digits(exponent));
  if (/^-?10(\.|$)/.test(mantissa)) mantissa = (v / 10 ** ++exponent).toFixed(digits(exponent));
  return `${minusSign(mantissa)}×10${superscript(exponent)}`;
}

/**
 * Labels as differences from a round offset, for ticks whose step is tiny
 * beside their size: 1e9 + 2e-4 reads "2×10⁻⁴" with the offset "1×10⁹".
 * The offset is a multiple of the power of ten just above the ticks' span,
 * so the differences stay within about two spans.
 */
function offsetLabels(values: readonly number[], step: number): AxisLabels {
  const span = Math.max(step, values[values.length - 1] - values[0]);
  const unit = 10 ** Math.ceil(Math.log10(span) - 1e-9);
  const offset = Math.floor(values[0] / unit + 1e-6) * unit;
  // differences rounded to whole steps, so that the rounding error of v − offset does not show
  const deltas = values.map((v) => Math.round((v - offset) / step) * step);
  const labels = plainLabels(deltas, step);
  return { values: [...values], labels, offset, offsetText: offsetText(offset, unit) };
}

/** The offset written with the digits it has down to `unit`, as m×10ⁿ when large or small. */
function offsetText(offset: number, unit: number): string {
  if (offset === 0) return '0';
  const exponent = Math.floor(Math.log10(Math.abs(offset)));
  const digits = Math.max(0, Math.min(15, exponent - Math.round(Math.log10(unit))));
  if (exponent < 5 && exponent >= -3) return minusSign(offset.toFixed(Math.max(0, -Math.round(Math.log10(unit)))));
  const fixed = (offset / 10 ** exponent).toFixed(digits);
  const mantissa = fixed.includes('.') ? fixed.replace(/\.?0+$/, '') : fixed;
  return `${minusSign(mantissa)}×10${superscript(exponent)}`;
}

const SUPERSCRIPT = '⁰¹²³⁴⁵⁶⁷⁸⁹';

function superscript(n: number): string {
  return String(n).replace(/\d/g, (d) => SUPERSCRIPT[Number(d)]).replace('-', '⁻');
}

/** 0, ±1, ±10, ±100, ±1000, then ±10⁴ … with a true minus sign: a symlog axis's decades. */
export function formatPower(value: number): string {
  if (value === 0) return '0';
  const sign = value < 0 ? '−' : '';
  const exponent = Math.round(Math.log10(Math.abs(value)));
  if (exponent < 4) return sign + String(Math.abs(value));
  return `${sign}10${superscript(exponent)}`;
}

/**
 * Labels for a symlog axis with constant c over [lo, hi]: a tick at 0 and
 * at ±10^k for every decade from c up, each labelled unless labels would
 * touch, in which case every 2nd, 3rd … decade is labelled (counted from the
 * largest), and a label crowding 0 gives way to it. Spans within ±10c get
 * linear labels: they hold at most one decade.
 */
export function symlogLabels(lo: number, hi: number, c: number, room: LabelRoom): AxisLabels {
  if (lo > hi) [lo, hi] = [hi, lo];
  const top = Math.max(Math.abs(lo), Math.abs(hi));
  if (!(top >= 10 * c) || !Number.isFinite(top)) return linearLabels(lo, hi, room);
  const first = Math.ceil(Math.log10(c) - 1e-9);
  const last = Math.floor(Math.log10(top) + 1e-9);
  const values: number[] = [];
  for (let k = last; k >= first; k--) if (-(10 ** k) >= lo) values.push(-(10 ** k));
  if (lo <= 0 && hi >= 0) values.push(0);
  for (let k = first; k <= last; k++) if (10 ** k <= hi) values.push(10 ** k);
  const decade = (v: number) => Math.round(Math.log10(Math.abs(v)));
  let labels: string[] = [];
  for (let stride = 1; stride <= last - first + 1; stride++) {
    labels = values.map((v) => (v === 0 || (last - decade(v)) % stride === 0 ? formatPower(v) : ''));
    // the innermost labelled decades may crowd 0; they give way to it below, which does not call for a wider stride
    const outer = labels.map((l, i) => (Math.abs(values[i]) > 10 ** (first + stride) ? l : ''));
    if (labelsFit(values, outer, room)) break;
  }
  return { values, labels: keepClear(values, labels, room), offset: 0, offsetText: '' };
}

/** Drops labels that touch one already kept, keeping 0 first, then the largest magnitudes. */
function keepClear(values: readonly number[], labels: readonly string[], room: LabelRoom): string[] {
  const order = values.map((_, i) => i).filter((i) => labels[i]);
  order.sort((a, b) => (values[a] === 0 ? -1 : values[b] === 0 ? 1 : Math.abs(values[b]) - Math.abs(values[a])));
  const kept = values.map(() => '');
  for (const i of order) {
    const trial = [...kept];
    trial[i] = labels[i];
    if (labelsFit(values, trial, room)) kept[i] = labels[i];
  }
  return kept;
}

/** Labels for an axis of either kind. */
export function axisLabels(kind: SignedKind, domain: readonly [number, number], room: LabelRoom, c = 1): AxisLabels {
  return kind === 'symlog' ? symlogLabels(domain[0], domain[1], c, room) : linearLabels(domain[0], domain[1], room);
}

/**
 * A label's width estimated from its characters at `font` pixels, a little
 * generous (proportional sans-serif fonts): for tests and for laying out
 * before a canvas exists. Digits ~0.6 em, superscripts ~0.4 em, the
 * punctuation narrower, × and − about a digit's width.
 */
export function estimateWidth(text: string, font: number): number {
  let em = 0;
  for (const ch of text) {
    if (SUPERSCRIPT.includes(ch) || ch === '⁻') em += 0.42;
    else if (ch === '.' || ch === ',' || ch === ' ') em += 0.32;
    else if (ch === '×' || ch === '−' || ch === '+') em += 0.62;
    else em += 0.62;
  }
  return em * font;
}

/**
 * Tick values for a symlog axis: 0 and ±c·10^k, thinned to every second or
 * third decade when there would be more than `count`. d3's own symlog ticks
 * are evenly spaced in data, which crowds all but one at the origin.
 */
export function symlogTicks(lo: number, hi: number, count: number, c = 1): number[] {
  const ticks: number[] = [];
  const top = Math.max(Math.abs(lo), Math.abs(hi));
  if (!(top > 0)) return lo <= 0 && hi >= 0 ? [0] : ticks;
  const first = Math.ceil(Math.log10(c) - 1e-9);
  const last = Math.floor(Math.log10(top) + 1e-9);
  const decades = Math.max(0, last - first + 1);
  const sides = (lo < 0 ? 1 : 0) + (hi > 0 ? 1 : 0);
  let step = 1;
  while (step < 10 && 1 + sides * Math.ceil(decades / step) > Math.max(count, 3)) step++;
  for (let k = last; k >= first; k -= step) if (-(10 ** k) >= lo) ticks.push(-(10 ** k));
  if (lo <= 0 && hi >= 0) ticks.push(0);
  for (let k = last - Math.floor((last - first) / step) * step; k <= last; k += step) if (10 ** k <= hi) ticks.push(10 ** k);
  return ticks.sort((p, q) => p - q);
}

/** Short labels for tick values: plain decimals in [1e-3, 1e5), else 1e6-style. */
export function formatTick(v: number): string {
  if (v === 0) return '0';
  const a = Math.abs(v);
  if (a >= 1e-3 && a < 1e5) return minusSign(String(Number(v.toPrecision(6))));
  const exponent = Math.floor(Math.log10(a));
  const mantissa = Number((v / 10 ** exponent).toPrecision(3));
  return `${mantissa === 1 ? '' : mantissa === -1 ? '−' : `${minusSign(String(mantissa))}×`}10${superscript(exponent)}`;
}

/** Tick values and their labels for a mapping, about `count` of them. */
export function ticksFor(m: Mapping, count: number): { values: number[]; labels: string[] } {
  if (m.kind === 'symlog') {
    const [lo, hi] = m.scale.domain() as [number, number];
    const values = symlogTicks(Math.min(lo, hi), Math.max(lo, hi), count, m.c);
    return { values, labels: values.map(formatTick) };
  }
  const values = m.scale.ticks(count);
  const format = m.scale.tickFormat(count);
  return { values, labels: values.map((v) => minusSign(format(v))) };
}
