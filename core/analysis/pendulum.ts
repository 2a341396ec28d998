/**
 * The plane pendulum H = p²/2 − ω² cos q in closed form: its period from
 * the complete elliptic integral of the first kind,
 *
 *     T = 4 K(k)/ω,  k = sin(q_max/2),  k² = (E + ω²)/(2ω²),
 *
 * (Landau & Lifshitz, *Mechanics*, §11, problem 1; Abramowitz & Stegun
 * 17.6 for K by the arithmetic–geometric mean), so that an integrator's
 * error after exactly one period is its distance from the initial state.
 */

/**
 * K(k) = ∫₀^{π/2} dθ/√(1 − k² sin²θ) = π/(2·AGM(1, √(1 − k²))) for 0 ≤ k < 1
 * (Abramowitz & Stegun 17.6.1): the AGM converges quadratically, to
 * rounding in about five iterations.
 */
export function completeEllipticK(k: number): number {
  if (!(Math.abs(k) < 1)) return NaN;
  let a = 1;
  let b = Math.sqrt(1 - k * k);
  for (let i = 0; i < 40 && Math.abs(a - b) > 1e-16 * a; i++) [a, b] = [(a + b) / 2, Math.sqrt(a * b)];
  return Math.PI / (a + b);
}

/**
 * The period of the pendulum H = p²/2 − ω² cos q started from (q0, p0);
 * NaN when the motion is not a libration (it goes over the top, E ≥ ω²).
 */
export function pendulumPeriod(q0: number, p0: number, omega = 1): number {
  const w2 = omega * omega;
  const energy = (p0 * p0) / 2 - w2 * Math.cos(q0);
  const k2 = (energy + w2) / (2 * w2);
  if (!(k2 >= 0 && k2 < 1)) return NaN;
  return (4 * completeEllipticK(Math.sqrt(k2))) / Math.abs(omega);
}
