/**
 * Scrolling a time plot back through its record. The window is named by its
 * right edge, an absolute pixel column like the live trace's (see
 * scroll-buffer.ts), so a scrolled-back window lines up with the live one.
 */

/**
 * The right edge of a scrolled window, kept between the first full window
 * after the record's first sample and the live end. When the record is
 * shorter than a window there is nothing to scroll and the live end is kept.
 */
export function clampEnd(end: number, firstColumn: number, liveEnd: number, width: number): number {
  const earliest = Math.min(liveEnd, Math.max(width, firstColumn + width));
  return Math.round(Math.min(liveEnd, Math.max(earliest, end)));
}

export interface WheelLike {
  deltaX: number;
  deltaY: number;
  /** 0 pixels, 1 lines, 2 pages */
  deltaMode: number;
  shiftKey: boolean;
}

const LINE_PIXELS = 16;

/**
 * Columns (device pixels) a wheel event scrolls the window by: positive is
 * later in time. A horizontal or shift-wheel always scrolls; a plain vertical
 * wheel scrolls only while the simulation is paused, and otherwise returns 0
 * so the page scrolls as usual.
 */
export function wheelColumns(event: WheelLike, paused: boolean, pageColumns: number, ratio: number): number {
  const horizontal = Math.abs(event.deltaX) > Math.abs(event.deltaY);
  let delta = horizontal ? event.deltaX : event.deltaY;
  if (!horizontal && !event.shiftKey && !paused) return 0;
  if (event.deltaMode === 1) delta *= LINE_PIXELS;
  else if (event.deltaMode === 2) delta *= pageColumns / ratio;
  return delta * ratio;
}
