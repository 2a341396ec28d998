/**
 * A chart's data in words and in columns: the text description read to
 * those who cannot see the figure, the CSV download, and the rows of its
 * data-table view. Pure, so unit-tested in Node.
 */
import type { Curve, ResolvedSeries } from './chart-options.ts';
import type { SettledChart } from './chart-scale.ts';
import { displayNumber } from '../table/table-format.ts';

/** A series' name where it has none in the legend: 'series 3'. */
export function seriesName(s: ResolvedSeries, index: number): string {
  return s.label ?? `series ${index + 1}`;
}

/** The curves of a series with a name each: a family's lines numbered, a band's edges named. */
export function namedCurves(s: ResolvedSeries, index: number): { name: string; curve: Curve }[] {
  const name = seriesName(s, index);
  if (s.kind === 'band') return [{ name: `${name} (lower)`, curve: s.curves[0] }, { name: `${name} (upper)`, curve: s.curves[1] }];
  if (s.source === 'lines') return s.curves.map((curve, j) => ({ name: `${name} ${j + 1}`, curve }));
  return s.curves.map((curve) => ({ name, curve }));
}

/** A CSV field, quoted when it holds a comma, a quote or a line break (RFC 4180). */
function field(text: string): string {
  return /[",\r\n]/.test(text) ? `"${text.replace(/"/g, '""')}"` : text;
}

/**
 * The chart's data as CSV, one row a point: `series,x,y`, numbers in
 * shortest round-trip form so they parse back to the same doubles. Formula
 * curves are given as sampled. Columns are headed by the axes' labels.
 */
export function chartCsv(chart: SettledChart): string {
  const lines = [['series', chart.x.label, chart.y.label].map(field).join(',')];
  chart.series.forEach((s, i) => {
    for (const { name, curve } of namedCurves(s, i)) {
      const n = field(name);
      for (let k = 0; k < curve.x.length; k++) lines.push(`${n},${String(curve.x[k])},${String(curve.y[k])}`);
    }
  });
  return `${lines.join('\n')}\n`;
}

/** A short number for reading aloud: four significant digits. */
const short = (v: number) => displayNumber(v === 0 ? 0 : v, 4).replace(/-/g, '−'); // −0 reads as 0

function extentOf(curves: readonly Curve[], coordinate: 'x' | 'y'): [number, number] | null {
  let lo = Infinity;
  let hi = -Infinity;
  for (const c of curves) {
    for (const v of c[coordinate]) {
      if (!Number.isFinite(v)) continue;
      if (v < lo) lo = v;
      if (v > hi) hi = v;
    }
  }
  return lo <= hi ? [lo, hi] : null;
}

function countOf(s: ResolvedSeries): string {
  const points = s.curves.reduce((n, c) => n + c.x.length, 0);
  if (s.kind === 'band') return 'a shaded band';
  if (s.source === 'formula') return 'a formula curve';
  if (s.source === 'curve') return `a parametric curve of ${points} points`;
  if (s.source === 'lines') return `${s.curves.length} lines`;
  return s.kind === 'dots' ? `${points} point${points === 1 ? '' : 's'}` : `a line of ${points} points`;
}

/**
 * The figure in words: what it shows, the axes and their ranges, and for
 * each series what it is and the range of its values; then the marked
 * lines. It is the chart's description and follows every redraw.
 */
export function chartSummary(chart: SettledChart): string {
  const axis = (name: string, a: SettledChart['x'], d: [number, number]) =>
    `${name} axis: ${a.label}, from ${short(d[0])} to ${short(d[1])}${a.scale === 'log' ? ', logarithmic' : ''}.`;
  const parts = [`${chart.label}.`, axis('Horizontal', chart.x, chart.xDomain), axis('Vertical', chart.y, chart.yDomain)];
  chart.series.forEach((s, i) => {
    const y = extentOf(s.curves, 'y');
    const x = extentOf(s.curves, 'x');
    const range = x && y ? `, x from ${short(x[0])} to ${short(x[1])}, y from ${short(y[0])} to ${short(y[1])}` : ', no values to draw';
    parts.push(`${seriesName(s, i)}: ${countOf(s)}${range}.`);
  });
  const marked = chart.rules.filter((r) => r.label).map((r) => `${r.label} (${r.x !== undefined ? `x = ${short(r.x)}` : `y = ${short(r.y ?? NaN)}`})`);
  if (marked.length) parts.push(`Marked: ${marked.join('; ')}.`);
  return parts.join(' ');
}

/** Rows shown of one curve in the data-table view; the CSV has them all. */
export const TABLE_ROWS = 200;

/**
 * The rows of a curve for the data-table view: all of them when there are
 * at most `limit`, else `limit` spread evenly from first to last (and the
 * count left out, for the note under the table).
 */
export function tableRows(curve: Curve, limit = TABLE_ROWS): { rows: [number, number][]; omitted: number } {
  const n = curve.x.length;
  if (n <= limit) return { rows: Array.from({ length: n }, (_, k) => [curve.x[k], curve.y[k]]), omitted: 0 };
  const rows: [number, number][] = [];
  for (let i = 0; i < limit; i++) {
    const k = Math.round((i * (n - 1)) / (limit - 1));
    rows.push([curve.x[k], curve.y[k]]);
  }
  return { rows, omitted: n - limit };
}
