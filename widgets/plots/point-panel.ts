/**
 * A panel on which the reader chooses a point of a plane: a launch point on
 * a Poincaré section, a pair of parameters on a stability chart. One canvas,
 * focusable and announced as an application (it takes the arrow keys, which
 * a screen reader would otherwise keep), drawn at the device's pixel ratio
 * on the theme's background with linear axes inside the panel margins. A
 * click, or the arrow keys and Enter, give the point in the plane's own
 * coordinates.
 */
import { type AxisReadout, drawAxes, MARGIN, type Rect } from './axes.ts';
import { pixelRatio, scaledContext } from './canvas.ts';
import { fitEqualAspect } from './extent.ts';
import { type Domain, makeMapping, type Mapping } from './scale.ts';
import { readTheme, type Theme } from './theme.ts';

/** One drawing of the panel: its context in CSS pixels, the theme, the plotting area and the plane's mappings onto it. */
export interface PanelFrame {
  readonly g: CanvasRenderingContext2D;
  readonly dpr: number;
  readonly theme: Theme;
  readonly rect: Rect;
  readonly mx: Mapping;
  readonly my: Mapping;
}

export interface PointPanelOptions {
  /**
   * The plane's axes share a unit (a surface of section's coordinate and
   * momentum in the same scaled units): one unit is then as long across as
   * up, and the ranges asked for are widened on one axis to fill the panel,
   * so that a disk is drawn as a disk. Axes of different quantities (a
   * stability chart's frequency and depth) fill the panel each on its own.
   */
  sameUnits?: boolean;
}

/** Width before the panel is laid out, and the least it is drawn at (CSS px). */
const FALLBACK_WIDTH = 640;
const LEAST_WIDTH = 280;

export class PointPanel {
  readonly canvas: HTMLCanvasElement;
  readonly #root: HTMLElement;
  /** The last drawing's mappings, which a click is read through; none before the first. */
  #drawn: { mx: Mapping; my: Mapping } | null = null;
  /** The width of the last drawing (CSS px), to tell a resize that needs a new one. */
  #drawnWidth = 0;
  readonly #sameUnits: boolean;
  /** The axes as last drawn, read through the root's `axes` as the book's other plots are (tests/e2e/plot-axes.mjs). */
  #axes: { x: AxisReadout; y: AxisReadout } | null = null;

