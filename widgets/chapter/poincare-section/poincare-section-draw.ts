/**
 * The drawing of a surface of section on its point panel: the rim of the
 * region the energy allows, each orbit's crossings in its series colour, and
 * the reader's launched orbits in the accent colour.
 */
import type { Domain } from '../../plots/scale.ts';
import type { PanelFrame } from '../../plots/point-panel.ts';
import { seriesColor } from '../../plots/theme.ts';
import type { SectionView } from './section-systems.ts';

/** One orbit's crossings of the plane, as (u, p_u) pairs. */
export interface Crossings {
  u: Float64Array;
  pu: Float64Array;
}

/** An orbit the reader launched, with its largest Lyapunov exponent. */
export interface LaunchedOrbit extends Crossings {
  exponent: number;
}

/** Room around the allowed region, so that its rim does not lie on the frame. */
const PAD = 1.08;

/** The plane's ranges drawn: the region's box, padded, centred on it in u and symmetric in p_u. */
export function sectionDomains(view: SectionView): { u: Domain; pu: Domain } {
  const box = view.box;
  const mid = (box.uMin + box.uMax) / 2;
  const half = ((box.uMax - box.uMin) / 2) * PAD;
  return { u: [mid - half, mid + half], pu: [-box.puMax * PAD, box.puMax * PAD] };
}

/** The energy's boundary on the plane: V(u) + p²/2 = E for Hénon–Heiles, the unit circle for the Kepler problem; upper half left to right, lower back. */
export function drawRim({ g, mx, my, theme }: PanelFrame, view: SectionView): void {
  const box = view.box;
  g.strokeStyle = theme.muted;
  g.lineWidth = 1;
  g.beginPath();
  for (let sign = -1, first = true; sign <= 1; sign += 2) {
    for (let i = 0; i <= 200; i++) {
      const u = sign < 0 ? box.uMin + ((box.uMax - box.uMin) * i) / 200 : box.uMax - ((box.uMax - box.uMin) * i) / 200;
      const p = sign * view.rim(u);
      (first ? g.moveTo : g.lineTo).call(g, mx.scale(u), my.scale(p));
      first = false;
    }
  }
  g.closePath();
  g.stroke();
}

/** Each orbit's crossings as dots of side `dot` (CSS px) in its own series colour. */
export function drawCrossings({ g, mx, my, theme }: PanelFrame, orbits: readonly Crossings[], dot: number): void {
  orbits.forEach((o, k) => {
    g.fillStyle = seriesColor(theme, k);
    for (let i = 0; i < o.u.length; i++) g.fillRect(mx.scale(o.u[i]) - dot / 2, my.scale(o.pu[i]) - dot / 2, dot, dot);
  });
}

/** The reader's orbits, a little larger, in the accent colour: they stand out from the section's. */
export function drawLaunched({ g, mx, my, theme }: PanelFrame, launched: readonly Crossings[]): void {
  g.fillStyle = theme.accent;
  for (const o of launched) for (let i = 0; i < o.u.length; i++) g.fillRect(mx.scale(o.u[i]) - 1.25, my.scale(o.pu[i]) - 1.25, 2.5, 2.5);
}
