import { h as el } from '../../controls/dom.ts';
import { minusSign } from '../../controls/format.ts';

/** What scrolling a time plot back needs from it. */
export interface Scrollable {
  /** the right edge (column) of the window shown now */
  end(): number;
  /** the plot width in device pixels, and device pixels per CSS pixel */
  width(): number;
  ratio(): number;
  /** shows the window ending at column `end` (clamped; the live end follows the trace again) */
  scrollTo(end: number): void;
  goLive(): void;
}

/** How to move a time plot through its record: the stage's tooltip, its accessible description, and a note shown while it has the keyboard's focus. */
export const SCROLL_HINT = 'Move through time: drag, scroll sideways, or Shift + wheel; keys ← →, Page Up/Down, Home, End (back to live)';

let hints = 0;

/**
 * The hint on a plot stage: its title (a mouse's hover) and a note inside it
 * (shown on keyboard focus, widgets.css), which the stage's description
 * names; returns the note's id for aria-describedby.
 */
export function addScrollHint(stage: HTMLElement): string {
  const note = el('span', 'pb-stage-hint', { id: `pb-stage-hint-${++hints}`, 'aria-hidden': 'true' }, SCROLL_HINT);
  stage.title = SCROLL_HINT;
  stage.append(note);
  return note.id;
}

/**
 * Drag, wheel and keys on the plot stage: a drag, a horizontal wheel, or a
 * vertical one with Shift, Ctrl or Alt held; ← → by a tenth of a window,
 * Page Up/Down by a window, Home to the start of the record, End to live.
 * A plain vertical wheel is the page's, paused or not: a reader scrolling
 * down the chapter must not be caught by every plot they pass.
 */
export function listenScroll(stage: HTMLElement, plot: Scrollable): void {
  stage.addEventListener(
    'wheel',
    (e) => {
      const columns = wheelColumns(e, plot.width(), plot.ratio());
      if (columns === 0) return;
      e.preventDefault();
      plot.scrollTo(plot.end() + columns);
    },
    { passive: false },
  );
  let dragX: number | null = null;
  stage.addEventListener('pointerdown', (e) => {
    if (e.button !== 0) return;
    dragX = e.clientX;
    stage.setPointerCapture?.(e.pointerId);
    stage.classList.add('pb-dragging');
  });
  stage.addEventListener('pointermove', (e) => {
    if (dragX === null) return;
    const dx = (e.clientX - dragX) * plot.ratio();
    if (Math.abs(dx) < 1) return;
    dragX = e.clientX;
    plot.scrollTo(plot.end() - dx);
  });
  const release = (): void => {
    dragX = null;
    stage.classList.remove('pb-dragging');
  };
  stage.addEventListener('pointerup', release);
  stage.addEventListener('pointercancel', release);
  stage.addEventListener('keydown', (e) => {
    const step = ({ ArrowLeft: -0.1, ArrowRight: 0.1, PageUp: -1, PageDown: 1 } as Record<string, number>)[e.key];
    if (step !== undefined) plot.scrollTo(plot.end() + step * plot.width());
    else if (e.key === 'Home') plot.scrollTo(-Infinity);
    else if (e.key === 'End') plot.goLive();
    else return;
    e.preventDefault();
  });
}

/** The slider under a time plot: where the window is in the record, a Live button, and the window's times. */
export class ScrubBar {
  readonly element: HTMLElement;
  readonly live: HTMLButtonElement;
  private readonly slider: HTMLInputElement;
  private readonly status: HTMLElement;

  constructor(onScrub: (time: number) => void, onLive: () => void) {
    this.slider = el('input', 'pb-scrub', { type: 'range', min: '0', max: '1', step: 'any', value: '1', 'aria-label': 'Scroll back through the recorded history' });
    this.live = el('button', 'pb-button pb-small', { type: 'button', disabled: '', title: 'Follow the simulation again' }, 'Live');
    this.status = el('span', 'pb-scrub-status', { 'aria-live': 'off' });
    this.element = el('div', 'pb-scrub-row', {}, this.slider, this.live, this.status);
    this.slider.addEventListener('input', () => onScrub(Number(this.slider.value)));
    this.live.addEventListener('click', onLive);
  }

  /**
   * Shows a window [t0, t1] of a record spanning [first, last] whose window
   * right edges can range over [lo, hi]; `following` when it is the live one.
   */
  show(lo: number, hi: number, t0: number, t1: number, first: number, last: number, following: boolean): void {
    this.slider.min = String(lo);
    this.slider.max = String(hi);
    this.slider.value = String(t1);
    this.slider.disabled = hi - lo <= 0;
    const text = `t ${short(t0)} – ${short(t1)}${following ? '' : ` of ${short(first)} – ${short(last)}`}`;
    this.slider.setAttribute('aria-valuetext', text);
    this.status.textContent = following ? '' : text;
    this.live.disabled = following;
  }
}

/** A time with four significant digits, or whole above 1000. */
export function short(t: number): string {
  return minusSign(Math.abs(t) >= 1000 ? t.toFixed(0) : t.toPrecision(4).replace(/(\.\d*?)0+$/, '$1').replace(/\.$/, ''));
}

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
  ctrlKey: boolean;
  altKey: boolean;
}

const LINE_PIXELS = 16;

/**
 * Columns (device pixels) a wheel event scrolls the window by: positive is
 * later in time. A horizontal wheel (a trackpad's sideways swipe) scrolls,
 * and so does a vertical one with Shift, Ctrl or Alt held (Chromium may turn
 * Shift's into a horizontal one itself); a plain vertical wheel returns 0, so
 * the page scrolls as usual.
 */
export function wheelColumns(event: WheelLike, pageColumns: number, ratio: number): number {
  const horizontal = Math.abs(event.deltaX) > Math.abs(event.deltaY);
  let delta = horizontal ? event.deltaX : event.deltaY;
  if (!horizontal && !(event.shiftKey || event.ctrlKey || event.altKey)) return 0;
  if (event.deltaMode === 1) delta *= LINE_PIXELS;
  else if (event.deltaMode === 2) delta *= pageColumns / ratio;
  return delta * ratio;
}
