/**
 * The plots' scales, value to pixel: linear, the paper's symmetric log
 * (§6.4, m(y) = ln(1 + |y|/c)·sgn y) and log, each as a d3-style scale for
 * ticks and labels together with the same map as two numbers (a Mapping),
 * pixel = a·T(v) + b, which the per-sample loops evaluate inline.
 *
 * The scales keep d3's ticks, nice domains and tick formats (d3-array,
 * d3-scale's tickFormat, and scaleLog's tick placement and label thinning,
 * which tests/unit/plots check against d3-scale) around a plain affine map.
 * d3-scale's own continuous scales interpolate through d3-interpolate, which
 * brings d3-color with it: about 7 kB gzip on every page with a plot, for
 * colour and string interpolation the plots never use (they map numbers to
 * pixels). These scales keep d3's behaviour for what the plots do use,
 * domain, range, invert, ticks, tickFormat and nice, and leave the rest.
 */
import { nice as niceDomain, ticks as linearTicks } from 'd3-array';
import { tickFormat as d3TickFormat } from 'd3-scale';

export interface NumberScale {
  (value: number): number;
  domain(): [number, number];
  domain(domain: readonly [number, number] | readonly number[]): this;
  range(): [number, number];
  range(range: readonly [number, number] | readonly number[]): this;
  invert(pixel: number): number;
  /** About `count` round values in the domain (d3's 1-2-5 ticks, evenly spaced in data). */
  ticks(count?: number): number[];
  /** The label format d3 picks for those ticks. */
  tickFormat(count?: number, specifier?: string): (value: number) => string;
  /** Extends the domain to round values, as d3's `nice`. */
  nice(count?: number): this;
}

interface Transform {
  forward(v: number): number;
  inverse(u: number): number;
}

const identity: Transform = { forward: (v) => v, inverse: (u) => u };

function scale(transform: () => Transform): NumberScale {
  let d: [number, number] = [0, 1];
  let r: [number, number] = [0, 1];
  // pixel = a·T(v) + b, refreshed whenever the domain, range or transform changes.
  let a = 1;
  let b = 0;
  const update = () => {
    const t = transform();
    const u0 = t.forward(d[0]);
    const u1 = t.forward(d[1]);
    a = u1 === u0 ? 0 : (r[1] - r[0]) / (u1 - u0);
    b = u1 === u0 ? (r[0] + r[1]) / 2 : r[0] - a * u0;
  };
  const s = ((v: number) => a * transform().forward(v) + b) as NumberScale;
  s.domain = ((value?: readonly number[]) => {
    if (value === undefined) return [d[0], d[1]];
    d = [Number(value[0]), Number(value[1])];
    update();
    return s;
  }) as NumberScale['domain'];
  s.range = ((value?: readonly number[]) => {
    if (value === undefined) return [r[0], r[1]];
    r = [Number(value[0]), Number(value[1])];
    update();
    return s;
  }) as NumberScale['range'];
  s.invert = (pixel) => transform().inverse(a === 0 ? transform().forward(d[0]) : (pixel - b) / a);
  s.ticks = (count = 10) => (d[0] <= d[1] ? linearTicks(d[0], d[1], count) : linearTicks(d[1], d[0], count).reverse());
  s.tickFormat = (count = 10, specifier) => d3TickFormat(d[0], d[1], count, specifier);
  s.nice = (count = 10) => {
    const lo = Math.min(d[0], d[1]);
    const hi = Math.max(d[0], d[1]);
    const [n0, n1] = niceDomain(lo, hi, count);
    d = d[0] <= d[1] ? [n0, n1] : [n1, n0];
    update();
    return s;
  };
  return s;
}

/** A linear scale, as d3's scaleLinear for what the plots use. */
export function scaleLinear(): NumberScale {
  return scale(() => identity);
}

/** The symlog scale T(v) = sign(v)·log1p(|v|/c), as d3's scaleSymlog; `constant` sets c. */
export function scaleSymlog(): NumberScale & { constant(c: number): NumberScale } {
  let c = 1;
  const t: Transform = {
    forward: (v) => Math.sign(v) * Math.log1p(Math.abs(v / c)),
    inverse: (u) => Math.sign(u) * Math.expm1(Math.abs(u)) * c,
  };
  const s = scale(() => t) as NumberScale & { constant(c: number): NumberScale };
  s.constant = (value: number) => {
    c = value;
    return s.domain(s.domain());
  };
  return s;
}

const logTransform: Transform = { forward: Math.log, inverse: Math.exp };

/**
 * The ticks of a log axis from `lo` to `hi` (0 < lo ≤ hi), as d3's scaleLog
 * places them: while the decades spanned are fewer than `count`, every
 * k·10ⁿ (k = 1…9) inside, or d3's linear ticks when those are under half of
 * `count`; beyond that, powers of ten at a 1-2-5 step in the exponent.
 */
