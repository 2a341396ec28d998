/**
 * What the standard-map widget says in words: the summary of the portrait
 * (for those who cannot see it), and the reading of an orbit the reader
 * launched, with the numbers that tell a regular orbit from a chaotic one.
 */
import { GREENE_K } from '../../../core/index.ts';

/** Iterates of an orbit the reader launches: long enough for its Lyapunov exponent to tell. */
export const LAUNCH_ITERATIONS = 5000;

/**
 * A measured exponent above this is called chaotic. A regular orbit's
 * finite-time exponent decays like ln n / n (≈ 0.002 at n = 5000), a
 * chaotic one's tends to its positive limit (≈ ln(K/2) for K ≳ 4, of order
 * 0.1 in the thin layers near K_c); the threshold lies between.
 */
export const CHAOTIC_EXPONENT = 0.01;

/** What the reader's orbit came to (core orbitReading) and where it started. */
export interface LaunchedReading {
  q: number;
  p: number;
  rotation: number;
  lyapunov: number;
  crossed: boolean;
}

const fixed = (x: number, digits = 3) => x.toFixed(digits).replace('-', '−');

/** The portrait in words: K, what it holds, and what K says of the invariant circles. */
export function mapSummary(K: number, orbits: number, points: number, last: LaunchedReading | null): string {
  const circles =
    K === 0
      ? 'At K = 0 every orbit keeps its p: each horizontal line is an invariant circle.'
      : K < GREENE_K
        ? `Below Greene's K_c ≈ ${GREENE_K.toFixed(4)} invariant circles that wind once around q still span the torus: no orbit's p crosses them, and the chaos stays in thin layers about the islands' chains.`
        : `Above Greene's K_c ≈ ${GREENE_K.toFixed(4)} no invariant circle spans q any more: the chaotic sea connects, and an orbit in it wanders in p without bound.`;
  return (
    `The standard map at K = ${Number(K.toFixed(4))}: ${orbits} orbits, ${points} iterates drawn on the torus q in [0, 2π), p in [−π, π). ` +
    `Closed curves are invariant circles and the islands' chains; scattered dots are chaotic orbits. ${circles}` +
    (last ? ` ${launchReading(last)}` : '')
  );
}

/** The launched orbit: its start, rotation number, Lyapunov exponent and whether its p crossed 2π. */
export function launchReading({ q, p, rotation, lyapunov, crossed }: LaunchedReading): string {
  const kind = lyapunov > CHAOTIC_EXPONENT ? 'chaotic' : 'regular';
  return (
    `Your orbit from q = ${fixed(q)}, p = ${fixed(p)}: ${LAUNCH_ITERATIONS} iterates, rotation number ${fixed(rotation, 4)}, ` +
    `Lyapunov exponent ${fixed(lyapunov, 4)} (${kind}); its p ${crossed ? 'moved by more than 2π: no invariant circle bars it' : 'stayed within 2π of its start'}.`
  );
}

/** Where the launch point is, as the keys move it. */
export function cursorReading([q, p]: readonly [number, number]): string {
  return `q = ${fixed(q)}, p = ${fixed(p)}: Enter launches an orbit from here.`;
}