  /** `root` is the widget's element: its width and theme are the panel's. `kind` names the panel to assistive technology. */
  constructor(root: HTMLElement, kind: string, label: string, options: PointPanelOptions = {}) {
    this.#root = root;
    this.#sameUnits = options.sameUnits ?? false;
    Object.defineProperty(root, 'axes', { get: () => (this.#axes ? [this.#axes] : []), configurable: true });
    const canvas = document.createElement('canvas');
    canvas.style.cursor = 'crosshair';
    canvas.tabIndex = 0;
    canvas.setAttribute('role', 'application');
    canvas.setAttribute('aria-roledescription', kind);
    canvas.setAttribute('aria-label', label);
    this.canvas = canvas;
  }

  /**
   * Sizes the canvas to the root's width and `heightFor` it, paints the
   * theme's background (a canvas is transparent, and the points must read on
   * the page's paper in either theme), and maps x and y onto the plotting
   * area, y upward (at one scale for both, widening one range, when the axes
   * share units). Returns what to draw with, or null without a 2D context.
   */
  frame(heightFor: (width: number) => number, x: Domain, y: Domain): PanelFrame | null {
    const width = this.#width();
    this.#drawnWidth = width;
    const height = heightFor(width);
    const dpr = pixelRatio();
    const g = scaledContext(this.canvas, width, height, dpr);
    if (!g) return null;
    const theme = readTheme(this.#root);
    g.fillStyle = theme.bg;
    g.fillRect(0, 0, width, height);
    const rect = { left: MARGIN.left, top: MARGIN.top, width: width - MARGIN.left - MARGIN.right, height: height - MARGIN.top - MARGIN.bottom };
    if (this.#sameUnits) [x, y] = equalScale(x, y, rect);
    const mx = makeMapping('linear', x, [rect.left, rect.left + rect.width]);
    const my = makeMapping('linear', y, [rect.top + rect.height, rect.top]);
    this.#drawn = { mx, my };
    return { g, dpr, theme, rect, mx, my };
  }

  /**
   * Calls `redraw` whenever the root's width changes the panel's (a phone
   * turned, a window resized, a column narrowed), so that the canvas never
   * overflows its column nor draws scaled; stops once the root has left
   * the page.
   */
  followWidth(redraw: () => void): void {
    if (typeof ResizeObserver === 'undefined') return;
    const observer = new ResizeObserver(() => {
      if (!this.#root.isConnected) return observer.disconnect();
      if (this.#drawnWidth > 0 && this.#root.clientWidth > 0 && this.#width() !== this.#drawnWidth) redraw();
    });
    observer.observe(this.#root);
  }

  /** The width to draw at: the root's, once laid out, but never under the least. */
  #width(): number {
    return Math.max(LEAST_WIDTH, this.#root.clientWidth || FALLBACK_WIDTH);
  }

  /** Ends a drawing: the ring around the chosen point (u, v), if any, then the axes over everything. */
  finish(f: PanelFrame, chosen: readonly [number, number] | null, labels: { xLabel: string; yLabel: string }): void {
    const { g, theme } = f;
    if (chosen) {
      g.strokeStyle = theme.accent;
      g.lineWidth = 2;
      g.beginPath();
      g.arc(f.mx.scale(chosen[0]), f.my.scale(chosen[1]), 6, 0, 2 * Math.PI);
      g.stroke();
    }
    this.#axes = drawAxes(g, f.rect, f.mx, f.my, f.theme, labels, f.dpr);
  }

  /** Calls `pick(u, v)` with the plane's point under each click, once the panel has been drawn. */
  onClick(pick: (u: number, v: number) => void): void {
    this.canvas.addEventListener('click', (event) => {
      if (!this.#drawn) return;
      const box = this.canvas.getBoundingClientRect();
      pick(this.#drawn.mx.scale.invert(event.clientX - box.left), this.#drawn.my.scale.invert(event.clientY - box.top));
    });
  }

  /**
   * The keyboard's way to the same point: an arrow calls `move(du, dv)` with
   * the step `step()` gives along its axis, `larger` times that with Shift;
   * Enter or Space calls `choose()`. The keys it handles do nothing else
   * (no scrolling of the page).
   */
  onKeys(step: () => readonly [number, number], larger: number, move: (du: number, dv: number) => void, choose: () => void): void {
    this.canvas.addEventListener('keydown', (event) => {
      if (event.key === 'Enter' || event.key === ' ') {
        event.preventDefault();
        return choose();
      }
      const [u, v] = step();
      const du = u * (event.shiftKey ? larger : 1);
      const dv = v * (event.shiftKey ? larger : 1);
      const moves: Record<string, [number, number]> = { ArrowLeft: [-du, 0], ArrowRight: [du, 0], ArrowDown: [0, -dv], ArrowUp: [0, dv] };
      if (!(event.key in moves)) return;
      event.preventDefault();
      move(...moves[event.key]);
    });
  }
}

/** The ranges x and y widened, about their centres, to one scale in `rect`; ranges that are not finite and increasing are left as given. */
function equalScale(x: Domain, y: Domain, rect: Rect): [Domain, Domain] {
  const span = (d: Domain) => d[1] - d[0];
  if (!(span(x) > 0 && span(y) > 0 && Number.isFinite(span(x) + span(y)) && rect.width > 0 && rect.height > 0)) return [x, y];
  const e = fitEqualAspect({ x0: x[0], x1: x[1], y0: y[0], y1: y[1] }, rect.width, rect.height);
  return [[e.x0, e.x1], [e.y0, e.y1]];
}
