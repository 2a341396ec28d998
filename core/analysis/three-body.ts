/**
 * The circular restricted three-body problem in the rotating frame, in the
 * units G = 1, m1 + m2 = 1, separation 1, angular velocity 1, with the
 * primaries of masses 1 − μ and μ at (−μ, 0) and (1 − μ, 0):
 *
 *   H = (px² + py²)/2 + y·px − x·py − (1 − μ)/r1 − μ/r2
 *
 * (Murray & Dermott, Solar System Dynamics, ch. 3; Szebehely, Theory of
 * Orbits, 1967). The state is [x, y, px, py].
 */

/** Routh's critical mass ratio: L4 and L5 are linearly stable for μ below it (Murray & Dermott §3.8). */
export const ROUTH_MU = (1 - Math.sqrt(23 / 27)) / 2;

/** The effective potential Ω = (x² + y²)/2 + (1 − μ)/r1 + μ/r2; the Jacobi constant is C = 2Ω − v². */
export function effectivePotential(x: number, y: number, mu: number): number {
  const r1 = Math.hypot(x + mu, y);
  const r2 = Math.hypot(x - 1 + mu, y);
  return (x * x + y * y) / 2 + (1 - mu) / r1 + mu / r2;
}

/** The Jacobi constant C = −2H of a state [x, y, px, py]. */
export function jacobiConstant(state: ArrayLike<number>, mu: number): number {
  const [x, y, px, py] = [state[0], state[1], state[2], state[3]];
  const r1 = Math.hypot(x + mu, y);
  const r2 = Math.hypot(x - 1 + mu, y);
  const h = (px * px + py * py) / 2 + y * px - x * py - (1 - mu) / r1 - mu / r2;
  return -2 * h;
}

/** The value of the polynomial with coefficients `c` (highest power first) at γ. */
function polynomial(c: readonly number[], gamma: number): number {
  return c.reduce((sum, a) => sum * gamma + a, 0);
}

/**
 * The quintics whose positive root is the distance γ of a collinear point
 * from its nearer primary (Szebehely, Theory of Orbits; Murray & Dermott ch. 3),
 * from the force balance ∂Ω/∂x = 0 on the axis cleared of its denominators:
 * L1 lies at 1 − μ − γ, L2 at 1 − μ + γ (both measured from m2), L3 at −μ − γ
 * (measured from m1).
 */
export function collinearQuintics(mu: number): Record<'L1' | 'L2' | 'L3', number[]> {
  const m = 1 - mu;
  return {
    L1: [1, -(3 - mu), 3 - 2 * mu, -mu, 2 * mu, -mu],
    L2: [1, 3 - mu, 3 - 2 * mu, -mu, -2 * mu, -mu],
    L3: [1, 2 + mu, 1 + 2 * mu, -m, -2 * m, -m],
  };
}

/**
 * The root of `c` in (low, high), where it changes sign, by bisection to the
 * last bit: bisection, because it cannot miss a bracketed root.
 */
function bracketedRoot(c: readonly number[], low: number, high: number): number {
  let a = low;
  let b = high;
  const fa = Math.sign(polynomial(c, a));
  if (fa === Math.sign(polynomial(c, b))) return NaN;
  for (let i = 0; i < 200; i++) {
    const mid = (a + b) / 2;
    if (mid === a || mid === b) break;
    if (Math.sign(polynomial(c, mid)) === fa) a = mid;
    else b = mid;
  }
  return (a + b) / 2;
}

export interface LagrangePoint {
  name: 'L1' | 'L2' | 'L3' | 'L4' | 'L5';
  x: number;
  y: number;
  /** the Jacobi constant of a particle at rest there, 2Ω: the level at which the forbidden region opens at that point */
  jacobi: number;
}

/**
 * The five equilibria of the rotating frame, for 0 < μ ≤ 1/2: L1, L2, L3 as
 * the roots of their quintics, L4 and L5 in closed form at the apexes of the
 * equilateral triangles on the primaries, (1/2 − μ, ±√3/2).
 */
