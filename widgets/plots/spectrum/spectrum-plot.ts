import type { Peak, Spectrum } from '../../../core/index.ts';
import { type AxisReadout, crisp, drawAxes, drawLegend, fontOf, leftMarginFor, type LegendItem, MARGIN, panelLabels, type Rect } from '../axes.ts';
import { makeMapping, type Mapping, toPixel } from '../scale.ts';
import { ColumnDecimator, traceColumns } from '../decimate.ts';
import { seriesColor, type Theme } from '../theme.ts';
import type { PathSink } from '../trace.ts';

/** Which parts of the transform X_k are drawn: |X|, Re X and Im X, or all three. */
export type SpectrumShow = 'magnitude' | 'reim' | 'both';

/** Everything one picture of a spectrum is drawn from. */
export interface SpectrumPicture {
  spectrum: Spectrum;
  peaks: readonly Peak[];
  show: SpectrumShow;
  maxFrequency: number;
  /** the amplitude axis reaches this (and −this when Re and Im are shown) */
  yMax: number;
  theory?: { frequency: number; label: string };
  series: string;
}

/** The frequency axis and the amplitude axis of a spectrum in a width × height canvas. */
export function spectrumMappings(width: number, height: number, picture: Pick<SpectrumPicture, 'maxFrequency' | 'yMax' | 'show'>, left = MARGIN.left): { rect: Rect; mx: Mapping; my: Mapping } {
  const rect = { left, top: MARGIN.top, width: width - left - MARGIN.right, height: height - MARGIN.top - MARGIN.bottom };
  const mx = makeMapping('linear', [0, picture.maxFrequency], [rect.left, rect.left + rect.width]);
  const y0 = picture.show === 'magnitude' ? 0 : -picture.yMax;
  const my = makeMapping('linear', [y0, picture.yMax], [rect.top + rect.height, rect.top]);
  return { rect, mx, my };
}

/** The last bin worth drawing for an axis that ends at maxFrequency: one past it, so the line reaches the edge. */
export function lastBin(s: Spectrum, maxFrequency: number): number {
  return Math.min(s.frequency.length - 1, Math.ceil(maxFrequency / s.binWidth) + 1);
}

/** The axes of a spectrum, with a left margin wide enough for the amplitude labels. */
export function fittedMappings(g: CanvasRenderingContext2D, width: number, height: number, picture: Pick<SpectrumPicture, 'maxFrequency' | 'yMax' | 'show'>, theme: Theme): { rect: Rect; mx: Mapping; my: Mapping } {
  const first = spectrumMappings(width, height, picture);
  const margin = leftMarginFor(g, panelLabels(g, first.rect, first.mx, first.my, theme).y, theme);
  return margin > MARGIN.left ? spectrumMappings(width, height, picture, margin) : first;
}

/** Draws axes, the chosen lines, the theory marker and numbered peak marks; returns the axes as drawn. */
export function drawSpectrum(g: CanvasRenderingContext2D, width: number, height: number, picture: SpectrumPicture, theme: Theme, dpr: number): { x: AxisReadout; y: AxisReadout } {
  const { spectrum: s, show } = picture;
  const { rect, mx, my } = fittedMappings(g, width, height, picture, theme);
  const axes = drawAxes(g, rect, mx, my, theme, { xLabel: 'frequency f (cycles per time unit)', yLabel: show === 'magnitude' ? 'amplitude' : 'amplitude, Re, Im' }, dpr);
  const magnitude = theme.accent;
  const real = show === 'both' ? seriesColor(theme, 1) : theme.accent;
  const legend: LegendItem[] = [];
  if (show !== 'magnitude') legend.push({ label: `Re`, color: real }, { label: `Im`, color: theme.muted });
  if (show !== 'reim') legend.unshift({ label: `|X|`, color: magnitude });
  drawLegend(g, rect, legend, theme, `spectrum of ${picture.series}`);

  const end = lastBin(s, picture.maxFrequency);
  g.save();
  g.beginPath();
  g.rect(rect.left, rect.top, rect.width, rect.height);
  g.clip();
  const line = (values: Float64Array, color: string, widthPx: number) => {
    g.beginPath();
    traceSeries(g, s.frequency, values, end, mx, my);
    g.strokeStyle = color;
    g.lineWidth = widthPx;
    g.stroke();
  };
  if (show !== 'magnitude') {
    line(s.im, theme.muted, 1.1);
    line(s.re, real, 1.3);
  }
  if (show !== 'reim') line(s.amplitude, magnitude, 1.75);
  if (picture.theory) drawTheory(g, rect, mx, picture.theory, theme, dpr);
  g.restore();
  drawPeakMarks(g, rect, mx, my, picture.peaks, picture.maxFrequency, theme);
  return axes;
}

