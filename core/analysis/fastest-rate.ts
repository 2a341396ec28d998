/**
 * The fastest rate Ω of a motion: the largest modulus of an eigenvalue of
 * the field's Jacobian ∂f/∂x over the states visited. For an oscillation
 * it is the angular frequency of the fastest small oscillation about the
 * orbit (√|V''| for H = p²/2 + V(q)); a step is "small" when Ω·dt is, and
 * the error terms of the integrators are series in Ω·dt.
 */

/** The spectral radius of a real dim×dim matrix, row-major. */
export function spectralRadius(matrix: ArrayLike<number>, dim: number): number {
  if (dim === 2) {
    // The eigenvalues of [[a, b], [c, d]]: tr/2 ± √(tr²/4 − det).
    const [a, b, c, d] = [matrix[0], matrix[1], matrix[2], matrix[3]];
    const half = (a + d) / 2;
    const disc = half * half - (a * d - b * c);
    return disc >= 0 ? Math.max(Math.abs(half + Math.sqrt(disc)), Math.abs(half - Math.sqrt(disc))) : Math.sqrt(half * half - disc);
  }
  // Power iteration on J²: a Hamiltonian Jacobian's eigenvalues come in pairs ±λ, which J alone would
  // leave in a tie; J² has them as λ², and its growth factor per iteration tends to ρ(J)².
  const square = new Float64Array(dim * dim);
  for (let i = 0; i < dim; i++) {
    for (let j = 0; j < dim; j++) {
      let s = 0;
      for (let k = 0; k < dim; k++) s += matrix[i * dim + k] * matrix[k * dim + j];
      square[i * dim + j] = s;
    }
  }
  let v = Float64Array.from({ length: dim }, (_, i) => 1 + i / dim);
  let growth = 0;
  for (let iteration = 0; iteration < 200; iteration++) {
    const w = new Float64Array(dim);
    for (let i = 0; i < dim; i++) for (let k = 0; k < dim; k++) w[i] += square[i * dim + k] * v[k];
    let norm = 0;
    for (const x of w) norm = Math.max(norm, Math.abs(x));
    let before = 0;
    for (const x of v) before = Math.max(before, Math.abs(x));
    if (!(norm > 0)) return 0;
    growth = Math.max(iteration > 150 ? growth : 0, norm / before);
    v = w.map((x) => x / norm);
  }
  return Math.sqrt(growth);
}

/** Ω = the largest spectral radius of `jacobian` at the given states (each of length dim). */
export function fastestRate(
  jacobian: (t: number, x: Float64Array, out: Float64Array) => void,
  dim: number,
  states: readonly Float64Array[],
  t = 0,
): number {
  const out = new Float64Array(dim * dim);
  let rate = 0;
  for (const x of states) {
    out.fill(0);
    jacobian(t, x, out);
    rate = Math.max(rate, spectralRadius(out, dim));
  }
  return rate;
}
