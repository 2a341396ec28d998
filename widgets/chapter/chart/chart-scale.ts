/**
 * The numbers behind a chart's picture: the domain each axis shows (fitted
 * to the data when the chapter gives none), formula curves sampled across
 * it, the plot's rectangle at a given width, and the axes as d3 scales with
 * their ticks and labels (plots/scale.ts, linear or log).
 * Pure, so it is unit-tested in Node.
 */
import { minusSign } from '../../controls/format.ts';
import { MARGIN, type Rect } from '../../plots/axes.ts';
import { makeMapping, scaleFor, scaleLinear, scaleLog, type Mapping, type NumberScale } from '../../plots/scale.ts';
import { formatTick } from '../../plots/ticks.ts';
import type { Curve, ResolvedAxis, ResolvedChart } from './chart-options.ts';

/** Space around the plot: the foundation's margins, less the top strip it keeps for a canvas legend (the chart's legend is text below). */
export const CHART_MARGIN = { left: MARGIN.left + 6, right: MARGIN.right + 4, top: 12, bottom: MARGIN.bottom + 4 };

/** Tick labels are drawn at this size in CSS pixels (plots/axes.ts), and the canvas is never scaled down. */
export const AXIS_FONT_PX = 11;

/** Every value of a list of curves, one coordinate. */
function* valuesOf(curves: readonly Curve[], coordinate: 'x' | 'y'): Generator<number> {
  for (const c of curves) yield* c[coordinate];
}

/**
 * The interval an axis shows for `values`: on a linear axis their extent,
 * rounded out to ticks, and starting at zero when none is negative and zero
 * lies within one span of them (a quantity that cannot be negative keeps its
 * floor); on a log axis the decades around their positive values.
 */
export function fitDomain(values: Iterable<number>, scale: 'linear' | 'log'): [number, number] {
  let lo = Infinity;
  let hi = -Infinity;
  for (const v of values) {
    if (!Number.isFinite(v) || (scale === 'log' && !(v > 0))) continue;
    if (v < lo) lo = v;
    if (v > hi) hi = v;
  }
  if (scale === 'log') {
    if (!(lo <= hi)) return [1, 10];
    const a = 10 ** Math.floor(Math.log10(lo) + 1e-12);
    const b = 10 ** Math.ceil(Math.log10(hi) - 1e-12);
    return a === b ? [a, b * 10] : [a, b];
  }
  if (!(lo <= hi)) return [0, 1];
  if (lo === hi) {
    const half = Math.abs(lo) * 0.1 || 1;
    [lo, hi] = [lo - half, hi + half];
  }
  const span = hi - lo;
  if (lo >= 0 && lo <= span) lo = 0;
  else if (hi <= 0 && -hi <= span) hi = 0;
  return scaleLinear().domain([lo, hi]).nice(8).domain() as [number, number];
}

/** `n` values from `a` to `b`, evenly spaced, or evenly in log when `log`. */
export function samplePoints(a: number, b: number, n: number, log: boolean): Float64Array {
  const out = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    const f = i / (n - 1);
    out[i] = log ? a * (b / a) ** f : a + (b - a) * f;
  }
  out[n - 1] = b;
  return out;
}

/** y = f(x) at each x; a value that throws or is not a finite number is NaN, which breaks the line there. */
export function sampleFormula(f: (x: number) => number, xs: Float64Array): Curve {
  const y = new Float64Array(xs.length);
  for (let i = 0; i < xs.length; i++) {
    let v: unknown;
    try {
      v = f(xs[i]);
    } catch {
      v = NaN;
    }
    y[i] = typeof v === 'number' && Number.isFinite(v) ? v : NaN;
  }
  return { x: xs, y };
}

/** A chart with its formulas sampled and both domains settled. */
export interface SettledChart extends ResolvedChart {
  xDomain: [number, number];
  yDomain: [number, number];
}

/**
 * Samples the formula curves and settles the domains: x from the option or
 * the data (and the formulas' own ranges), then the formulas across it, then
 * y from the option or everything drawn, including the rules.
 */
