/**
 * Hamiltonians of n degrees of freedom whose size grows in proportion to n,
 * written out term by term as a reader would type them: the inputs for
 * measuring how the cost of building a model grows with n
 * (bench/model-build.ts) and for checking large models' derivatives
 * (tests/unit/core/expression/model-build.test.ts). States are named q0…, p0…; with n = 1
 * the compiler takes q0 and p0 as q and p.
 */

/** n uncoupled unit oscillators, H = Σ (p_i² + q_i²)/2. */
export function harmonicSource(n: number): string {
  return Array.from({ length: n }, (_, i) => `(p${i}^2 + q${i}^2)/2`).join(' + ');
}

/**
 * The FPU-β chain of n unit masses between two fixed walls:
 * H = Σ p_i²/2 + Σ_bonds [Δ²/2 + β Δ⁴/4], Δ the stretch of each of the
 * n + 1 bonds (q_{i+1} − q_i between masses, ±q at a wall, since the walls
 * sit at q = 0). β is a parameter.
 */
export function fpuSource(n: number): string {
  const kinetic = Array.from({ length: n }, (_, i) => `p${i}^2/2`);
  const stretches = [`q0`, ...Array.from({ length: n - 1 }, (_, i) => `(q${i + 1} - q${i})`), `q${n - 1}`];
  const bonds = stretches.map((d) => `${d}^2/2 + beta*${d}^4/4`);
  return [...kinetic, ...bonds].join(' + ');
}
