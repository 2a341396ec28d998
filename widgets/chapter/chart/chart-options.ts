/**
 * What a chapter writes to draw a figure, and the one step that turns it into
 * checked data: `chart({label, x, y, series, rules})` in a cell. Pure (no
 * DOM), so the checks and the sampling of formula curves are unit-tested in
 * Node; chapter/chart/chart.ts draws the result.
 *
 * Every error message is here, each naming the option at fault, so that a
 * slip in a cell shows one line under that cell and nothing crashes.
 */

/** A colour of the book's series palette (the same in every plot and theme), or the text's own colours. */
export type ChartColor = 'blue' | 'orange' | 'teal' | 'raspberry' | 'violet' | 'ochre' | 'green' | 'slate' | 'text' | 'muted';

/** The palette's names, in the order of the plots' palette (plots/theme.ts). */
export const PALETTE_NAMES: readonly ChartColor[] = ['blue', 'orange', 'teal', 'raspberry', 'violet', 'ochre', 'green', 'slate'];

/** A curve given by its points: `[[x, y], …]` or the two columns `{x, y}` (typed arrays welcome). */
export type ChartCurve = ArrayLike<readonly [number, number]> | { x: ArrayLike<number>; y: ArrayLike<number> };

/** One axis of a chart. */
export interface ChartAxisOptions {
  /** the axis title, with the quantity's symbol or unit, e.g. 'time t' */
  label?: string;
  /** [from, to]; by default the data's extent, rounded to ticks, with zero as the floor when no value is negative */
  domain?: readonly [number, number];
  /** 'linear' (the default) or 'log' (positive values only; every decade labelled when there is room) */
  scale?: 'linear' | 'log';
  /** tick values, when d3's choice will not do (e.g. every 30 degrees) */
  ticks?: readonly number[];
}

/**
 * One series of a chart. Give exactly one of: `points` (or `x` and `y`), a
 * family of `lines`, a `formula` y(x), a parametric `curve` (x(s), y(s)), or
 * a band between `lower` and `upper`.
 */
export interface ChartSeriesOptions {
  /** the legend's name; a series without one is drawn but not listed in the legend */
  label?: string;
  /** measured points `[[x, y], …]` */
  points?: ArrayLike<readonly [number, number]>;
  /** the x column of the points (with `y`), e.g. a record's column */
  x?: ArrayLike<number>;
  /** the y column of the points (with `x`) */
  y?: ArrayLike<number>;
  /** several curves of one kind under one legend entry, e.g. the trajectories of a beam: each `[[x, y], …]` or `{x, y}` */
  lines?: readonly ChartCurve[];
  /** a formula y(x), sampled densely across the x axis (or over `from` … `to`) */
  formula?: (x: number) => number;
  /** a curve given by a parameter, s ↦ [x, y], e.g. an orbit over one period: (t) => [cos(ω t), −sin(ω t)], with `from` and `to` the parameter's range */
  curve?: (s: number) => readonly [number, number];
  /** where the formula (or a band's function edges) starts (default: the x axis's start); a curve's first parameter value */
  from?: number;
  /** where the formula (or a band's function edges) ends (default: the x axis's end); a curve's last parameter value */
  to?: number;
  /** points at which a formula or a curve is sampled (default 400) */
  samples?: number;
  /** the lower edge of a shaded band: points, or a function of x sampled like a formula */
  lower?: ChartCurve | ((x: number) => number);
  /** the upper edge of a shaded band: points, or a function of x sampled like a formula */
  upper?: ChartCurve | ((x: number) => number);
  /** 'line' (joined) or 'dots' (a marker per point); points default to dots, the rest to lines */
  mark?: 'line' | 'dots';
  /** a palette colour; by default the next one */
  color?: ChartColor;
  /** a dashed line: true, or the dash pattern in pixels, e.g. [6, 4] */
  dash?: boolean | readonly number[];
  /** line width in pixels (default 2) */
  width?: number;
  /** 0 … 1 (default 1) */
  opacity?: number;
  /** dot radius in pixels (default 3) */
  radius?: number;
}

