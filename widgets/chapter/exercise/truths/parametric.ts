/**
 * Truths for the parametric-resonance chapter: the Floquet multiplier and
 * growth rate of Mathieu's equation q̈ + ω²(1 + u cos γt) q = 0, and the edge
 * of its first instability tongue.
 *
 * The chapter measures these with the book's RK 3/8 stepper (its checks, its
 * stability chart). To be graded against something else, the monodromy matrix
 * here comes from its own classical fourth-order Runge–Kutta integration of
 * the two fundamental solutions over one drive period (Arnold, Mathematical
 * Methods, §25): a second method, sharing no code with the chapter.
 */
import type { Truth } from '../truth.ts';

/**
 * Steps per drive period. RK4's error per period is about (ωh)⁵ per step,
 * with ωh = 2πω/γN ≈ 1.5·10⁻³ for γ ≈ 2ω: below 10⁻¹² in tr M in total.
 */
const STEPS = 2000;

/** The monodromy matrix's trace over one drive period 2π/γ, by classical RK4. */
export function mathieuTrace(omega: number, u: number, gamma: number): number {
  const period = (2 * Math.PI) / gamma;
  const h = period / STEPS;
  const stiffness = (t: number) => omega * omega * (1 + u * Math.cos(gamma * t));
  // Both fundamental solutions, (q, p) from (1, 0) and from (0, 1), advance together.
  let [q1, p1, q2, p2] = [1, 0, 0, 1];
  for (let i = 0; i < STEPS; i++) {
    const t = i * h;
    const [k0, kh, k1] = [stiffness(t), stiffness(t + h / 2), stiffness(t + h)];
    const step = (q: number, p: number): [number, number] => {
      const a1 = p, b1 = -k0 * q;
      const a2 = p + (h / 2) * b1, b2 = -kh * (q + (h / 2) * a1);
      const a3 = p + (h / 2) * b2, b3 = -kh * (q + (h / 2) * a2);
      const a4 = p + h * b3, b4 = -k1 * (q + h * a3);
      return [q + (h / 6) * (a1 + 2 * a2 + 2 * a3 + a4), p + (h / 6) * (b1 + 2 * b2 + 2 * b3 + b4)];
    };
    [q1, p1] = step(q1, p1);
    [q2, p2] = step(q2, p2);
  }
  return q1 + p2;
}

/** The multiplier of largest magnitude, signed: a root of λ² − (tr M)λ + 1 = 0 (det M = 1); of magnitude 1 when stable. */
export function floquetMultiplier(omega: number, u: number, gamma: number): number {
  const half = mathieuTrace(omega, u, gamma) / 2;
  if (Math.abs(half) <= 1) return 1;
  return half + Math.sign(half) * Math.sqrt(half * half - 1);
}

/**
 * The drive frequency at the upper (side = 1) or lower (side = −1) edge of
 * the first tongue at depth u: where |tr M| = 2. Walks out from the tongue's
 * centre, 2ω − u²ω/32, in steps of uω/20 until the motion is stable, then
 * bisects to rounding. For 0 < u ≲ 0.8 no other tongue lies on the way.
 */
export function tongueEdge(omega: number, u: number, side: number): number {
  const unstable = (gamma: number) => Math.abs(mathieuTrace(omega, u, gamma)) > 2;
  const w = Math.abs(omega), depth = Math.abs(u);
  let inside = 2 * w - (depth * depth * w) / 32;
  if (!(depth > 0) || !unstable(inside)) return NaN;
  const stride = Math.sign(side) * (depth * w) / 20;
  let outside = inside + stride;
  for (let k = 0; unstable(outside); k++) {
    if (k > 40) return NaN;
    inside = outside;
    outside += stride;
  }
  for (let k = 0; k < 60 && Math.abs(outside - inside) > 1e-12 * w; k++) {
    const middle = (inside + outside) / 2;
    if (unstable(middle)) inside = middle;
    else outside = middle;
  }
  return (inside + outside) / 2;
}

const RK4_SOURCE = 'the monodromy matrix of Mathieu’s equation over one drive period, by an independent classical RK4 integration (2000 steps, tr M to 10⁻¹²), with λ² − (tr M)λ + 1 = 0 (Arnold, Mathematical Methods, §25; Landau & Lifshitz §27)';

export const PARAMETRIC_TRUTHS: Readonly<Record<string, Truth>> = {
  floquetGrowth: {
    args: ['omega', 'u', 'gamma'],
    compute: ({ omega, u, gamma }) => (Math.log(Math.abs(floquetMultiplier(omega, u, gamma))) * Math.abs(gamma)) / (2 * Math.PI),
    method: `s = ln|λ|/T from ${RK4_SOURCE}`,
  },
  floquetMultiplier: {
    args: ['omega', 'u', 'gamma'],
    compute: ({ omega, u, gamma }) => floquetMultiplier(omega, u, gamma),
    method: `the larger multiplier λ from ${RK4_SOURCE}`,
  },
  tongueEdge: {
    args: ['omega', 'u', 'side'],
    compute: ({ omega, u, side }) => tongueEdge(omega, u, side),
    method: `the γ where |tr M| = 2, found by bisection, from ${RK4_SOURCE}`,
  },
};
