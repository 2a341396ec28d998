/**
 * The leading term of the modified Hamiltonian of the Störmer–Verlet
 * method (kick–drift–kick, "velocity Verlet", the book's `verlet`) for a
 * separable H = T(p) + V(q). Backward error analysis (Hairer, Lubich &
 * Wanner, *Geometric Numerical Integration*, 2nd ed., Springer 2006,
 * ch. IX: §IX.3 for symplectic methods, §IX.4 for splittings via the
 * Baker–Campbell–Hausdorff formula) says that the method's steps are, up
 * to exponentially small terms, exact steps of a Hamiltonian
 *
 *     H̃ = H + h² H₂ + h⁴ H₄ + … .
 *
 * The symmetric BCH formula for the composition φ^V_{h/2} ∘ φ^T_h ∘ φ^V_{h/2}
 * (HLW §III.4.2 and §IX.4) gives h²H₂ from the double brackets: the one
 * with the inner flow twice, {T, {T, V}} = V''(T_p, T_p), weighs 1/12, the
 * one with the outer flow twice, {V, {V, T}} = T''(V_q, V_q), weighs 1/24:
 *
 *     H₂ = (1/12)·V''(q)[T_p, T_p] − (1/24)·T''(p)[V_q, V_q],
 *
 * i.e. (1/12)·pᵀV''p − (1/24)·|∇V|² for H = p²/2 + V(q). The relative sign
 * is pinned by the harmonic oscillator, where the map is linear and its
 * exact invariant p² + ω²(1 − h²ω²/4)q² is found by hand; the unit tests
 * check that invariant, and that on the pendulum H + h²H₂ varies only by
 * O(h⁴) while H varies by O(h²).
 *
 * It is computed here from the model's field f = (T_p, −V_q) and its
 * Jacobian, whose blocks are ∂q̇/∂p = T'' and ∂ṗ/∂q = −V'', so it needs no
 * symbolic H: any model whose H separates will do.
 */
import type { VectorField } from '../types.ts';

export type JacobianAt = (t: number, x: Float64Array, out: Float64Array) => void;

/** x ↦ H₂(x) for Störmer–Verlet (kick–drift–kick) on a separable H; see the module comment. */
export function verletCorrection(field: VectorField, jacobian: JacobianAt, dim: number): (t: number, x: Float64Array) => number {
  const n = dim / 2;
  const f = new Float64Array(dim);
  const J = new Float64Array(dim * dim);
  return (t, x) => {
    field(t, x, f);
    J.fill(0);
    jacobian(t, x, J);
    let potential = 0; // V''(T_p, T_p) = Σ V_{q_i q_j} T_{p_i} T_{p_j}, V_{q_i q_j} = −∂ṗ_i/∂q_j
    let kinetic = 0; // T''(V_q, V_q) = Σ T_{p_i p_j} V_{q_i} V_{q_j}, T_{p_i p_j} = ∂q̇_i/∂p_j, V_q = −ṗ
    for (let i = 0; i < n; i++) {
      for (let j = 0; j < n; j++) {
        potential += -J[(n + i) * dim + j] * f[i] * f[j];
        kinetic += J[i * dim + (n + j)] * f[n + i] * f[n + j];
      }
    }
    return potential / 12 - kinetic / 24;
  };
}