/** A dashed marker line across the chart at x or at y, with a label. */
export interface ChartRuleOptions {
  /** a vertical line at this x */
  x?: number;
  /** a horizontal line at this y */
  y?: number;
  label?: string;
  /** drawn lighter, for a reference that matters less */
  faint?: boolean;
}

export interface ChartOptions {
  /** what the figure shows, in words: the chart's accessible name and the start of its text description */
  label: string;
  x?: ChartAxisOptions;
  y?: ChartAxisOptions;
  series: readonly ChartSeriesOptions[];
  /** marker lines; false, null or undefined entries are skipped, so `cond && {x: …}` works */
  rules?: readonly (ChartRuleOptions | false | null | undefined)[];
  /** height in CSS pixels (default 320); with `aspect: 'equal'`, the most the figure may take (the plot then narrows instead) */
  height?: number;
  /** 'equal': one unit as long across as up, so circles stay round (linear axes); as wide as the column allows unless `height` is given */
  aspect?: 'equal';
  /** the downloaded files' name, without extension (default: from the label) */
  name?: string;
}

/** A curve as two columns of equal length. */
export interface Curve {
  x: Float64Array;
  y: Float64Array;
}

export interface ResolvedSeries {
  label: string | null;
  kind: 'line' | 'dots' | 'band';
  /** where the series came from, for the text description */
  source: 'points' | 'lines' | 'formula' | 'curve' | 'band';
  /** the curves drawn: one for points and formulas, several for `lines`, [lower, upper] for a band (functions' curves are filled in by settleChart) */
  curves: Curve[];
  /** functions of x to sample into the curve of the same index: a formula, a band's function edges */
  functions: ((x: number) => number)[] | null;
  /** an index into the palette, or 'text' / 'muted' */
  color: number | 'text' | 'muted';
  dash: readonly number[];
  width: number;
  opacity: number;
  radius: number;
  from?: number;
  to?: number;
  samples: number;
}

export interface ResolvedAxis {
  label: string;
  scale: 'linear' | 'log';
  /** as given, or null to fit the data */
  domain: [number, number] | null;
  ticks: number[] | null;
}

export interface ResolvedRule {
  x?: number;
  y?: number;
  label: string;
  faint: boolean;
}

export interface ResolvedChart {
  label: string;
  name: string;
  x: ResolvedAxis;
  y: ResolvedAxis;
  series: ResolvedSeries[];
  rules: ResolvedRule[];
  height: number;
  /** whether the chapter gave the height (with an equal aspect it is then a limit; otherwise the width decides) */
  heightGiven: boolean;
  equalAspect: boolean;
}

const SERIES_KEYS = new Set(['label', 'points', 'x', 'y', 'lines', 'formula', 'curve', 'from', 'to', 'samples', 'lower', 'upper', 'mark', 'color', 'dash', 'width', 'opacity', 'radius']);
const CHART_KEYS = new Set(['label', 'x', 'y', 'series', 'rules', 'height', 'aspect', 'name']);
const AXIS_KEYS = new Set(['label', 'domain', 'scale', 'ticks']);
const RULE_KEYS = new Set(['x', 'y', 'label', 'faint']);

const isObject = (v: unknown): v is Record<string, unknown> => typeof v === 'object' && v !== null && !Array.isArray(v);

function unknownKeys(where: string, value: Record<string, unknown>, known: Set<string>): void {
  const extra = Object.keys(value).filter((k) => !known.has(k));
  if (extra.length) throw new Error(`chart: ${where} has no option ${extra.map((k) => `'${k}'`).join(', ')} (it takes ${[...known].join(', ')})`);
}

function isArrayLike(v: unknown): v is ArrayLike<unknown> {
  return Array.isArray(v) || ArrayBuffer.isView(v) || (isObject(v) && typeof (v as { length?: unknown }).length === 'number');
}

