/**
 * How tall each view's plot is for its width: one rule per view, read by the
 * view itself to size its canvas and by the page's build to reserve the
 * view's space before any script runs (simulator/reserve.ts), so that a
 * widget appears in a box of its own size and moves nothing.
 */
import { TIME_MARGIN } from './axes.ts';

/** A height that follows the width, clamp(min, slope · width, max), in CSS pixels. */
export interface Proportional {
  readonly min: number;
  readonly slope: number;
  readonly max: number;
}

/** The trajectory view: nearly square on a phone, wide on a desk. */
export const TRAJECTORY_PANEL: Proportional = { min: 220, slope: 0.7, max: 560 };
/** A phase portrait drawn as one plane. */
export const PHASE_PANEL: Proportional = { min: 220, slope: 0.62, max: 460 };
/** One of several small phase portraits side by side (`layout: 'multiples'`). */
export const PHASE_MULTIPLE: Proportional = { min: 180, slope: 0.8, max: 460 };
/** The spectrum. */
export const SPECTRUM_PLOT: Proportional = { min: 200, slope: 0.46, max: 340 };

/** The time plot's plotting area by default; its canvas adds the axes' margins. */
export const TIME_PLOT_AREA = 220;

/** Plane panels go two abreast from this canvas width up. */
export const TWO_COLUMNS_FROM = 520;

/** The height of `size` at `width`, in whole pixels, as the canvas takes it. */
export function heightAt(size: Proportional, width: number): number {
  return Math.max(size.min, Math.min(size.max, Math.round(width * size.slope)));
}

/** The same height as a CSS length, for a width given as a CSS length (e.g. `100cqw - 2px`). */
export function heightCss(size: Proportional, width: string): string {
  return `clamp(${size.min}px, ${size.slope} * (${width}), ${size.max}px)`;
}

/** Columns of a plane view with `count` panels at canvas width `width`. */
export function gridColumns(count: number, width: number): number {
  return count > 1 && width >= TWO_COLUMNS_FROM ? 2 : 1;
}

/** The time plot's canvas height for a plotting area of `area` pixels. */
export function timePlotHeight(area = TIME_PLOT_AREA): number {
  return area + TIME_MARGIN.top + TIME_MARGIN.bottom;
}

/**
 * Which of a simulator's views take the whole width where views go two
 * abreast (widgets.css, class pb-span): the spectrum, whose list of peaks
 * reads on one line only there, and any other view that has no neighbour
 * to pair with, in order; so the time plot and a phase portrait go side by
 * side over the spectrum. `spectrum[i]` says whether view i is one.
 */
export function spanningViews(spectrum: readonly boolean[]): boolean[] {
  const spans = spectrum.map((s) => s);
  let waiting: number | null = null;
  spectrum.forEach((isSpectrum, i) => {
    if (isSpectrum) {
      if (waiting !== null) spans[waiting] = true;
      waiting = null;
    } else if (waiting === null) waiting = i;
    else waiting = null;
  });
  if (waiting !== null) spans[waiting] = true;
  return spans;
}