export function settleChart(chart: ResolvedChart): SettledChart {
  const xs = [...valuesOf(chart.series.flatMap((s) => s.curves), 'x')];
  for (const s of chart.series) if (s.functions) xs.push(...[s.from, s.to].filter((v): v is number => v !== undefined));
  for (const r of chart.rules) if (r.x !== undefined) xs.push(r.x);
  const fitted = xs.some((v) => Number.isFinite(v) && (chart.x.scale === 'linear' || v > 0));
  if (!chart.x.domain && !fitted && chart.series.some((s) => s.functions)) {
    throw new Error('chart: a formula needs the x axis\'s domain, or from and to, to know where to draw');
  }
  const xDomain = chart.x.domain ?? fitDomain(xs, chart.x.scale);
  const log = chart.x.scale === 'log';
  const series = chart.series.map((s) => {
    if (!s.functions) return s;
    const a = s.from ?? Math.min(...xDomain);
    const b = s.to ?? Math.max(...xDomain);
    if (log && !(a > 0 && b > 0)) throw new Error('chart: a formula on a log x axis needs positive from and to');
    const at = samplePoints(a, b, s.samples, log);
    const functions = s.functions;
    return { ...s, curves: s.curves.map((c, i) => (c.x.length === 0 && functions[i] ? sampleFormula(functions[i], at) : c)) };
  });
  const ys = [...valuesOf(series.flatMap((s) => s.curves), 'y')];
  for (const r of chart.rules) if (r.y !== undefined) ys.push(r.y);
  const yDomain = chart.y.domain ?? fitDomain(ys, chart.y.scale);
  return { ...chart, series, xDomain, yDomain };
}

/** The plot's rectangle and the figure's height at a width in CSS pixels. */
export function layoutChart(chart: SettledChart, width: number): { rect: Rect; height: number } {
  const w = Math.max(200, width);
  let plotWidth = w - CHART_MARGIN.left - CHART_MARGIN.right;
  let plotHeight = chart.height - CHART_MARGIN.top - CHART_MARGIN.bottom;
  if (chart.equalAspect) {
    const ratio = Math.abs(chart.yDomain[1] - chart.yDomain[0]) / Math.abs(chart.xDomain[1] - chart.xDomain[0]);
    // A given height caps the plot (a small figure in a wide column): the plot then narrows to keep the units equal.
    const most = chart.heightGiven ? Math.min(1200, plotHeight) : 1200;
    plotHeight = Math.min(most, Math.max(80, plotWidth * ratio));
    if (chart.heightGiven) plotWidth = Math.min(plotWidth, plotHeight / ratio);
  }
  return {
    rect: { left: CHART_MARGIN.left, top: CHART_MARGIN.top, width: plotWidth, height: plotHeight },
    height: Math.round(plotHeight + CHART_MARGIN.top + CHART_MARGIN.bottom),
  };
}

/** Round labels for given tick values: shortest form to six digits, with a true minus sign. */
function fixedFormat(v: number): string {
  return minusSign(String(Number(v.toPrecision(6))));
}

/**
 * About how many ticks an axis of `pixels` wants: d3's count. A log axis
 * spanning at least two decades asks for one a decade when each gets
 * `spacing` pixels (d3 then labels every power of ten), else for fewer.
 */
export function tickCount(axis: ResolvedAxis, domain: readonly [number, number], pixels: number, spacing: number): number {
  const budget = Math.max(2, Math.floor(pixels / spacing));
  if (axis.scale !== 'log') return budget;
  const lo = Math.min(...domain);
  const hi = Math.max(...domain);
  // d3's scaleLog gives one tick a power of ten when the count is at most the decades spanned, else 1–9 multiples
  const decades = Math.floor(Math.log10(hi) - Math.log10(lo) + 1e-9);
  return decades >= 2 ? Math.min(decades, budget) : budget;
}

/** `base` with other ticks or another tick format, the rest (domain, range, invert) its own. */
function retick(base: NumberScale, ticks: NumberScale['ticks'], tickFormat: NumberScale['tickFormat']): NumberScale {
  const s = ((v: number) => base(v)) as NumberScale;
  Object.assign(s, base, { ticks, tickFormat });
  s.domain = base.domain;
  s.range = base.range;
  s.invert = base.invert;
  return s;
}

/**
 * An axis as the plot foundation's Mapping (a scale with ticks and tick
 * labels), for plots/axes.ts. A log axis has d3's log ticks, labelled by
 * the foundation's formatTick (0.01, 1, 100, 10⁻¹¹); given ticks replace
 * the scale's choice.
 */
export function axisMapping(axis: ResolvedAxis, domain: readonly [number, number], range: readonly [number, number]): Mapping {
  let scale = axis.scale === 'log' ? scaleLog(formatTick).domain(domain).range(range) : scaleFor(axis.scale, domain, range);
  if (axis.ticks) {
    const [lo, hi] = [Math.min(...domain), Math.max(...domain)];
    const fixed = axis.ticks.filter((v) => v >= lo && v <= hi && (axis.scale === 'linear' || v > 0));
    scale = retick(scale, () => fixed, () => fixedFormat);
  }
  return makeMapping(axis.scale, domain, range, 1, scale);
}

/** Whether a point can be drawn on these axes (finite, and positive on a log axis). */
export function drawable(x: number, y: number, xLog: boolean, yLog: boolean): boolean {
  return Number.isFinite(x) && Number.isFinite(y) && (!xLog || x > 0) && (!yLog || y > 0);
}