/** A curve from `[[x, y], …]` or `{x, y}`; entries that are not numbers become NaN, which breaks the line there. */
export function toCurve(where: string, value: unknown): Curve {
  if (isObject(value) && 'x' in value && 'y' in value && !isArrayLike(value)) {
    const { x, y } = value as { x: unknown; y: unknown };
    if (!isArrayLike(x) || !isArrayLike(y)) throw new Error(`chart: ${where}: x and y must be arrays of numbers`);
    if (x.length !== y.length) throw new Error(`chart: ${where}: x has ${x.length} values but y has ${y.length}`);
    return { x: Float64Array.from(x as ArrayLike<number>, Number), y: Float64Array.from(y as ArrayLike<number>, Number) };
  }
  if (!isArrayLike(value)) throw new Error(`chart: ${where} must be a list of [x, y] points or {x, y} columns`);
  const n = value.length;
  const curve = { x: new Float64Array(n), y: new Float64Array(n) };
  for (let i = 0; i < n; i++) {
    const p = value[i];
    if (!isArrayLike(p) || p.length < 2) throw new Error(`chart: ${where}: point ${i} is not an [x, y] pair`);
    curve.x[i] = Number(p[0]);
    curve.y[i] = Number(p[1]);
  }
  return curve;
}

function colorOf(where: string, value: unknown, next: () => number): ResolvedSeries['color'] {
  if (value === undefined) return next();
  if (value === 'text' || value === 'muted') return value;
  const index = PALETTE_NAMES.indexOf(value as ChartColor);
  if (index < 0) throw new Error(`chart: ${where}: color must be one of ${[...PALETTE_NAMES, 'text', 'muted'].join(', ')}, not ${JSON.stringify(value)}`);
  return index;
}

function finiteOption(where: string, value: unknown, fallback: number, check: (v: number) => boolean, rule: string): number {
  if (value === undefined) return fallback;
  if (typeof value !== 'number' || !Number.isFinite(value) || !check(value)) throw new Error(`chart: ${where} must be ${rule}, not ${String(value)}`);
  return value;
}

