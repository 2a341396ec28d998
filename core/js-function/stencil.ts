import type { VectorField } from '../types.ts';

/** A Hamiltonian as an opaque function of time and the state. */
export type OpaqueHamiltonian = (t: number, x: Float64Array) => number;

// ε^(1/5): the step that balances the stencil's O(h⁴) truncation against its
// O(ε/h) rounding, relative to the size of the coordinate.
const RELATIVE_STEP = Math.pow(Number.EPSILON, 0.2);

/**
 * Hamilton's equations from an opaque H by the 5-point central difference
 *
 *     ∂H/∂x_i ≈ [H(x − 2h) − 8H(x − h) + 8H(x + h) − H(x + 2h)] / 12h,
 *
 * with h = ε^(1/5)·max(1, |x_i|), rounded so that x_i ± h is exact. Its error
 * is O(h⁴·H⁽⁵⁾) + O(ε·|H|/h): about 1e-13 relative for a smooth H of unit
 * scale, where the paper's 2-point formula with fixed h = 1e-6 loses
 * 40–500× the accuracy of the RK 3/8 step itself on a non-quadratic H.
 * Costs 4·2n evaluations of H per field evaluation.
 */
export function stencilField(hamiltonian: OpaqueHamiltonian, dim: number): VectorField {
  const dof = dim / 2;
  const y = new Float64Array(dim);
  return (t, x, dxdt) => {
    y.set(x);
    for (let i = 0; i < dim; i++) {
      const xi = x[i];
      const h = xi + RELATIVE_STEP * Math.max(1, Math.abs(xi)) - xi;
      y[i] = xi - 2 * h;
      const m2 = hamiltonian(t, y);
      y[i] = xi - h;
      const m1 = hamiltonian(t, y);
      y[i] = xi + h;
      const p1 = hamiltonian(t, y);
      y[i] = xi + 2 * h;
      const p2 = hamiltonian(t, y);
      y[i] = xi;
      const gradient = (m2 - 8 * m1 + 8 * p1 - p2) / (12 * h);
      // ẋ = ω∇H: q̇_i = ∂H/∂p_i, ṗ_i = −∂H/∂q_i.
      if (i < dof) dxdt[i + dof] = -gradient;
      else dxdt[i - dof] = gradient;
    }
  };
}

/** The field ω∇H from a gradient the author supplies. */
export function gradientField(gradient: VectorField, dim: number): VectorField {
  const dof = dim / 2;
  const g = new Float64Array(dim);
  return (t, x, dxdt) => {
    gradient(t, x, g);
    for (let i = 0; i < dof; i++) {
      dxdt[i] = g[i + dof];
      dxdt[i + dof] = -g[i];
    }
  };
}
