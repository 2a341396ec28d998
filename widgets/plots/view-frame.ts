import { pixelRatio } from './canvas.ts';
import { watchTheme, readTheme, sameTheme, type Theme } from './theme.ts';
import { PlotTable } from './plot-table.ts';
import type { TableData } from './table-data.ts';

/** An offscreen canvas kept at the frame's size, with its context scaled to CSS pixels. */
export interface Layer {
  readonly canvas: HTMLCanvasElement;
  readonly context: CanvasRenderingContext2D;
}

export interface FrameOptions {
  /** the root element's data-widget */
  kind: string;
  /** the canvas's accessible name */
  label: string;
  /** the canvas height in CSS pixels for a given width */
  height: (width: number) => number;
}

/** Width used before the element is laid out (detached, or hidden). */
const FALLBACK_WIDTH = 640;

/**
 * The DOM around one canvas plot: a root element carrying data-widget, a
 * visible canvas sized to the column at the device's pixel ratio, offscreen
 * layers kept at the same size, and the theme. `onChange` hears of a new
 * size, pixel ratio or theme, after which every layer is blank and the view
 * redraws; the view also calls `measure()` each frame, which notices a pixel
 * ratio change (browser zoom, a window moved to another screen).
 */
export class ViewFrame {
  readonly element: HTMLDivElement;
  /** the bordered box holding the canvas and any message over it */
  readonly stage: HTMLDivElement;
  readonly canvas: HTMLCanvasElement;
  readonly context: CanvasRenderingContext2D;
  width = FALLBACK_WIDTH;
  height = 0;
  dpr = 1;
  theme: Theme;
  onChange: (() => void) | null = null;
  private readonly layers: Layer[] = [];
  private readonly cleanups: (() => void)[] = [];
  private note: HTMLDivElement | null = null;
  /** whether the stage may have changed width since it was last read */
  private widthStale = true;

  constructor(private readonly options: FrameOptions) {
    const element = document.createElement('div');
    element.dataset.widget = options.kind;
    element.className = `pb-plot pb-plot-${options.kind}`;
    element.style.cssText = 'width:100%;max-width:100%;min-width:0;';
    // The stage looks like the time plot's: the page's background, a hairline border.
    const stage = document.createElement('div');
    stage.className = 'pb-plot-stage';
    stage.style.cssText =
      'position:relative;background:var(--bg,#fbfaf6);border:1px solid var(--rule,#dedad0);border-radius:4px;overflow:hidden;';
    const canvas = document.createElement('canvas');
    canvas.setAttribute('role', 'img');
    canvas.setAttribute('aria-label', options.label);
    canvas.style.cssText = 'display:block;width:100%;';
    stage.append(canvas);
    element.append(stage);
    this.element = element;
    this.stage = stage;
    this.canvas = canvas;
    this.context = this.contextOf(canvas);
    this.theme = readTheme(element);
    this.measure(true);
    this.observe();
  }

  /**
   * The plot's data-table view: a "Table" button in the top right corner of
   * the stage (the margin above the plot, which the legend leaves free) and
   * the table under the plot, shown while the button is pressed.
   */
  addTable(name: string, data: () => TableData | null): PlotTable {
    const table = new PlotTable(name, data);
    table.button.classList.add('pb-table-corner');
    this.stage.append(table.button);
    this.element.append(table.element);
    return table;
  }

  /** Sets the canvas's text alternative: what is shown and the current values (the caller keeps it to a few times a second). */
  describe(text: string): void {
    if (this.canvas.getAttribute('aria-label') !== text) this.canvas.setAttribute('aria-label', text);
  }

  /** A new offscreen layer of the frame's size. */
  layer(): Layer {
    const canvas = document.createElement('canvas');
    const layer = { canvas, context: this.contextOf(canvas) };
    this.layers.push(layer);
    this.size(layer);
    return layer;
  }

  /**
   * Re-reads width and pixel ratio and resizes every canvas if either
   * changed (clearing them); returns whether it did.
   */
  measure(force = false): boolean {
    const dpr = Math.min(4, pixelRatio());
    // Reading the width forces a layout when the page changed since the last one, as a frame's readouts do;
    // so it is read only when the stage was resized (or there is no ResizeObserver to say so), not each frame.
    let width = this.width;
    if (force || this.widthStale) {
      const measured = this.canvas.clientWidth;
      width = Math.max(160, Math.round(measured > 0 ? measured : this.width || FALLBACK_WIDTH));
      this.widthStale = typeof ResizeObserver !== 'function' || measured <= 0;
    }
    if (!force && width === this.width && dpr === this.dpr) return false;
    this.width = width;
    this.dpr = dpr;
    this.height = Math.round(this.options.height(width));
    this.canvas.style.height = `${this.height}px`;
    this.size({ canvas: this.canvas, context: this.context });
    for (const layer of this.layers) this.size(layer);
    return true;
  }

  /**
   * Clears the visible canvas, ready for layers to be composed onto it. It
   * stays transparent, like the time plot's, so the plot sits on whatever
   * surface holds it; a PNG download puts it on the theme's background.
   */
  clear(): void {
    const g = this.context;
    g.save();
    g.setTransform(1, 0, 0, 1, 0, 0);
    g.clearRect(0, 0, this.canvas.width, this.canvas.height);
    g.restore();
  }

  /** Draws a layer onto the visible canvas, pixel for pixel. */
  compose(layer: Layer): void {
    const g = this.context;
    g.save();
    g.setTransform(1, 0, 0, 1, 0, 0);
    g.drawImage(layer.canvas, 0, 0);
    g.restore();
  }

  /** Shows a one-line message over the plot (a problem, or what it is waiting for); null hides it. */
  say(text: string | null): void {
    if (text === null) {
      this.note?.remove();
      this.note = null;
      return;
    }
    if (!this.note) {
      this.note = document.createElement('div');
      this.note.className = 'pb-plot-note';
      this.note.setAttribute('role', 'status');
      this.note.style.cssText =
        'position:absolute;left:0;right:0;top:50%;transform:translateY(-50%);text-align:center;padding:0 1.5em;color:var(--muted,#5e5b55);pointer-events:none;';
      this.stage.append(this.note);
    }
    if (this.note.textContent !== text) this.note.textContent = text;
  }

  markReady(): void {
    if (!('ready' in this.element.dataset)) this.element.dataset.ready = '';
  }

  dispose(): void {
    for (const cleanup of this.cleanups.splice(0)) cleanup();
    this.onChange = null;
    this.element.remove();
  }

  private contextOf(canvas: HTMLCanvasElement): CanvasRenderingContext2D {
    const context = canvas.getContext('2d');
    if (!context) throw new Error('this browser cannot draw on a canvas (no 2D context)');
    return context;
  }

  private size(layer: Layer): void {
    layer.canvas.width = Math.round(this.width * this.dpr);
    layer.canvas.height = Math.round(this.height * this.dpr);
    layer.context.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
    layer.context.lineCap = 'round';
    layer.context.lineJoin = 'round';
  }

  private changed(): void {
    this.widthStale = true;
    const theme = readTheme(this.element);
    const themeChanged = !sameTheme(theme, this.theme);
    this.theme = theme;
    if (this.measure() || themeChanged) this.onChange?.();
  }

  private observe(): void {
    const changed = () => this.changed();
    if (typeof ResizeObserver === 'function') {
      const resize = new ResizeObserver(changed);
      resize.observe(this.stage);
      this.cleanups.push(() => resize.disconnect());
    }
    this.cleanups.push(watchTheme(changed));
  }
}
