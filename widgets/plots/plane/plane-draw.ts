import type { TrajectoryRecord } from '../../../core/index.ts';
import { toPixel, type Mapping } from '../scale.ts';
import type { Panel } from './plane-panels.ts';
import { traceRows, type Stroke } from '../trace.ts';

/**
 * The drawing steps of a plane plot, each over all panels: stroking new
 * rows onto the trail, fading it, rescaling it, and the current-state dots.
 * They take a context and the panels, so they hold no state of their own.
 */

/** How lines are drawn: width and opacity in CSS px, jump fraction, and each colour group's colour. */
export interface LineStyle {
  lineWidth: number;
  lineOpacity: number;
  /** a step longer than this fraction of the shown extent is a jump */
  jump: number;
  color: (group: number) => string;
}

/** Samples closer than this (CSS px) to the last drawn point are skipped. */
const MIN_STEP = 0.5;

/** Strokes rows [from, to) of every track at `opacity`, one path per panel and colour group, clipped to the panel. */
export function strokeRows(g: CanvasRenderingContext2D, record: TrajectoryRecord, panels: readonly Panel[], from: number, to: number, opacity: number, style: LineStyle): void {
  const slices = record.slices(from, to);
  g.save();
  g.lineWidth = style.lineWidth;
  g.globalAlpha = opacity * style.lineOpacity;
  for (const panel of panels) {
    const { rect, pens, xs, ys, shown } = panel;
    const stroke: Stroke = { minStep: MIN_STEP, jumpX: style.jump * (shown.x1 - shown.x0), jumpY: style.jump * (shown.y1 - shown.y0) };
    g.save();
    g.beginPath();
    g.rect(rect.left, rect.top, rect.width, rect.height);
    g.clip();
    for (let i = 0; i < panel.groups.length; i++) {
      g.strokeStyle = style.color(panel.groups[i]);
      g.beginPath();
      for (let k = panel.starts[i]; k < panel.starts[i + 1]; k++) {
        for (const s of slices) traceRows(g, s.data, record.width, s.from, s.to, xs[k], ys[k], panel.mx, panel.my, pens, k, stroke);
      }
      g.stroke();
    }
    g.restore();
  }
  g.restore();
}

/** Multiplies the layer's opacity by 1 − alpha (a `destination-out` fill). */
export function fadeLayer(g: CanvasRenderingContext2D, alpha: number, width: number, height: number): void {
  g.save();
  g.globalCompositeOperation = 'destination-out';
  g.fillStyle = `rgba(0,0,0,${alpha})`;
  g.fillRect(0, 0, width, height);
  g.restore();
}

/**
 * Draws `image` (the old trail, `dpr` device pixels per CSS pixel) under each
 * panel's new linear mapping, given the mappings it was drawn with, taking
 * each panel's picture only from its own rectangle; moves the pens with it.
 */
export function rescaleImage(
  g: CanvasRenderingContext2D,
  image: CanvasImageSource,
  panels: readonly Panel[],
  before: readonly { mx: Mapping; my: Mapping }[],
  width: number,
  height: number,
  dpr: number,
): void {
  g.clearRect(0, 0, width, height);
  panels.forEach((panel, i) => {
    // pixel' = s·pixel + o, from the old map pixel = a·v + b and the new a'·v + b'
    const sx = panel.mx.a / before[i].mx.a;
    const sy = panel.my.a / before[i].my.a;
    const ox = panel.mx.b - sx * before[i].mx.b;
    const oy = panel.my.b - sy * before[i].my.b;
    g.save();
    g.beginPath();
    g.rect(panel.rect.left, panel.rect.top, panel.rect.width, panel.rect.height);
    g.clip();
    g.transform(sx, 0, 0, sy, ox, oy);
    const { left, top, width: w, height: h } = panel.rect;
    g.drawImage(image, left * dpr, top * dpr, w * dpr, h * dpr, left, top, w, h);
    g.restore();
    const { pens } = panel;
    for (let k = 0; k < pens.x.length; k++) {
      pens.x[k] = sx * pens.x[k] + ox;
      pens.y[k] = sy * pens.y[k] + oy;
    }
  });
}

/** A dot of `radius` at each track's state in `row`, one path per colour group; ringed in `ring` when large enough to need it. */
export function drawDots(g: CanvasRenderingContext2D, record: TrajectoryRecord, row: number, panels: readonly Panel[], radius: number, color: (group: number) => string, ring: string): void {
  const [slice] = record.slices(row, row + 1);
  const at = slice.from * record.width;
  for (const panel of panels) {
    const { rect, xs, ys, mx, my } = panel;
    g.save();
    g.beginPath();
    g.rect(rect.left - radius, rect.top - radius, rect.width + 2 * radius, rect.height + 2 * radius);
    g.clip();
    for (let i = 0; i < panel.groups.length; i++) {
      g.beginPath();
      for (let k = panel.starts[i]; k < panel.starts[i + 1]; k++) {
        const x = toPixel(mx, slice.data[at + xs[k]]);
        const y = toPixel(my, slice.data[at + ys[k]]);
        if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
        g.moveTo(x + radius, y);
        g.arc(x, y, radius, 0, 2 * Math.PI);
      }
      g.fillStyle = color(panel.groups[i]);
      g.fill();
      if (radius >= 3) {
        g.lineWidth = 1.25;
        g.strokeStyle = ring;
        g.stroke();
      }
    }
    g.restore();
  }
}

/** Default dot radius and line style for a number of tracks: a 1000-particle beam gets fine, translucent lines. */
export function defaultLook(tracks: number): { radius: number; lineWidth: number; lineOpacity: number } {
  return {
    radius: tracks > 100 ? 1.6 : tracks > 10 ? 2.5 : 4,
    lineWidth: tracks > 20 ? 1 : 1.5,
    lineOpacity: tracks > 100 ? 0.55 : 1,
  };
}
