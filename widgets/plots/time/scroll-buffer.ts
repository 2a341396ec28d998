import { context2d, type Context, type Surface, type SurfaceFactory } from '../canvas.ts';

/**
 * The scrolling graph of the paper's §5.1, generalised from two bitmaps to a
 * ring of three. Time maps to an absolute device-pixel column
 * c = ⌊(t − t0)·pixelsPerTime⌋ that only grows. Tile k is an offscreen canvas
 * holding columns [k·w, (k+1)·w), where w is the plot's width, and lives in
 * ring slot k mod 3. The view shows columns [left, left + w) with
 * left = max(0, end − w), so at most two consecutive tiles are visible, each
 * blitted at x = k·w − left (the paper's sprite positions −(m_t mod w) and
 * w − (m_t mod w)). New samples are drawn once, into their tile; nothing
 * already drawn is touched again, so the work per frame is proportional to
 * the new samples. The third slot exists so that a stroke near a tile's edge
 * can also be drawn into the next tile before that tile scrolls into view:
 * preparing tile k+1 recycles the slot of tile k−2, which is never visible
 * once drawing has reached tile k.
 */

export const SLOTS = 3;

/** The tile holding column c. */
export function tileOf(column: number, width: number): number {
  return Math.floor(column / width);
}

/** The ring slot of tile k (k may be negative). */
export function slotOf(tile: number): number {
  return ((tile % SLOTS) + SLOTS) % SLOTS;
}

/** The first visible column when columns before `end` have been drawn: the trace fills the view, then scrolls. */
export function viewLeft(end: number, width: number): number {
  return Math.max(0, end - width);
}

/** Where tile k's left edge lands in a view starting at column `left`. */
export function tileX(tile: number, width: number, left: number): number {
  return tile * width - left;
}

/**
 * Tiles [k0, k1] that columns [c0, c1] must be drawn into so that strokes up
 * to `pad` columns wide are whole on both sides of a tile boundary. Never
 * reaches further back than the tile before c1's, whose slot is the oldest
 * still in use.
 */
export function tileSpan(c0: number, c1: number, width: number, pad: number): [number, number] {
  const own = tileOf(c1, width);
  return [Math.max(tileOf(c0 - pad, width), own - 1), tileOf(c1 + pad, width)];
}

/** The ring of tiles. */
export class ScrollBuffer {
  private readonly surfaces: Surface[] = [];
  private readonly contexts: Context[] = [];
  /** which tile each slot holds; NaN for none */
  private readonly held = new Float64Array(SLOTS).fill(NaN);

  constructor(
    readonly width: number,
    readonly height: number,
    create: SurfaceFactory,
    /** extra canvas width beyond the tile, for content that overhangs it (axis labels) */
    readonly overhang = 0,
  ) {
    for (let i = 0; i < SLOTS; i++) {
      const surface = create(width + overhang, height);
      this.surfaces.push(surface);
      this.contexts.push(context2d(surface));
    }
  }

  /** Empties every tile. */
  reset(): void {
    for (let i = 0; i < SLOTS; i++) this.contexts[i].clearRect(0, 0, this.width + this.overhang, this.height);
    this.held.fill(NaN);
  }

  /** True when tile k's slot holds tile k. */
  holds(tile: number): boolean {
    return this.held[slotOf(tile)] === tile;
  }

  /** Tile k's context, its slot cleared first when it held another tile. */
  claim(tile: number): Context {
    const slot = slotOf(tile);
    const ctx = this.contexts[slot];
    if (this.held[slot] !== tile) {
      ctx.clearRect(0, 0, this.width + this.overhang, this.height);
      this.held[slot] = tile;
    }
    return ctx;
  }

  /**
   * Hands `paint` the context of every tile columns [c0, c1] touch, with the
   * column offset of the tile's left edge; the canvas clips what lies outside.
   */
  paint(c0: number, c1: number, pad: number, paint: (ctx: Context, offset: number) => void): void {
    const [k0, k1] = tileSpan(c0, c1, this.width, pad);
    for (let k = k0; k <= k1; k++) paint(this.claim(k), k * this.width);
  }

  /**
   * Where ring slot `slot` shows in the view that ends before column `end`:
   * the x of its left edge in device pixels, or NaN when it is not visible.
   * A display moves each slot's canvas there (the paper's sprites) or blits it.
   */
  placement(slot: number, end: number): number {
    const k = this.held[slot];
    if (k !== k) return NaN;
    const left = viewLeft(end, this.width);
    const last = tileOf(Math.max(left, end - 1), this.width);
    return k >= tileOf(left, this.width) && k <= last ? tileX(k, this.width, left) : NaN;
  }

  /** The canvas of ring slot `slot`. */
  surface(slot: number): Surface {
    return this.surfaces[slot];
  }

  /** Blits the tiles visible in the view that ends before column `end` onto `target` at (x, y). */
  composite(target: Context, end: number, x = 0, y = 0): void {
    for (let slot = 0; slot < SLOTS; slot++) {
      const at = this.placement(slot, end);
      if (at === at) target.drawImage(this.surfaces[slot] as CanvasImageSource, x + at, y);
    }
  }
}
