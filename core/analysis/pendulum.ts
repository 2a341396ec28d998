/**
 * The plane pendulum H = p²/2 − ω² cos q in closed form: its period from
 * the complete elliptic integral of the first kind,
 *
 *     T = 4 K(k)/ω,  k = sin(q_max/2),  k² = (E + ω²)/(2ω²),
 *
 * (Landau & Lifshitz, *Mechanics*, §11, problem 1; Abramowitz & Stegun
 * 17.6 for K by the arithmetic–geometric mean), so that an integrator's
 * error after exactly one period is its distance from the initial state.
 *
 * Its action–angle variables too: the action J = (1/2π)∮p dq of a
 * libration in closed form from K and the complete elliptic integral of
 * the second kind E, and the frequency ω(J) = ∂H/∂J = 2π/T (Landau &
 * Lifshitz §50, problem; Lichtenberg & Lieberman, *Regular and Chaotic
 * Dynamics*, §1.3), against which an action measured from a simulated
 * orbit is checked.
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

/**
 * The AGM of A&S 17.6 for the modulus k (|k| < 1): K(k) = π/(2a_N), and the
 * tail Σ_{n≥1} 2^{n−1}c_n² of the sum that gives E (the n = 0 term, c_0²/2 =
 * k²/2, is left to the caller, so that E − k′²K = K(k²/2 − tail) can be formed
 * without cancelling two numbers near π/2 against each other at small k).
 * c_{n+1} = c_n²/(4a_{n+1}) rather than (a_n − b_n)/2, which would lose c's
 * digits to the subtraction once a and b agree.
 */
function arithmeticGeometricMean(k: number): { K: number; tail: number } {
  let a = 1;
  let b = Math.sqrt(1 - k * k);
  let c = Math.abs(k);
  let weight = 0.5;
  let tail = 0;
  for (let n = 1; n < 40; n++) {
    const next = (a + b) / 2;
    c = (c * c) / (4 * next);
    b = Math.sqrt(a * b);
    a = next;
    weight *= 2;
    const term = weight * c * c;
    tail += term;
    if (term <= 1e-17 * (k * k)) break;
  }
  return { K: Math.PI / (2 * a), tail };
}

/**
 * E(k) = ∫₀^{π/2} √(1 − k² sin²θ) dθ for |k| < 1 (NaN otherwise), by the same
 * AGM as K with the sum of A&S 17.6.3–4, E = K(1 − Σ_{n≥0} 2^{n−1}c_n²),
 * c_0 = k: the pendulum's action needs E beside K, and the AGM gives both to
 * rounding in about five iterations. E is even in k; negative k are accepted,
 * as completeEllipticK accepts them.
 */
export function completeEllipticE(k: number): number {
  if (!(Math.abs(k) < 1)) return NaN;
  const { K, tail } = arithmeticGeometricMean(k);
  return K * (1 - (k * k) / 2 - tail);
}

/**
 * k² = (H + ω²)/(2ω²) of the pendulum started from (q0, p0), written as
 * sin²(q0/2) + p0²/(4ω²) so that a small swing is not lost to 1 − cos q0;
 * NaN unless 0 ≤ k² < 1, a libration.
 */
function librationModulusSquared(q0: number, p0: number, omega: number): number {
  const k2 = Math.sin(q0 / 2) ** 2 + (p0 * p0) / (4 * omega * omega);
  return k2 >= 0 && k2 < 1 ? k2 : NaN;
}

/**
 * The action J = (1/2π)∮p dq of the libration of H = p²/2 − ω² cos q through
 * (q0, p0): the area of its phase curve over 2π,
 *
 *     J = (8ω/π)[E(k) − (1 − k²)K(k)],  k² = (H + ω²)/(2ω²)
 *
 * (Landau & Lifshitz §50, problem; Lichtenberg & Lieberman §1.3), the
 * adiabatic invariant and the momentum of the action–angle pair. For small
 * swings J → E₀/ω(1 + E₀/16ω²), E₀ = H + ω², the harmonic oscillator's E/ω.
 * NaN when the motion is not a libration. E − k′²K is formed as
 * K(k²/2 − Σ_{n≥1}2^{n−1}c_n²), exact in relative terms as k → 0.
 */
export function pendulumAction(q0: number, p0: number, omega = 1): number {
  const k2 = librationModulusSquared(q0, p0, omega);
  if (Number.isNaN(k2)) return NaN;
  const { K, tail } = arithmeticGeometricMean(Math.sqrt(k2));
  return ((8 * Math.abs(omega)) / Math.PI) * K * (k2 / 2 - tail);
}

/**
 * The frequency of the libration through (q0, p0) as a function of its
 * action, ω(J) = ∂H/∂J = πω/(2K(k)) = 2π/T: the rate at which the angle
 * variable advances, which falls from ω at the bottom to 0 at the
 * separatrix, the pendulum's nonlinearity in one number. NaN when the
 * motion is not a libration.
 */
export function pendulumFrequency(q0: number, p0: number, omega = 1): number {
  const k2 = librationModulusSquared(q0, p0, omega);
  if (Number.isNaN(k2)) return NaN;
  return (Math.PI * Math.abs(omega)) / (2 * arithmeticGeometricMean(Math.sqrt(k2)).K);
}
