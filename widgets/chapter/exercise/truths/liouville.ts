/**
 * Truths for Liouville's theorem and Poincaré recurrence: the area of a
 * damped blob, from Liouville's formula d(ln A)/dt = ∇·v = −γ; Kac's mean
 * return time 1/ε to an arc of ε turns; and the golden rotation's first
 * return closer than a distance d, which comes at a Fibonacci number F_k,
 * the first with φ^(−k) < d, since ‖F_k φ‖ = φ^(−k) by Binet's formula.
 */
import type { Truth } from '../truth.ts';

const GOLDEN = (1 + Math.sqrt(5)) / 2;

/** F_k, with F_1 = F_2 = 1, by the recurrence (exact in doubles far beyond the k asked for here). */
function fibonacci(k: number): number {
  let [a, b] = [0, 1];
  for (let i = 0; i < k; i++) [a, b] = [b, a + b];
  return a;
}

export const LIOUVILLE_TRUTHS: Readonly<Record<string, Truth>> = {
  dampedArea: {
    args: ['radius', 'gamma', 't'],
    compute: ({ radius, gamma, t }) => (radius > 0 && t >= 0 ? Math.PI * radius * radius * Math.exp(-gamma * t) : NaN),
    method: 'Liouville’s formula d(ln A)/dt = ∇·v = −γ for ṗ = −∂H/∂q − γp, so A = πr²e^(−γt) (Arnold, Mathematical Methods, §16), exact',
  },
  areaHalvingTime: {
    args: ['gamma'],
    compute: ({ gamma }) => (gamma > 0 ? Math.LN2 / gamma : NaN),
    method: 'Liouville’s formula: A(t) = A(0)e^(−γt) for a damping γ, so the area halves at ln 2/γ, exact',
  },
  kacMeanReturn: {
    args: ['width'],
    compute: ({ width }) => (width > 0 && width <= 1 ? 1 / width : NaN),
    method: 'Kac’s lemma: the mean return time to a set of measure ε under an ergodic measure-preserving map is 1/ε (Kac 1947), exact',
  },
  goldenFirstReturn: {
    args: ['distance'],
    compute: ({ distance }) => {
      if (!(distance > 0 && distance < 0.5)) return NaN;
      // ‖F_k φ‖ = φ^(−k) (Binet), and the closest returns come only at the F_k (Khinchin, Continued Fractions, §6).
      const k = Math.floor(-Math.log(distance) / Math.log(GOLDEN)) + 1;
      return fibonacci(k);
    },
    method: 'the golden rotation’s record returns at the Fibonacci numbers F_k, ‖F_k φ‖ = φ^(−k) (Binet; Khinchin, Continued Fractions, §6), exact',
  },
};
