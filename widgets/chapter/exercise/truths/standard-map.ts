/**
 * Truths for the standard map: where its two simplest periodic orbits turn
 * unstable, from the traces of their Jacobians' products, and Chirikov's
 * overlap of its primary resonances, each a closed form.
 */
import type { Truth } from '../truth.ts';

export const STANDARD_MAP_TRUTHS: Readonly<Record<string, Truth>> = {
  mainIslandLimit: {
    args: [],
    // tr M(π) = 2 − K leaves (−2, 2) at K = 4.
    compute: () => 4,
    method: 'closed form: the trace 2 − K of the Jacobian at the fixed point (π, 0) reaches −2 at K = 4 (Greene 1979), exact',
  },
  halfResonanceLimit: {
    args: [],
    // tr M(π)M(0) = 2 − K² leaves (−2, 2) at K = 2.
    compute: () => 2,
    method: 'closed form: the trace 2 − K² of the product of the Jacobians along the period-2 orbit through (0, π) reaches −2 at K = 2 (Greene 1979), exact',
  },
  primaryOverlap: {
    args: [],
    // 4√K = 2π.
    compute: () => Math.PI ** 2 / 4,
    method: 'closed form π²/4, where the primary resonances of half-width 2√K, 2π apart, touch (Chirikov 1979), exact',
  },
};
