/**
 * Truths for “Order and chaos”: the disk Hénon and Heiles's section fills,
 * the factor of the paper's two-body variant for a given mass ratio of its
 * relative motion, and Kepler's third law for the isotropic problem. Closed
 * forms, independent of the chapter's integrations.
 */
import type { Truth } from '../truth.ts';

export const CHAOS_TRUTHS: Readonly<Record<string, Truth>> = {
  henonHeilesSectionRadius: {
    args: ['energy'],
    // On y = 0, V = x²/2: the crossings satisfy x² + pₓ² = 2E − p_y² ≤ 2E.
    compute: ({ energy }) => (energy > 0 ? Math.sqrt(2 * energy) : NaN),
    method: 'closed form √(2E): on the plane y = 0 the Hénon–Heiles potential is x²/2, so x² + pₓ² ≤ 2E (Hénon & Heiles 1964; Lichtenberg & Lieberman, ch. 1), exact',
  },
  anisotropicFactor: {
    args: ['mu', 'sign'],
    // H = Σp² − k/hypot(c·x1 − x2, y1 − y2) has a = c² + 1 along u and b = 2 along v; μ = a/b for the u direction heavier.
    compute: ({ mu, sign }) => (2 * mu - 1 >= 0 && sign !== 0 ? Math.sign(sign) * Math.sqrt(2 * mu - 1) : NaN),
    method: 'closed form c = ±√(2μ − 1): the relative motion of Σp² − k/hypot(c·x1 − x2, y1 − y2) has a = c² + 1 along u and b = 2 along v, so μ = a/b = (c² + 1)/2 (Gutzwiller 1990, ch. 11, for the anisotropic problem), exact',
  },
  isotropicKeplerPeriod: {
    args: ['a', 'k', 'energy'],
    compute: ({ a, k, energy }) => {
      if (!(a > 0 && k > 0 && energy < 0)) return NaN;
      const mass = 1 / (2 * a); // H = a·p² is p²/2m
      const semiMajor = k / (2 * Math.abs(energy)); // E = −k/2A
      return 2 * Math.PI * Math.sqrt((mass * semiMajor ** 3) / k);
    },
    method: 'Kepler’s third law T = 2π√(mA³/k), with m = 1/(2a) and A = k/(2|E|) (Landau & Lifshitz, Mechanics, §15), exact',
  },
};