function drawTheory(g: CanvasRenderingContext2D, rect: Rect, mx: Mapping, theory: { frequency: number; label: string }, theme: Theme, dpr: number): void {
  const x = crisp(mx.scale(theory.frequency), dpr);
  g.save();
  g.setLineDash([5, 4]);
  g.strokeStyle = theme.fg;
  g.globalAlpha = 0.75;
  g.lineWidth = 1;
  g.beginPath();
  g.moveTo(x, rect.top);
  g.lineTo(x, rect.top + rect.height);
  g.stroke();
  g.globalAlpha = 1;
  g.font = fontOf(theme, 11.5);
  g.textBaseline = 'top';
  const width = g.measureText(theory.label).width;
  const right = x + 6 + width > rect.left + rect.width;
  const left = right ? x - 6 - width : x + 5;
  // a backing of the background colour keeps the label readable over grid and lines
  g.fillStyle = theme.bg;
  g.globalAlpha = 0.85;
  g.fillRect(left - 2, rect.top + 3, width + 4, 15);
  g.globalAlpha = 1;
  g.fillStyle = theme.fg;
  g.textAlign = 'left';
  g.fillText(theory.label, left, rect.top + 5);
  g.restore();
}

function drawPeakMarks(g: CanvasRenderingContext2D, rect: Rect, mx: Mapping, my: Mapping, peaks: readonly Peak[], maxFrequency: number, theme: Theme): void {
  g.save();
  g.font = fontOf(theme, 11, 600);
  g.textAlign = 'center';
  g.textBaseline = 'bottom';
  peaks.forEach((p, i) => {
    if (!(p.frequency <= maxFrequency)) return;
    const x = mx.scale(p.frequency);
    const y = Math.max(rect.top + 34, my.scale(p.amplitude) - 5);
    g.fillStyle = theme.fg;
    g.beginPath();
    g.moveTo(x - 4, y - 7);
    g.lineTo(x + 4, y - 7);
    g.lineTo(x, y);
    g.closePath();
    g.fill();
    g.fillText(String(i + 1), x, y - 8);
  });
  g.restore();
}

/** One decimator for every trace, grown to the longest series seen: a spectrum is redrawn a few times a second. */
let decimator: ColumnDecimator | null = null;

/**
 * Traces y against x for indices [0, end] as one polyline, connecting
 * adjacent points (the paper's §5.2). Where several points fall in one pixel
 * column, as when a long series is shown up to Nyquist, the column is drawn
 * as its first value, its range and its last value (decimate.ts): the same
 * picture as every point, at a few segments per pixel. Points that do not
 * map to the canvas (a log axis's zero) are passed over.
 */
export function traceSeries(sink: PathSink, x: ArrayLike<number>, y: ArrayLike<number>, end: number, mx: Mapping, my: Mapping): number {
  const n = Math.min(end + 1, x.length, y.length);
  if (!decimator || decimator.capacity < n) decimator = new ColumnDecimator(1, Math.max(64, n), () => {});
  const d = decimator;
  d.reset();
  for (let k = 0; k < n; k++) {
    const px = toPixel(mx, x[k]);
    const py = toPixel(my, y[k]);
    if (!Number.isFinite(px) || !Number.isFinite(py)) continue;
    d.column(Math.floor(px), px);
    d.value(0, py);
  }
  // All columns stay pending (the capacity holds every point), so they are traced here rather than flushed.
  d.close();
  return traceColumns(sink, d, 0, 0, NaN, NaN);
}
