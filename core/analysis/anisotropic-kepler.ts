/**
 * The anisotropic Kepler problem, H = a·p_u² + b·p_v² − k/√(u² + v²): a body
 * of mass 1/(2a) along u and 1/(2b) along v in a round Coulomb potential
 * (Gutzwiller 1990, Chaos in Classical and Quantum Mechanics, ch. 11).
 * The paper's chaotic two-body variant, H = Σp² − k/hypot(c·x1 − x2, y1 − y2)
 * with c = 1.5, reduces to it with a = c² + 1 and b = 2 (relativeMotion).
 *
 * Regularisation, and why this one. Near a collision the momenta grow like
 * r^(−1/2) and the force like r^(−2), so a fixed time step fails at every
 * close approach. We use the Levi-Civita transformation (Levi-Civita 1920;
 * Stiefel & Scheifele 1971, §§9–10)
 *
 *     u + i·v = (ξ + i·η)²,   p_ξ = 2ξ·p_u + 2η·p_v,   p_η = −2η·p_u + 2ξ·p_v,
 *
 * a point transformation extended canonically, together with the Poincaré
 * time transformation dt = r·ds on the extended phase space: the flow of
 *
 *     K = r·(H − E) = (a + b)/8·(p_ξ² + p_η²) + (a − b)/8·Q/r − k − E·r,
 *     Q = (ξ² − η²)(p_ξ² − p_η²) − 4ξη·p_ξ·p_η,   r = ξ² + η²,
 *
 * on its level K = 0 is the flow of H on H = E, run in the fictitious time s.
 * It was chosen over the Sundman transformation alone (dt = r·ds in u, v,
 * which leaves the momenta unbounded at r = 0) and over a plain adaptive
 * step in t (whose steps shrink like r^(3/2) and whose error piles up at each
 * approach) because:
 *
 * - it stays Hamiltonian, so the Jacobian below is the exact Hessian of K and
 *   the tangent flow is symplectic, as the Lyapunov exponent needs;
 * - at isotropy (a = b) K is exactly the harmonic oscillator
 *   a·(p_ξ² + p_η²)/4 + |E|·r − k, regular everywhere, which the tests check
 *   against Kepler's laws;
 * - with a ≠ b no transformation can regularise the collision: Devaney
 *   (1978, J. Differential Equations 29, 252, "Nonregularizability of the
 *   anisotropic Kepler problem") proved that collision orbits cannot be
 *   continued continuously. Here the term Q/r is bounded (it depends on the
 *   direction of (ξ, η) only) and its force grows like 1/√r only along
 *   orbits that pass within √r of the centre: milder than 1/r², and an exact
 *   collision is a set of measure zero. The adaptive Dormand–Prince step in
 *   s (anisotropic-kepler-flow.ts) resolves what remains.
 *
 * State layout of the regularised flow: z = [ξ, η, p_ξ, p_η, t], the physical
 * time carried along as dt/ds = r.
 */
import type { VectorField } from '../types.ts';

export interface AnisotropicKepler {
  /** coefficient of p_u²: the mass along u is 1/(2a) */
  readonly a: number;
  /** coefficient of p_v²: the mass along v is 1/(2b) */
  readonly b: number;
  /** strength of the attraction −k/r */
  readonly k: number;
}

/** The paper's coupling constant (section 7.1). */
export const PAPER_K = 500;
/** The paper's initial state [x1, y1, x2, y2, px1, py1, px2, py2] (section 7.1). */
export const PAPER_INITIAL: readonly number[] = [-3, -3, 3, 3, 2, -3, -2, 3];

/**
 * The relative motion of H = Σp² − k/hypot(c·x1 − x2, y1 − y2). With
 * u = c·x1 − x2, w = x1 + c·x2 (∇w ⊥ ∇u, so no p_u·p_w cross term),
 * v = y1 − y2, Y = (y1 + y2)/2:
 * p_x1² + p_x2² = (c² + 1)(p_u² + p_w²), p_y1² + p_y2² = 2p_v² + p_Y²/2, so
 * a = c² + 1, b = 2, and p_u = (c·p_x1 − p_x2)/(c² + 1), p_v = (p_y1 − p_y2)/2.
 * Returns the system and the relative state [u, v, p_u, p_v].
 */