function resolveSeries(raw: unknown, i: number, nextColor: () => number): ResolvedSeries {
  const where = `series[${i}]`;
  if (!isObject(raw)) throw new Error(`chart: ${where} must be an object such as {label, points}`);
  unknownKeys(where, raw, SERIES_KEYS);
  const named = raw.label === undefined || raw.label === null ? '' : ` ('${String(raw.label)}')`;
  const at = `${where}${named}`;
  const given = [
    (raw.points !== undefined || raw.x !== undefined || raw.y !== undefined) && 'points',
    raw.lines !== undefined && 'lines',
    raw.formula !== undefined && 'formula',
    raw.curve !== undefined && 'curve',
    (raw.lower !== undefined || raw.upper !== undefined) && 'band',
  ].filter((s): s is ResolvedSeries['source'] => !!s);
  if (given.length !== 1) {
    throw new Error(`chart: ${at} needs exactly one of points (or x and y), lines, formula, curve, or lower and upper${given.length ? `; it has ${given.join(' and ')}` : ''}`);
  }
  const source = given[0];
  let curves: Curve[] = [];
  let functions: ResolvedSeries['functions'] = null;
  const empty = (): Curve => ({ x: new Float64Array(0), y: new Float64Array(0) });
  if (source === 'points') {
    if (raw.points !== undefined && (raw.x !== undefined || raw.y !== undefined)) throw new Error(`chart: ${at}: give points or x and y, not both`);
    curves = [raw.points !== undefined ? toCurve(`${at}.points`, raw.points) : toCurve(at, { x: raw.x, y: raw.y })];
  } else if (source === 'lines') {
    if (!Array.isArray(raw.lines)) throw new Error(`chart: ${at}.lines must be a list of curves`);
    curves = raw.lines.map((c, j) => toCurve(`${at}.lines[${j}]`, c));
  } else if (source === 'band') {
    if (raw.lower === undefined || raw.upper === undefined) throw new Error(`chart: ${at}: a band needs both lower and upper`);
    const edges = [raw.lower, raw.upper];
    curves = edges.map((e, j) => (typeof e === 'function' ? empty() : toCurve(`${at}.${j ? 'upper' : 'lower'}`, e)));
    if (edges.some((e) => typeof e === 'function')) {
      const missing = () => NaN;
      functions = edges.map((e) => (typeof e === 'function' ? (e as (x: number) => number) : missing));
    }
  } else if (source === 'curve') {
    if (typeof raw.curve !== 'function') throw new Error(`chart: ${at}.curve must be a function of a parameter giving [x, y], e.g. (t) => [cos(t), sin(t)]`);
    const range = [raw.from, raw.to];
    if (!range.every((v) => typeof v === 'number' && Number.isFinite(v)) || raw.from === raw.to) {
      throw new Error(`chart: ${at}: a curve needs from and to, two different numbers: the range of its parameter`);
    }
    const samples = Math.round(finiteOption(`${at}.samples`, raw.samples, 400, (v) => v >= 2 && v <= 100_000, 'between 2 and 100000'));
    curves = [sampleCurve(raw.curve as (s: number) => unknown, raw.from as number, raw.to as number, samples)];
  } else if (typeof raw.formula !== 'function') {
    throw new Error(`chart: ${at}.formula must be a function of x, e.g. (x) => x ** 2`);
  } else {
    functions = [raw.formula as (x: number) => number];
    curves = [empty()];
  }
  if (raw.mark !== undefined && raw.mark !== 'line' && raw.mark !== 'dots') throw new Error(`chart: ${at}.mark must be 'line' or 'dots'`);
  if (source === 'band' && raw.mark !== undefined) throw new Error(`chart: ${at}: a band has no mark`);
  const dash = raw.dash === true ? [6, 4] : raw.dash === undefined || raw.dash === false ? [] : raw.dash;
  if (!Array.isArray(dash) || !dash.every((d) => typeof d === 'number' && d >= 0 && Number.isFinite(d))) {
    throw new Error(`chart: ${at}.dash must be true or a list of lengths in pixels, e.g. [6, 4]`);
  }
  const kind = source === 'band' ? 'band' : ((raw.mark as 'line' | 'dots' | undefined) ?? (source === 'points' ? 'dots' : 'line'));
  return {
    label: raw.label === undefined || raw.label === null || raw.label === '' ? null : String(raw.label),
    kind,
    source,
    curves,
    color: colorOf(at, raw.color, nextColor),
    dash,
    width: finiteOption(`${at}.width`, raw.width, 2, (v) => v > 0, 'a positive number'),
    opacity: finiteOption(`${at}.opacity`, raw.opacity, 1, (v) => v >= 0 && v <= 1, 'between 0 and 1'),
    radius: finiteOption(`${at}.radius`, raw.radius, 3, (v) => v > 0, 'a positive number'),
    samples: Math.round(finiteOption(`${at}.samples`, raw.samples, 400, (v) => v >= 2 && v <= 100_000, 'between 2 and 100000')),
    functions,
    ...(functions && {
      from: raw.from === undefined ? undefined : finiteOption(`${at}.from`, raw.from, 0, () => true, 'a number'),
      to: raw.to === undefined ? undefined : finiteOption(`${at}.to`, raw.to, 0, () => true, 'a number'),
    }),
  };
}

/**
 * The points of a parametric curve at `n` even steps of its parameter from
 * `a` to `b`; a step that throws or gives no finite [x, y] is NaN, which
 * breaks the line there.
 */
export function sampleCurve(f: (s: number) => unknown, a: number, b: number, n: number): Curve {
  const curve = { x: new Float64Array(n), y: new Float64Array(n) };
  for (let i = 0; i < n; i++) {
    const s = i === n - 1 ? b : a + ((b - a) * i) / (n - 1);
    let p: unknown;
    try {
      p = f(s);
    } catch {
      p = null;
    }
    const ok = isArrayLike(p) && p.length >= 2 && Number.isFinite(p[0]) && Number.isFinite(p[1]);
    curve.x[i] = ok ? Number((p as ArrayLike<number>)[0]) : NaN;
    curve.y[i] = ok ? Number((p as ArrayLike<number>)[1]) : NaN;
  }
  return curve;
}

