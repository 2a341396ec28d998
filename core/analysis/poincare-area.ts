/**
 * The fraction of a surface of section covered by chaotic orbits, the
 * quantity of Hénon & Heiles (1964), Fig. 6 (there as its complement, the
 * "relative area covered by curves"). Launch points on a uniform grid over
 * the section's allowed region are classified by their finite-time largest
 * Lyapunov exponent: regular orbits' λ(T) decays like ln T / T, chaotic ones
 * stay near the sea's exponent, which is far larger at these energies.
 *
 * The error of the fraction has two named parts: the grid's sampling error,
 * √(f(1 − f)/N) as for N independent draws, and the classification's,
 * estimated by the share of points whose verdict at T/2 differs from that
 * at T (sticky orbits near islands that look regular for a while).
 */
import type { PlanarSystem } from './henon-heiles.ts';
import { largestLyapunov } from './lyapunov.ts';
import { launchState, type Plane } from './poincare.ts';

/**
 * The published curve: Hénon & Heiles (1964), Fig. 6, plots the relative
 * area of their section (x = 0, in y and p_y) covered by invariant curves
 * against E. Its complement, the chaotic share, at the three energies of
 * their Figs. 2–5, read off that figure by eye: no chaos visible at 1/12, a
 * little under half at 1/8, almost all at 1/6. `reading` is the error of
 * reading a printed figure (and of a hand count of curves behind it).
 */
export const HENON_HEILES_FIG6: readonly { energy: number; chaotic: number; reading: number }[] = [
  { energy: 1 / 12, chaotic: 0, reading: 0.05 },
  { energy: 1 / 8, chaotic: 0.45, reading: 0.1 },
  { energy: 1 / 6, chaotic: 0.9, reading: 0.1 },
];

export interface AreaOptions {
  plane?: Plane;
  /** grid points per side of the bounding box (only those inside the allowed region count) */
  grid?: number;
  time?: number;
  dt?: number;
  /** λ(T) above this counts as chaotic */
  threshold?: number;
  progress?: (fraction: number) => void;
}

export interface ChaoticArea {
  fraction: number;
  chaotic: number;
  total: number;
  /** √(f(1 − f)/N) */
  samplingError: number;
  /** share of points whose verdict changed between T/2 and T */
  undecided: number;
  /** the launch points and their verdicts, for drawing */
  points: { u: number; pu: number; exponent: number; chaotic: boolean }[];
}

/** The section's extent at energy E: the box [−a, a] × [−b, b] holding the allowed region, found by scanning. */
export function sectionBox(system: PlanarSystem, energy: number, plane: Plane = 'y') {
  let uMin = 0;
  let uMax = 0;
  const V = (u: number) => (plane === 'y' ? system.potential(u, 0) : system.potential(0, u));
  for (let u = 0; V(u) < energy && u < 10; u += 1e-4) uMax = u;
  for (let u = 0; V(u) < energy && u > -10; u -= 1e-4) uMin = u;
  return { uMin, uMax, puMax: Math.sqrt(2 * energy) };
}

export function chaoticArea(system: PlanarSystem, energy: number, options: AreaOptions = {}): ChaoticArea {
  const { plane = 'x', grid = 14, time = 600, dt = 0.05, threshold = 0.02, progress } = options;
  const box = sectionBox(system, energy, plane);
  const launches: { u: number; pu: number; s: Float64Array }[] = [];
  for (let i = 0; i < grid; i++) {
    for (let j = 0; j < grid; j++) {
      // cell centres, so that no point sits on the boundary where p = 0
      const u = box.uMin + ((i + 0.5) / grid) * (box.uMax - box.uMin);
      const pu = -box.puMax + ((j + 0.5) / grid) * 2 * box.puMax;
      const s = launchState(system, energy, u, pu, plane);
      if (s) launches.push({ u, pu, s });
    }
  }
  const points: ChaoticArea['points'] = [];
  let chaotic = 0;
  let flipped = 0;
  launches.forEach(({ u, pu, s }, k) => {
    const run = largestLyapunov(system, s, { time, dt });
    const half = run.estimates[Math.floor(run.estimates.length / 2) - 1];
    const isChaotic = !run.finished || run.exponent > threshold;
    if (isChaotic !== (half > threshold)) flipped++;
    if (isChaotic) chaotic++;
    points.push({ u, pu, exponent: run.exponent, chaotic: isChaotic });
    progress?.((k + 1) / launches.length);
  });
  const total = launches.length;
  const fraction = total ? chaotic / total : NaN;
  // At f = 0 or 1 the binomial formula gives 0; one grid point's share is the honest floor.
  const samplingError = Math.max(Math.sqrt((fraction * (1 - fraction)) / total), 1 / total);
  return { fraction, chaotic, total, samplingError, undecided: flipped / total, points };
}
