import { scaleLinear, scaleSymlog, type NumberScale } from './scale.ts';
import { transform, type AxisKind } from './extent.ts';

/**
 * One axis of a plot as a d3 scale (for ticks and labels) together with the
 * same map as two numbers, pixel = a·T(v) + b, so that the per-sample loops
 * do a multiply-add instead of a call through d3's interpolators. T is the
 * identity or d3's symlog transform, so both agree to rounding.
 */
export interface Mapping {
  readonly kind: AxisKind;
  readonly c: number;
  readonly a: number;
  readonly b: number;
  readonly scale: NumberScale;
}

export function makeMapping(kind: AxisKind, domain: readonly [number, number], range: readonly [number, number], c = 1): Mapping {
  const scale = kind === 'symlog' ? scaleSymlog().constant(c) : scaleLinear();
  scale.domain(domain).range(range);
  const u0 = transform(kind, domain[0], c);
  const u1 = transform(kind, domain[1], c);
  const a = u1 === u0 ? 0 : (range[1] - range[0]) / (u1 - u0);
  return { kind, c, a, b: range[0] - a * u0, scale };
}

/** Data value to pixel; allocation-free, for per-sample loops. */
export function toPixel(m: Mapping, v: number): number {
  if (m.kind === 'linear') return m.a * v + m.b;
  return m.a * Math.sign(v) * Math.log1p(Math.abs(v / m.c)) + m.b;
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
  if (a >= 1e-3 && a < 1e5) return String(Number(v.toPrecision(6))).replace('-', '−');
  const exponent = Math.floor(Math.log10(a));
  const mantissa = Number((v / 10 ** exponent).toPrecision(3));
  return `${mantissa === 1 ? '' : mantissa === -1 ? '−' : `${mantissa}×`}10${superscript(exponent)}`;
}

const SUPERSCRIPTS = '⁰¹²³⁴⁵⁶⁷⁸⁹';

function superscript(n: number): string {
  return (n < 0 ? '⁻' : '') + String(Math.abs(n)).replace(/\d/g, (d) => SUPERSCRIPTS[Number(d)]);
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
  return { values, labels: values.map((v) => format(v).replace('-', '−')) };
}