export function logTicks(lo: number, hi: number, count = 10): number[] {
  const e0 = Math.log10(lo);
  const e1 = Math.log10(hi);
  // "1e-5" and not 10 ** -5, which is one rounding off
  if (e1 - e0 >= count) return linearTicks(e0, e1, Math.min(e1 - e0, count)).map((e) => Number(`1e${e}`));
  const values: number[] = [];
  for (let e = Math.floor(e0); e <= Math.ceil(e1); e++) {
    for (let k = 1; k < 10; k++) {
      // k/10^|e| rather than k·10^e below 1, so that 0.3 is 0.3 and not 0.30000000000000004
      const v = e < 0 ? k / Number(`1e${-e}`) : k * Number(`1e${e}`);
      if (v >= lo && v <= hi) values.push(v);
    }
  }
  return values.length * 2 < count ? linearTicks(lo, hi, count) : values;
}

/**
 * A log scale for positive values, with d3 scaleLog's ticks (logTicks) and
 * its thinning of their labels: with `count` asked for, a tick k·10ⁿ is
 * labelled when k ≤ max(1, 10·count / the number of its ten ticks), so a crowded axis
 * labels its powers of ten and leaves the 2…9 multiples as marks. `label`
 * writes a labelled tick.
 */
export function scaleLog(label: (value: number) => string): NumberScale {
  const s = scale(() => logTransform);
  s.ticks = (count = 10) => {
    const [d0, d1] = s.domain();
    const values = logTicks(Math.min(d0, d1), Math.max(d0, d1), count);
    return d0 <= d1 ? values : values.reverse();
  };
  s.tickFormat = (count = 10) => {
    const most = Math.max(1, (10 * count) / Math.max(1, s.ticks().length));
    return (v) => {
      let mantissa = v / Number(`1e${Math.round(Math.log10(v))}`);
      if (mantissa * 10 < 9.5) mantissa *= 10;
      return mantissa <= most ? label(v) : '';
    };
  };
  s.nice = () => {
    const [d0, d1] = s.domain();
    const n0 = Number(`1e${Math.floor(Math.log10(Math.min(d0, d1)))}`);
    const n1 = Number(`1e${Math.ceil(Math.log10(Math.max(d0, d1)))}`);
    return s.domain(d0 <= d1 ? [n0, n1] : [n1, n0]);
  };
  return s;
}

/** How an axis maps data to pixels: straight, the paper's symmetric log with constant c, or log (positive values only). */
export type AxisKind = 'linear' | 'symlog' | 'log';

/** The kinds an axis of signed values may take: a log axis would drop every sign change (of q or p, say). */
export type SignedKind = Exclude<AxisKind, 'log'>;

export type Domain = readonly [number, number];

/** The forward transform T of an axis kind; symlog's is d3's scaleSymlog transform with constant c. */
export function transform(kind: AxisKind, v: number, c = 1): number {
  if (kind === 'symlog') return Math.sign(v) * Math.log1p(Math.abs(v / c));
  return kind === 'log' ? Math.log(v) : v;
}

/** The inverse of `transform`. */
export function untransform(kind: AxisKind, u: number, c = 1): number {
  if (kind === 'symlog') return Math.sign(u) * Math.expm1(Math.abs(u)) * c;
  return kind === 'log' ? Math.exp(u) : u;
}

/** The d3-style scale of a linear or symlog axis over `domain` onto `range`, for ticks and labels (a log axis's is scaleLog(label)). */
export function scaleFor(kind: SignedKind, domain: Domain, range: Domain, c = 1): NumberScale {
  const scale = kind === 'symlog' ? scaleSymlog().constant(c) : scaleLinear();
  return scale.domain(domain).range(range);
}

/**
 * One axis of a plot: its d3-style scale (for ticks and labels) and the same
 * map as two numbers, pixel = a·T(v) + b, so that per-sample loops do a
 * multiply-add instead of a call through the scale. Both agree to rounding,
 * a zero-width domain included (everything at the middle of the range).
 */
export interface Mapping {
  readonly kind: AxisKind;
  readonly c: number;
  readonly a: number;
  readonly b: number;
  readonly scale: NumberScale;
}

/** The mapping of `domain` onto `range`; a log axis passes its scale, scaleLog(label) with the same domain and range. */
export function makeMapping(kind: AxisKind, domain: Domain, range: Domain, c = 1, given?: NumberScale): Mapping {
  if (!given && kind === 'log') throw new Error('makeMapping: a log axis takes its scale from the caller, scaleLog(label)');
  const scale = given ?? scaleFor(kind as SignedKind, domain, range, c);
  const u0 = transform(kind, domain[0], c);
  const u1 = transform(kind, domain[1], c);
  const a = u1 === u0 ? 0 : (range[1] - range[0]) / (u1 - u0);
  return { kind, c, a, b: u1 === u0 ? (range[0] + range[1]) / 2 : range[0] - a * u0, scale };
}

/** Data value to pixel; allocation-free, for per-sample loops. */
export function toPixel(m: Mapping, v: number): number {
  if (m.kind === 'linear') return m.a * v + m.b;
  if (m.kind === 'symlog') return m.a * Math.sign(v) * Math.log1p(Math.abs(v / m.c)) + m.b;
  return m.a * Math.log(v) + m.b;
}