export function relativeMotion(factor: number, initial: ArrayLike<number> = PAPER_INITIAL, k = PAPER_K): { system: AnisotropicKepler; state: Float64Array } {
  const a = factor * factor + 1;
  const [x1, y1, x2, y2, px1, py1, px2, py2] = Array.from(initial);
  const state = Float64Array.of(factor * x1 - x2, y1 - y2, (factor * px1 - px2) / a, (py1 - py2) / 2);
  return { system: { a, b: 2, k }, state };
}

/** Heavy mass over light one, m_heavy/m_light = max(a, b)/min(a, b) (Gutzwiller's and Devaney's μ). */
export function massRatio(system: AnisotropicKepler): number {
  return Math.max(system.a, system.b) / Math.min(system.a, system.b);
}

/**
 * Devaney (1978, Inventiones Math. 45, 221, "Collision orbits in the
 * anisotropic Kepler problem"): for μ > 9/8 orbits can wind any number of
 * times about the heavy axis between crossings of the light one, and the
 * orbits of a closed invariant set are coded by doubly infinite sequences of
 * these winding numbers (symbolic dynamics).
 */
export const DEVANEY_THRESHOLD = 9 / 8;

/** H at the physical state [u, v, p_u, p_v]. */
export function keplerEnergy(system: AnisotropicKepler, s: ArrayLike<number>): number {
  return system.a * s[2] * s[2] + system.b * s[3] * s[3] - system.k / Math.hypot(s[0], s[1]);
}

/** L = u·p_v − v·p_u, conserved only at isotropy. */
export function angularMomentum(s: ArrayLike<number>): number {
  return s[0] * s[3] - s[1] * s[2];
}

/**
 * [u, v, p_u, p_v] → [ξ, η, p_ξ, p_η], one of the two square roots ((ξ, η)
 * and (−ξ, −η) are the same physical point): ξ ≥ 0 for u ≥ 0, and η ≥ 0 for
 * u < 0, v = 0. The larger of ξ² = (r + u)/2 and η² = (r − u)/2 is taken
 * from its formula and the other from v = 2ξη, so that neither suffers the
 * cancellation of r + u or r − u near the negative or positive u-axis.
 */
export function toLeviCivita(s: ArrayLike<number>): Float64Array {
  const [u, v, pu, pv] = [s[0], s[1], s[2], s[3]];
  const r = Math.hypot(u, v);
  let xi: number;
  let eta: number;
  if (u >= 0) {
    xi = Math.sqrt((r + u) / 2);
    eta = xi > 0 ? v / (2 * xi) : 0;
  } else {
    eta = (v < 0 ? -1 : 1) * Math.sqrt((r - u) / 2);
    xi = v / (2 * eta);
  }
  return Float64Array.of(xi, eta, 2 * xi * pu + 2 * eta * pv, -2 * eta * pu + 2 * xi * pv);
}

/** [ξ, η, p_ξ, p_η, …] → [u, v, p_u, p_v]: the inverse of the momenta's 2×2 map, whose determinant is 4r. */
export function fromLeviCivita(z: ArrayLike<number>): Float64Array {
  const [xi, eta, pxi, peta] = [z[0], z[1], z[2], z[3]];
  const r = xi * xi + eta * eta;
  return Float64Array.of(xi * xi - eta * eta, 2 * xi * eta, (xi * pxi - eta * peta) / (2 * r), (eta * pxi + xi * peta) / (2 * r));
}

/** K = r(H − E) at z: zero along the orbit, so its size measures the integration error. */
export function regularisedHamiltonian(system: AnisotropicKepler, energy: number, z: ArrayLike<number>): number {
  const [xi, eta, pxi, peta] = [z[0], z[1], z[2], z[3]];
  const r = xi * xi + eta * eta;
  const Q = (xi * xi - eta * eta) * (pxi * pxi - peta * peta) - 4 * xi * eta * pxi * peta;
  return ((system.a + system.b) / 8) * (pxi * pxi + peta * peta) + ((system.a - system.b) / 8) * (Q / r) - system.k - energy * r;
}

