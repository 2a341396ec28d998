/**
 * The symplectic condition MᵀΩM = Ω by finite differences
 * (core/analysis/flow-map.ts) against maps whose Jacobians are known in
 * closed form: the harmonic oscillator's exact flow (a canonical map,
 * Goldstein §9.4), the damped oscillator's exact flow, for which
 * MᵀΩM = det M·Ω with det M = e^{−2γT} (Liouville's formula: the trace of
 * its linear vector field is −2γ), the shear (q, p) ↦ (q + Bp, p), canonical
 * exactly when B is symmetric (MᵀΩM − Ω = [[0, 0], [0, Bᵀ − B]]), two
 * uncoupled oscillators, and the pendulum's flow by a plain RK4 written here.
 */
import { describe, expect, test } from 'vitest';
import { flowJacobian, symplecticCheck, symplecticDefect } from '../../../../core/analysis/flow-map.ts';

/** The exact flow over T of H = p²/2 + ω²q²/2 for each pair (q_i, p_i), the state ordered q_1..q_n, p_1..p_n. */
const oscillators = (omegas: readonly number[], T: number) => (x: Float64Array) => {
  const n = omegas.length;
  const y = new Float64Array(2 * n);
  omegas.forEach((w, i) => {
    const [c, s] = [Math.cos(w * T), Math.sin(w * T)];
    y[i] = x[i] * c + (x[i + n] / w) * s;
    y[i + n] = -x[i] * w * s + x[i + n] * c;
  });
  return y;
};

/** The exact flow over T of q̈ + 2γq̇ + ω₀²q = 0 with p = q̇, underdamped (ω_d = √(ω₀² − γ²)). */
const dampedOscillator = (omega0: number, gamma: number, T: number) => (x: Float64Array) => {
  const wd = Math.sqrt(omega0 ** 2 - gamma ** 2);
  const [c, s, decay] = [Math.cos(wd * T), Math.sin(wd * T), Math.exp(-gamma * T)];
  return Float64Array.of(decay * (x[0] * c + ((x[1] + gamma * x[0]) / wd) * s), decay * (x[1] * c - ((omega0 ** 2 * x[0] + gamma * x[1]) / wd) * s));
};

/** The pendulum q′ = p, p′ = −sin q over T by the classical fourth-order Runge–Kutta method at step dt. */
const pendulumRK4 = (T: number, dt: number) => (x: Float64Array) => {
  let [q, p] = [x[0], x[1]];
  for (let i = 0, steps = Math.round(T / dt); i < steps; i++) {
    const [k1q, k1p] = [p, -Math.sin(q)];
    const [k2q, k2p] = [p + (dt / 2) * k1p, -Math.sin(q + (dt / 2) * k1q)];
    const [k3q, k3p] = [p + (dt / 2) * k2p, -Math.sin(q + (dt / 2) * k2q)];
    const [k4q, k4p] = [p + dt * k3p, -Math.sin(q + dt * k3q)];
    q += (dt / 6) * (k1q + 2 * k2q + 2 * k3q + k4q);
    p += (dt / 6) * (k1p + 2 * k2p + 2 * k3p + k4p);
  }
  return Float64Array.of(q, p);
};

describe('flowJacobian(flow, x0, ε)', () => {
  test('is the harmonic oscillator’s matrix [[cos ωT, sin ωT/ω], [−ω sin ωT, cos ωT]], row-major', () => {
    const [w, T] = [1.7, 3];
    const M = flowJacobian(oscillators([w], T), [0.4, -0.2], 1e-4);
    const expected = [Math.cos(w * T), Math.sin(w * T) / w, -w * Math.sin(w * T), Math.cos(w * T)];
    expected.forEach((m, i) => expect(Math.abs(M[i] - m)).toBeLessThan(1e-11));
  });

  test('hands the flow copies, never x0, and refuses a step ε ≤ 0', () => {
    const x0 = Float64Array.of(0.4, -0.2);
    flowJacobian((x) => {
      x[0] = 99;
      return x;
    }, x0, 1e-3);
    expect(Array.from(x0)).toEqual([0.4, -0.2]);
    expect(() => flowJacobian(oscillators([1], 1), [0, 0], 0)).toThrow(/ε/);
  });
});

