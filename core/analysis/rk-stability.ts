/**
 * Where a four-stage, fourth-order Runge–Kutta method (the classical RK4 and
 * the 3/8 rule alike) stops being stable on an oscillation.
 *
 * Every such method multiplies a solution of ẋ = λx by the same polynomial
 * in z = λΔt per step, R(z) = 1 + z + z²/2 + z³/6 + z⁴/24 (Hairer & Wanner,
 * *Solving Ordinary Differential Equations II*, §IV.2). A harmonic
 * oscillator of frequency ω has λ = ±iω, so one step multiplies its
 * amplitude by |R(iωΔt)|, and the motion stays bounded while that is at
 * most 1: up to ωΔt = 2√2 (where |R(iy)|² = 1 − y⁶/72 + y⁸/576).
 */

/** |R(iy)|: the factor by which one step of RK4 or the 3/8 rule scales an oscillation's amplitude at ωΔt = y. */
export function rk4Amplification(y: number): number {
  const real = 1 - (y * y) / 2 + y ** 4 / 24;
  const imaginary = y - y ** 3 / 6;
  return Math.hypot(real, imaginary);
}

/** The largest ωΔt at which |R(iωΔt)| ≤ 1, found by bisection on the polynomial (not from its closed form, 2√2, which the tests check it against). */
export function rk4StabilityLimit(): number {
  let stable = 0.1;
  let unstable = 4;
  for (let i = 0; i < 200; i++) {
    const mid = (stable + unstable) / 2;
    if (rk4Amplification(mid) <= 1) stable = mid;
    else unstable = mid;
  }
  return stable;
}
