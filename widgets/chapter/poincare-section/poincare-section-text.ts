/**
 * What a surface of section says in words: the summary of what the canvas
 * shows (for those who cannot see it), and the readings of the launch point
 * and of a launched orbit.
 */
import type { Crossings, LaunchedOrbit } from './poincare-section-draw.ts';
import { energyName, type KeplerSetting, type SectionView } from './section-systems.ts';

/** A λ(T) above this is called chaotic: several times what a regular orbit still shows at T (ln T / T ≈ 0.004 at T = 2000; at isotropy |λ(T)| ≤ ln κ / T ≈ 0.004 at T = 500). */
const CHAOTIC_EXPONENT = 0.02;

const regularity = (exponent: number) => (exponent > CHAOTIC_EXPONENT ? 'chaotic' : 'regular');

/** Crossings drawn in all. */
export function crossingCount(orbits: readonly Crossings[], launched: readonly Crossings[]): number {
  return orbits.reduce((n, o) => n + o.u.length, 0) + launched.reduce((n, o) => n + o.u.length, 0);
}

/** The largest distance of an orbit's crossing from its first: 0 when every orbit closes. */
export function spread(orbits: readonly Crossings[]): number {
  let most = 0;
  for (const o of orbits) for (let i = 1; i < o.u.length; i++) most = Math.max(most, Math.hypot(o.u[i] - o.u[0], o.pu[i] - o.pu[0]));
  return most;
}

/** The section in words: its setting, what it holds, how to read it, and the reader's last orbit. */
export function sectionSummary(view: SectionView, kepler: KeplerSetting | null, orbits: readonly Crossings[], launched: readonly LaunchedOrbit[]): string {
  const last = launched[launched.length - 1];
  const what = kepler
    ? `The rim is p_v = 0 and the vertical line σ = 0 the collision. ` +
      (kepler.mu === 1
        ? `At isotropy every orbit is a closed Kepler ellipse: each orbit's crossings fall on one point.`
        : `Curves are orbits confined by an integral; scattered dots are orbits with none.`)
    : `Closed curves are regular orbits on invariant tori; scattered dots fill the chaotic sea.`;
  return (
    `At ${view.setting}: ${orbits.length} orbits, ${crossingCount(orbits, launched)} crossings of ${view.plane}, ` +
    `inside the allowed region (the outer curve). ${what}` +
    (last ? ` Your last orbit: ${last.u.length} crossings, largest Lyapunov exponent ${last.exponent.toPrecision(2)} (${regularity(last.exponent)}).` : '')
  );
}

/** Where the launch point is, as the keys move it. */
export function cursorReading(view: SectionView, [u, pu]: readonly [number, number]): string {
  const label = view.labels;
  return `${label.u} = ${u.toPrecision(3)}, ${label.pu} = ${pu.toPrecision(3)}${view.allowed(u, pu) ? '' : ' (outside the allowed region)'}`;
}

/** Why no orbit starts from (u, pu): the energy does not reach it (or, for the Kepler problem on σ = 0, it is the collision). */
export function outsideReading(view: SectionView, kepler: KeplerSetting | null, energy: number, u: number, pu: number): string {
  const label = view.labels;
  return `${label.u} = ${u.toPrecision(3)}, ${label.pu} = ${pu.toPrecision(3)} lies outside the region ${kepler ? 'the energy' : `E = ${energyName(energy)}`} allows${kepler && u === 0 ? ' (σ = 0 is a collision)' : ''}: choose a point inside the curve.`;
}

/** The orbit launched from (u, pu): its crossings and its largest Lyapunov exponent, called chaotic or regular. */
export function launchReading(view: SectionView, [u, pu]: readonly [number, number], crossings: number, exponent: number | undefined): string {
  const label = view.labels;
  return `Launched from ${label.u} = ${u.toPrecision(3)}, ${label.pu} = ${pu.toPrecision(3)}: ${crossings} crossings, λ ≈ ${(exponent ?? NaN).toPrecision(2)}${(exponent ?? 0) > CHAOTIC_EXPONENT ? ', chaotic' : ', regular'}.`;
}
