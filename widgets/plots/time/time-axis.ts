import { scaleLinear } from '../scale.ts';
import type { Theme } from '../theme.ts';
import { drawXTicks } from '../axes.ts';
import type { Context, Surface, SurfaceFactory } from '../canvas.ts';
import { ScrollBuffer, SLOTS, tileOf, viewLeft } from './scroll-buffer.ts';

/** What the strips need to know of the trace's time mapping (a TimeRenderer). */
export interface TimeMapping {
  readonly origin: number;
  readonly window: number;
  /** tile width in device pixels */
  readonly width: number;
  /** device pixels per time unit */
  readonly scaleX: number;
}

/** The tick step and label format for a window shown over `cssWidth` pixels: the same for every tile. */
export function timeTicks(window: number, cssWidth: number): { step: number; format: (t: number) => string } {
  const count = Math.max(2, Math.floor(cssWidth / 90));
  const scale = scaleLinear().domain([0, window]);
  const ticks = scale.ticks(count);
  return { step: ticks.length > 1 ? ticks[1] - ticks[0] : window, format: scale.tickFormat(count) };
}

/** The multiples of `step` in [t0, t1). */
export function multiples(t0: number, t1: number, step: number): number[] {
  const out: number[] = [];
  for (let k = Math.ceil(t0 / step - 1e-9); k * step < t1 - 1e-9 * step && out.length < 1000; k++) out.push(k * step + 0); // + 0: no −0
  return out;
}

/**
 * The t axis of the live trace, scrolled like the data: tile k's tick marks
 * and labels are drawn once, into a strip that moves with tile k, so a
 * scrolling axis costs nothing per frame. Each strip is `spill` device
 * pixels wider than its tile on both sides, so a label near the tile's edge
 * is whole; each tick is drawn only by the tile that holds its column.
 */
export class TimeAxisStrips {
  private ring: ScrollBuffer | null = null;
  private ticks = timeTicks(10, 600);
  private ratio = 1;

  constructor(
    private readonly create: SurfaceFactory,
    /** device pixels a strip extends beyond its tile on each side */
    public spill = 24,
  ) {}

  /** New strips for tiles `width` device pixels wide; the band is `height` device pixels. */
  resize(width: number, height: number, ratio: number, mapping: TimeMapping): void {
    this.ratio = ratio;
    this.spill = Math.round(24 * ratio);
    this.ring = new ScrollBuffer(width, height, this.create, 2 * this.spill);
    this.ticks = timeTicks(mapping.window, width / ratio);
  }

  /** Forgets every strip (the window, origin or theme changed). */
  reset(mapping: TimeMapping): void {
    this.ring?.reset();
    if (this.ring) this.ticks = timeTicks(mapping.window, mapping.width / this.ratio);
  }

  /**
   * Draws the strips of the tiles visible in the view that ends before column
   * `end` (once each), then calls `place(slot, strip, x)` with each strip's x
   * in device pixels relative to the plot's left edge minus `spill` (NaN: hidden).
   */
  place(end: number, mapping: TimeMapping, theme: Theme, place: (slot: number, strip: Surface, x: number) => void): void {
    const ring = this.ring;
    if (!ring) return;
    const w = mapping.width;
    const left = viewLeft(end, w);
    for (let k = tileOf(left, w); k <= tileOf(Math.max(left, end - 1), w); k++) if (!ring.holds(k)) this.paint(k, ring.claim(k), mapping, theme);
    for (let slot = 0; slot < SLOTS; slot++) {
      const x = ring.placement(slot, end);
      place(slot, ring.surface(slot), x);
    }
  }

  /** Blits the visible strips at (x − spill, y), for a PNG. */
  composite(target: Context, end: number, x: number, y: number): void {
    this.ring?.composite(target, end, x - this.spill, y);
  }

  private paint(tile: number, ctx: Context, m: TimeMapping, theme: Theme): void {
    const { step, format } = this.ticks;
    const t0 = m.origin + (tile * m.width) / m.scaleX;
    const t1 = m.origin + ((tile + 1) * m.width) / m.scaleX;
    const r = this.ratio;
    ctx.setTransform(r, 0, 0, r, 0, 0);
    const position = (t: number): number => (this.spill + (t - m.origin) * m.scaleX - tile * m.width) / r;
    drawXTicks(ctx, 0.5, multiples(t0, t1, step), format, position, theme);
    ctx.setTransform(1, 0, 0, 1, 0, 0);
  }
}
