/**
 * The symplectic condition MᵀΩM = Ω for the Jacobian M of a flow map
 * x(0) ↦ x(T), measured by finite differences: a Hamiltonian flow is a
 * canonical transformation, and this is the condition that says so
 * (Goldstein, *Classical Mechanics*, §9.4; Arnold, *Mathematical Methods of
 * Classical Mechanics*, §38), Liouville's theorem (det M = 1) being its
 * consequence. The state is ordered q_1..q_n, p_1..p_n, as the book's
 * models are, so Ω = [[0, I], [−I, 0]].
 *
 * The central difference has a truncation error O(ε²) and a rounding error
 * of about u·|x|/ε (u the unit roundoff, magnified by the flow's own
 * sensitivity): too small an ε buys rounding, too large a one truncation.
 * symplecticCheck runs at ε and ε/2 to say which of the two a defect is.
 *
 * Only a Hamiltonian flow is canonical: a model with a non-Hamiltonian term
 * (model/non-hamiltonian.ts), a damped oscillator's friction say, shrinks
 * phase-space volume by design, so its defect is the physics, not an error,
 * and symplecticCheck says the check is outside its validity.
 */
import type { CheckCondition } from './check-input.ts';
import { hamiltonianFlowCondition } from '../model/non-hamiltonian.ts';
import type { NonHamiltonianPart } from '../types.ts';

/**
 * The 2n×2n Jacobian M_ij = ∂x_i(T)/∂x_j(0) of `flow` at x0, row-major, by the
 * central differences (flow(x0 + εe_j) − flow(x0 − εe_j))/(2ε): the
 * linearised flow, whose symplecticity a canonical map must show. `flow` is
 * given copies of the state, never x0 itself.
 */
export function flowJacobian(flow: (x0: Float64Array) => Float64Array, x0: ArrayLike<number>, epsilon: number): Float64Array {
  if (!(epsilon > 0 && Number.isFinite(epsilon))) throw new RangeError(`the difference step ε must be positive and finite, not ${epsilon}`);
  const dim = x0.length;
  const M = new Float64Array(dim * dim);
  for (let j = 0; j < dim; j++) {
    const plus = Float64Array.from(x0);
    const minus = Float64Array.from(x0);
    plus[j] += epsilon;
    minus[j] -= epsilon;
    const [up, down] = [flow(plus), flow(minus)];
    if (up.length !== dim || down.length !== dim) throw new RangeError(`the flow must return a state of ${dim} coordinates, not ${up.length === dim ? down.length : up.length}`);
    // The steps actually taken, x0 ± ε rounded, rather than ±ε.
    const width = plus[j] - minus[j];
    for (let i = 0; i < dim; i++) M[i * dim + j] = (up[i] - down[i]) / width;
  }
  return M;
}

/** MᵀΩM − Ω for a 2n×2n row-major M, entry by entry: (MᵀΩM)_ij = Σ_{k<n}(M_ki M_{k+n,j} − M_{k+n,i} M_kj). */
function symplecticResidual(M: ArrayLike<number>, n: number): Float64Array {
  const dim = 2 * n;
  if (!(Number.isInteger(n) && n >= 1)) throw new RangeError(`the number of degrees of freedom must be a positive integer, not ${n}`);
  if (M.length !== dim * dim) throw new RangeError(`a ${dim}×${dim} matrix has ${dim * dim} entries, not ${M.length}`);
  const S = new Float64Array(dim * dim);
  for (let i = 0; i < dim; i++) {
    for (let j = 0; j < dim; j++) {
      let s = 0;
      for (let k = 0; k < n; k++) s += M[k * dim + i] * M[(k + n) * dim + j] - M[(k + n) * dim + i] * M[k * dim + j];
      const omega = j === i + n ? 1 : i === j + n ? -1 : 0;
      S[i * dim + j] = s - omega;
    }
  }
  return S;
}

/**
 * The largest |(MᵀΩM − Ω)_ij| of a 2n×2n row-major M, Ω = [[0, I], [−I, 0]]
 * for the state q_1..q_n, p_1..p_n: zero for a canonical map, and for one
 * degree of freedom |det M − 1|, since MᵀΩM = det M·Ω for any 2×2 M.
 */
export function symplecticDefect(M: ArrayLike<number>, n: number): number {
  return symplecticResidual(M, n).reduce((worst, s) => Math.max(worst, Math.abs(s)), 0);
}

/**
 * The symplectic defect of `flow` at x0 with the difference step ε and ε/2,
 * and `truncation`, the Richardson estimate of the finite differences' error
 * in MᵀΩM − Ω at ε: central differences err by cε² + O(ε⁴), so the error at
 * ε is 4/3 of the change from ε to ε/2, taken here as the largest over the
 * entries. A defect well above `truncation` belongs to the map; one at or
 * below it is the differencing's (or, if halving ε raised the defect,
 * rounding's). The state has 2n coordinates, n = x0.length/2.
 *
 * `validity` holds the conditions of the claim MᵀΩM = Ω, for a theory
 * check's `validity` (check-input.ts): given the model whose flow `flow` is,
 * one that fails when the model has a non-Hamiltonian term. A bare flow,
 * with no model, is taken at its word.
 */
export function symplecticCheck(
  flow: (x0: Float64Array) => Float64Array,
  x0: ArrayLike<number>,
  epsilon: number,
  model?: { readonly nonHamiltonian?: NonHamiltonianPart },
): { defect: number; defectHalf: number; truncation: number; validity: CheckCondition[] } {
  if (x0.length % 2 !== 0 || x0.length === 0) throw new RangeError(`a state q_1..q_n, p_1..p_n has an even number of coordinates, not ${x0.length}`);
  const n = x0.length / 2;
  const S = symplecticResidual(flowJacobian(flow, x0, epsilon), n);
  const half = symplecticResidual(flowJacobian(flow, x0, epsilon / 2), n);
  let [defect, defectHalf, change] = [0, 0, 0];
  for (let i = 0; i < S.length; i++) {
    defect = Math.max(defect, Math.abs(S[i]));
    defectHalf = Math.max(defectHalf, Math.abs(half[i]));
    change = Math.max(change, Math.abs(S[i] - half[i]));
  }
  const validity = [hamiltonianFlowCondition(model, 'its flow is not canonical')];
  return { defect, defectHalf, truncation: (4 / 3) * change, validity };
}