/** dz/ds for z = [ξ, η, p_ξ, p_η, t]: Hamilton's equations of K, and dt/ds = r. */
export function regularisedField(system: AnisotropicKepler, energy: number): VectorField {
  const alpha = (system.a + system.b) / 4;
  const delta = (system.a - system.b) / 8;
  return (_s, z, out) => {
    const xi = z[0], eta = z[1], pxi = z[2], peta = z[3];
    const r = xi * xi + eta * eta;
    const c = xi * xi - eta * eta, sv = 2 * xi * eta; // u and v
    const C = pxi * pxi - peta * peta, S = 2 * pxi * peta;
    out[0] = alpha * pxi;
    out[1] = alpha * peta;
    out[2] = 2 * energy * xi;
    out[3] = 2 * energy * eta;
    if (delta !== 0) {
      // Q = c·C − sv·S; its gradient, and that of Q/r with ∇r = (2ξ, 2η).
      const Q = c * C - sv * S;
      const Qxi = 2 * xi * C - 2 * eta * S, Qeta = -2 * eta * C - 2 * xi * S;
      const Qpxi = 2 * pxi * c - 2 * sv * peta, Qpeta = -2 * peta * c - 2 * sv * pxi;
      out[0] += (delta * Qpxi) / r;
      out[1] += (delta * Qpeta) / r;
      out[2] -= delta * (Qxi / r - (2 * xi * Q) / (r * r));
      out[3] -= delta * (Qeta / r - (2 * eta * Q) / (r * r));
    }
    out[4] = r;
  };
}

/**
 * ∂f/∂z for the canonical part (ξ, η, p_ξ, p_η), row-major 4×4, written into J:
 * J = [[K_pq, K_pp], [−K_qq, −K_qp]] from the exact Hessian of K. With
 * F = Q/r = Q·w, w = 1/r: ∇²F = w∇²Q + ∇Q⊗∇w + ∇w⊗∇Q + Q∇²w, where
 * ∇w = −(2ξ, 2η)/r² and ∇²w = −2I/r² + 8(ξ, η)⊗(ξ, η)/r³ in the coordinates.
 */
export function regularisedJacobian(system: AnisotropicKepler, energy: number, z: ArrayLike<number>, J: Float64Array): void {
  const delta = (system.a - system.b) / 8;
  const xi = z[0], eta = z[1], pxi = z[2], peta = z[3];
  // Hessian of K, order (ξ, η, p_ξ, p_η).
  const H = new Float64Array(16);
  H[0] = -2 * energy;
  H[5] = -2 * energy;
  H[10] = (system.a + system.b) / 4;
  H[15] = (system.a + system.b) / 4;
  if (delta !== 0) {
    const r = xi * xi + eta * eta;
    const c = xi * xi - eta * eta, sv = 2 * xi * eta;
    const C = pxi * pxi - peta * peta, S = 2 * pxi * peta;
    const Q = c * C - sv * S;
    const g = [2 * xi * C - 2 * eta * S, -2 * eta * C - 2 * xi * S, 2 * pxi * c - 2 * sv * peta, -2 * peta * c - 2 * sv * pxi];
    // ∇²Q, symmetric
    const hq = [
      [2 * C, -2 * S, 4 * xi * pxi - 4 * eta * peta, -4 * xi * peta - 4 * eta * pxi],
      [-2 * S, -2 * C, -4 * eta * pxi - 4 * xi * peta, 4 * eta * peta - 4 * xi * pxi],
      [4 * xi * pxi - 4 * eta * peta, -4 * eta * pxi - 4 * xi * peta, 2 * c, -2 * sv],
      [-4 * xi * peta - 4 * eta * pxi, 4 * eta * peta - 4 * xi * pxi, -2 * sv, -2 * c],
    ];
    const w = 1 / r;
    const gw = [(-2 * xi) / (r * r), (-2 * eta) / (r * r), 0, 0];
    const q = [xi, eta];
    for (let i = 0; i < 4; i++) {
      for (let j = 0; j < 4; j++) {
        let hw = 0;
        if (i < 2 && j < 2) hw = (i === j ? -2 / (r * r) : 0) + (8 * q[i] * q[j]) / (r * r * r);
        H[i * 4 + j] += delta * (w * hq[i][j] + g[i] * gw[j] + gw[i] * g[j] + Q * hw);
      }
    }
  }
  // f = (K_p, −K_q): row i of J is ∂f_i/∂z.
  for (let j = 0; j < 4; j++) {
    J[0 * 4 + j] = H[2 * 4 + j];
    J[1 * 4 + j] = H[3 * 4 + j];
    J[2 * 4 + j] = -H[0 * 4 + j];
    J[3 * 4 + j] = -H[1 * 4 + j];
  }
}
