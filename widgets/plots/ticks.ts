import { scaleLinear } from './scale.ts';
import type { Domain, YScaleKind } from './y-map.ts';

/** Tick values and their labels. */
export interface Ticks {
  values: number[];
  format: (value: number) => string;
}

/**
 * Ticks for an axis. Linear axes use d3's 1-2-5 ticks and formats; a symlog
 * axis spanning decades gets 0 and signed powers of ten, thinned to every
 * 2nd, 3rd … decade when there are too many, because d3's symlog scale
 * offers only linear ticks, which bunch at one end.
 */
export function axisTicks(kind: YScaleKind, domain: Domain, count: number): Ticks {
  const lo = Math.min(domain[0], domain[1]);
  const hi = Math.max(domain[0], domain[1]);
  const big = Math.max(Math.abs(lo), Math.abs(hi));
  if (kind === 'linear' || big < 10) {
    const scale = scaleLinear().domain([lo, hi]);
    const values = scale.ticks(count);
    const largest = Math.max(...values.map(Math.abs));
    const scientific = largest >= 1e5 || (largest > 0 && largest < 1e-3);
    return { values, format: scientific ? scientificFormat(values) : scale.tickFormat(count) };
  }
  const decades = Math.floor(Math.log10(big));
  for (let stride = 1; ; stride++) {
    const values = powersOfTen(lo, hi, decades, stride);
    if (values.length <= Math.max(3, count) || stride > decades) return { values, format: formatPower };
  }
}

/** 0 and ±10^k for k a multiple of `stride`, within [lo, hi], in increasing order. */
function powersOfTen(lo: number, hi: number, decades: number, stride: number): number[] {
  const out: number[] = [];
  for (let k = decades; k >= 0; k--) if (k % stride === 0 && -(10 ** k) >= lo) out.push(-(10 ** k));
  if (lo <= 0 && hi >= 0) out.push(0);
  for (let k = 0; k <= decades; k++) if (k % stride === 0 && 10 ** k <= hi) out.push(10 ** k);
  return out;
}

const SUPERSCRIPT = '⁰¹²³⁴⁵⁶⁷⁸⁹';

/**
 * Labels m×10ⁿ sharing the exponent of the largest tick, with the decimals
 * the step needs, so 2e9, 4e9 read 2×10⁹, 4×10⁹ and fit beside the axis.
 */
export function scientificFormat(values: readonly number[]): (value: number) => string {
  const largest = Math.max(...values.map(Math.abs));
  const exponent = Math.floor(Math.log10(largest));
  const step = values.length > 1 ? Math.abs(values[1] - values[0]) : largest;
  const digits = Math.max(0, Math.min(6, exponent - Math.floor(Math.log10(step) + 1e-9)));
  const power = `10${superscript(exponent)}`;
  return (value) => (value === 0 ? '0' : `${(value / 10 ** exponent).toFixed(digits).replace('-', '−')}×${power}`);
}

function superscript(n: number): string {
  return String(n).replace(/\d/g, (d) => SUPERSCRIPT[Number(d)]).replace('-', '⁻');
}

/** 0, ±1, ±10, ±100, ±1000, then ±10⁴ … with a true minus sign. */
export function formatPower(value: number): string {
  if (value === 0) return '0';
  const sign = value < 0 ? '−' : '';
  const exponent = Math.round(Math.log10(Math.abs(value)));
  if (exponent < 4) return sign + String(Math.abs(value));
  return `${sign}10${superscript(exponent)}`;
}