function resolveAxis(name: 'x' | 'y', raw: unknown): ResolvedAxis {
  if (raw === undefined) return { label: name, scale: 'linear', domain: null, ticks: null };
  if (!isObject(raw)) throw new Error(`chart: ${name} must be an object such as {label: 'time t', domain: [0, 10]}`);
  unknownKeys(name, raw, AXIS_KEYS);
  const scale = raw.scale ?? 'linear';
  if (scale !== 'linear' && scale !== 'log') throw new Error(`chart: ${name}.scale must be 'linear' or 'log'`);
  let domain: [number, number] | null = null;
  if (raw.domain !== undefined) {
    const d = raw.domain;
    if (!isArrayLike(d) || d.length !== 2 || ![d[0], d[1]].every((v) => typeof v === 'number' && Number.isFinite(v)) || d[0] === d[1]) {
      throw new Error(`chart: ${name}.domain must be two different finite numbers [from, to]`);
    }
    domain = [d[0] as number, d[1] as number];
    if (scale === 'log' && !(domain[0] > 0 && domain[1] > 0)) throw new Error(`chart: ${name}.domain of a log axis must be positive`);
  }
  let ticks: number[] | null = null;
  if (raw.ticks !== undefined) {
    if (!Array.isArray(raw.ticks) || !raw.ticks.every((v) => typeof v === 'number' && Number.isFinite(v))) throw new Error(`chart: ${name}.ticks must be a list of numbers`);
    ticks = [...raw.ticks];
  }
  return { label: raw.label === undefined ? name : String(raw.label), scale, domain, ticks };
}

function resolveRule(raw: unknown, i: number): ResolvedRule {
  const where = `rules[${i}]`;
  if (!isObject(raw)) throw new Error(`chart: ${where} must be {x, label} or {y, label}`);
  unknownKeys(where, raw, RULE_KEYS);
  const hasX = raw.x !== undefined;
  if (hasX === (raw.y !== undefined)) throw new Error(`chart: ${where} needs exactly one of x or y`);
  const at = raw[hasX ? 'x' : 'y'];
  if (typeof at !== 'number' || !Number.isFinite(at)) throw new Error(`chart: ${where}.${hasX ? 'x' : 'y'} must be a finite number`);
  return { ...(hasX ? { x: at } : { y: at }), label: raw.label === undefined ? '' : String(raw.label), faint: raw.faint === true };
}

/** A file name from a label: 'Deflection angle against b' → 'deflection-angle-against-b'. */
export function fileName(label: string): string {
  const slug = label
    .normalize('NFKD')
    .toLowerCase()
    .replace(/[^a-z0-9]+/g, '-')
    .replace(/^-+|-+$/g, '')
    .slice(0, 60)
    .replace(/-+$/, '');
  return slug || 'chart';
}

/** Checks a chart's options and turns them into data; throws one readable Error on a slip. */
export function resolveChart(options: unknown): ResolvedChart {
  if (!isObject(options)) throw new Error("chart: give an options object, e.g. chart({label: 'q against t', series: [{points}]})");
  unknownKeys('the options', options, CHART_KEYS);
  if (typeof options.label !== 'string' || !options.label.trim()) throw new Error('chart: label must say what the figure shows (it is read to those who cannot see it)');
  if (!Array.isArray(options.series)) throw new Error('chart: series must be a list, e.g. [{label, points}]');
  let palette = 0;
  const series = options.series.map((s, i) => resolveSeries(s, i, () => palette++));
  const rules = (Array.isArray(options.rules) ? options.rules : options.rules === undefined ? [] : null)?.filter((r) => r !== false && r !== null && r !== undefined).map(resolveRule);
  if (!rules) throw new Error('chart: rules must be a list, e.g. [{y: 1, label: "v = c"}]');
  const x = resolveAxis('x', options.x);
  const y = resolveAxis('y', options.y);
  if (options.aspect !== undefined && options.aspect !== 'equal') throw new Error("chart: aspect can only be 'equal'");
  const equalAspect = options.aspect === 'equal';
  if (equalAspect && (x.scale === 'log' || y.scale === 'log')) throw new Error("chart: aspect: 'equal' needs linear axes");
  const height = finiteOption('height', options.height, 320, (v) => v >= 120 && v <= 2000, 'between 120 and 2000 pixels');
  if (options.name !== undefined && typeof options.name !== 'string') throw new Error('chart: name must be a string');
  const heightGiven = options.height !== undefined;
  return { label: options.label, name: fileName((options.name as string | undefined) ?? options.label), x, y, series, rules, height, heightGiven, equalAspect };
}