export function lagrangePoints(mu: number): LagrangePoint[] {
  if (!(mu > 0 && mu <= 0.5)) throw new RangeError(`the mass ratio μ must lie in (0, 1/2], not ${mu}`);
  const q = collinearQuintics(mu);
  // L1 lies between the primaries (γ < 1); L2 and L3 within one separation beyond them.
  const g1 = bracketedRoot(q.L1, 0, 1);
  const g2 = bracketedRoot(q.L2, 0, 2);
  const g3 = bracketedRoot(q.L3, 0, 2);
  const at = (name: LagrangePoint['name'], x: number, y: number): LagrangePoint => ({ name, x, y, jacobi: 2 * effectivePotential(x, y, mu) });
  return [
    at('L1', 1 - mu - g1, 0),
    at('L2', 1 - mu + g2, 0),
    at('L3', -mu - g3, 0),
    at('L4', 0.5 - mu, Math.sqrt(3) / 2),
    at('L5', 0.5 - mu, -Math.sqrt(3) / 2),
  ];
}

/**
 * The small oscillations about L4 (or L5). Below Routh's μ the four roots
 * are imaginary: two frequencies, and nothing grows. Above it two roots
 * a ± ib have a positive real part: a displacement grows at the rate a,
 * turning at b.
 */
export type TriangularModes =
  | { stable: true; /** the long-period (libration) angular frequency */ libration: number; /** the short-period (epicyclic) angular frequency */ epicycle: number; growth: 0 }
  | { stable: false; /** the real part of the growing roots */ growth: number; /** their imaginary part */ rotation: number };

/**
 * The small oscillations about L4 (or L5): the roots of
 * λ⁴ + λ² + (27/4)μ(1 − μ) = 0 (Murray & Dermott §3.8).
 */
export function triangularModes(mu: number): TriangularModes {
  const k = (27 / 4) * mu * (1 - mu);
  const discriminant = 1 - 4 * k;
  if (discriminant >= 0) {
    // λ² = (−1 ± √(1 − 4k))/2, both negative: λ = ±iω
    const root = Math.sqrt(discriminant);
    return { stable: true, libration: Math.sqrt((1 - root) / 2), epicycle: Math.sqrt((1 + root) / 2), growth: 0 };
  }
  // λ² = (−1 ± i√(4k − 1))/2 has modulus √k: λ = ±(a ± ib) with a² = (√k − 1/2)/2, b² = (√k + 1/2)/2
  const modulus = Math.sqrt(k);
  return { stable: false, growth: Math.sqrt((modulus - 0.5) / 2), rotation: Math.sqrt((modulus + 0.5) / 2) };
}

/**
 * Points of the zero-velocity curve 2Ω(x, y) = C inside the square |x|, |y| ≤ half,
 * found where 2Ω − C changes sign between neighbours of an n × n grid, along
 * its rows and its columns, and placed there by linear interpolation (to
 * within the grid's spacing squared times Ω's curvature). Also the grid
 * points where 2Ω < C, the region a particle of Jacobi constant C cannot
 * reach, since v² = 2Ω − C would be negative there (Murray & Dermott ch. 3).
 */
export function zeroVelocityCurve(mu: number, C: number, { half = 1.6, n = 161, coarse = 41 } = {}): { curve: [number, number][]; forbidden: [number, number][] } {
  const level = (x: number, y: number) => 2 * effectivePotential(x, y, mu) - C;
  const at = (i: number, m: number) => -half + (2 * half * i) / (m - 1);
  const curve: [number, number][] = [];
  const values = Array.from({ length: n }, (_, j) => Array.from({ length: n }, (_, i) => level(at(i, n), at(j, n))));
  const cross = (a: number, b: number) => a / (a - b);
  for (let j = 0; j < n; j++) {
    for (let i = 0; i + 1 < n; i++) {
      const [a, b] = [values[j][i], values[j][i + 1]];
      if (Math.sign(a) !== Math.sign(b) && Number.isFinite(a) && Number.isFinite(b)) curve.push([at(i, n) + cross(a, b) * (at(1, n) - at(0, n)), at(j, n)]);
      const [c, d] = [values[i][j], values[i + 1][j]];
      if (Math.sign(c) !== Math.sign(d) && Number.isFinite(c) && Number.isFinite(d)) curve.push([at(j, n), at(i, n) + cross(c, d) * (at(1, n) - at(0, n))]);
    }
  }
  const forbidden: [number, number][] = [];
  for (let j = 0; j < coarse; j++) for (let i = 0; i < coarse; i++) if (level(at(i, coarse), at(j, coarse)) < 0) forbidden.push([at(i, coarse), at(j, coarse)]);
  return { curve, forbidden };
}