describe('symplecticDefect(M, n) and symplecticCheck(flow, x0, ε)', () => {
  test('the harmonic oscillator’s exact flow is canonical: defect below 10⁻⁹ at ε = 10⁻⁴', () => {
    const check = symplecticCheck(oscillators([1.7], 3), [0.4, -0.2], 1e-4);
    expect(check.defect).toBeLessThan(1e-9);
    expect(check.defectHalf).toBeLessThan(1e-9);
  });

  test('a damped oscillator is not: e^{−γT} times a rotation and the exact flow of q̈ + 2γq̇ + ω₀²q = 0 both give |e^{−2γT} − 1| (γ = 0.1, T = 3) to 10⁻⁶', () => {
    const [gamma, T] = [0.1, 3];
    const expected = Math.abs(Math.exp(-2 * gamma * T) - 1);
    // e^{−γT}R(ωT): the exact flow of q′ = −γq + ωp, p′ = −ωq − γp
    const w = 1.3;
    const shrinkingRotation = (x: Float64Array) => {
      const [c, s, decay] = [Math.cos(w * T), Math.sin(w * T), Math.exp(-gamma * T)];
      return Float64Array.of(decay * (c * x[0] + s * x[1]), decay * (-s * x[0] + c * x[1]));
    };
    expect(Math.abs(symplecticCheck(shrinkingRotation, [0.3, 0.5], 1e-4).defect - expected)).toBeLessThan(1e-6);
    expect(Math.abs(symplecticCheck(dampedOscillator(2, gamma, T), [0.3, 0.5], 1e-4).defect - expected)).toBeLessThan(1e-6);
    // and det M − 1 read off the Jacobian directly
    const M = flowJacobian(dampedOscillator(2, gamma, T), [0.3, 0.5], 1e-4);
    expect(Math.abs(M[0] * M[3] - M[1] * M[2] - Math.exp(-2 * gamma * T))).toBeLessThan(1e-9);
  });

  test('the pendulum’s flow by RK4 over T = 5 at dt = 10⁻³ shows a defect below 10⁻⁸ at ε = 10⁻⁴, all of it the differencing’s', () => {
    // RK4 is not symplectic, but its step's Jacobian is the exact flow's to O(dt⁵), so the map's own
    // defect is O(T·dt⁴) ≈ 10⁻¹¹ here. What the central difference sees at ε = 10⁻⁴ is its own
    // truncation, cε² with c the flow's third derivatives: about 2·10⁻⁹ from (q, p) = (1, 0), which
    // Richardson's estimate accounts for to 10⁻¹⁰ (observed: defect 2.25·10⁻⁹, estimate 2.21·10⁻⁹).
    const check = symplecticCheck(pendulumRK4(5, 1e-3), [1, 0], 1e-4);
    expect(check.defect).toBeLessThan(1e-8);
    expect(check.defectHalf).toBeLessThan(check.defect / 3);
    expect(Math.abs(check.defect - check.truncation)).toBeLessThan(1e-10);
  });

  test('a non-canonical error in the flow is seen above the truncation: the RK4 pendulum with p scaled by 1 + 10⁻⁶ at the end', () => {
    const rk4 = pendulumRK4(5, 1e-3);
    const check = symplecticCheck((x) => {
      const y = rk4(x);
      y[1] *= 1 + 1e-6;
      return y;
    }, [1, 0], 1e-4);
    // det M = 1 + 10⁻⁶: the defect is 10⁻⁶, far above the 2·10⁻⁹ of differencing
    expect(Math.abs(check.defect - 1e-6)).toBeLessThan(5e-9);
    expect(check.truncation).toBeLessThan(1e-8);
  });

  test('two dof, q₁ q₂ p₁ p₂: uncoupled oscillators of frequencies 1 and 2.3 are canonical; the same maps applied to the pairs (x₀, x₁), (x₂, x₃) are not', () => {
    const omegas = [1, 2.3];
    const T = 1.1;
    expect(symplecticCheck(oscillators(omegas, T), [0.1, 0.2, -0.3, 0.4], 1e-4).defect).toBeLessThan(1e-9);
    // the oscillators applied as if the state were ordered q₁ p₁ q₂ p₂: canonical for that Ω, not for this one
    const misordered = (x: Float64Array) => {
      const y = oscillators(omegas, T)(Float64Array.of(x[0], x[2], x[1], x[3]));
      return Float64Array.of(y[0], y[2], y[1], y[3]);
    };
    expect(symplecticCheck(misordered, [0.1, 0.2, -0.3, 0.4], 1e-4).defect).toBeGreaterThan(0.1);
  });

  test('the shear (q, p) ↦ (q + Bp, p) on two dof has defect max|Bᵀ − B|: zero for B symmetric, 0.3 for B₁₂ = 0.3, B₂₁ = 0', () => {
    const shear = (B: number[][]) => {
      const M = new Float64Array(16);
      for (let i = 0; i < 4; i++) M[i * 4 + i] = 1;
      for (let i = 0; i < 2; i++) for (let j = 0; j < 2; j++) M[i * 4 + 2 + j] = B[i][j];
      return M;
    };
    expect(symplecticDefect(shear([[0.5, 0.3], [0.3, -1]]), 2)).toBe(0);
    expect(symplecticDefect(shear([[0.5, 0.3], [0, -1]]), 2)).toBeCloseTo(0.3, 15);
    expect(symplecticDefect(shear([[0, 0], [0.3, 0]]), 2)).toBeCloseTo(0.3, 15);
    expect(() => symplecticDefect(new Float64Array(9), 2)).toThrow(/16 entries/);
  });
});
