/**
 * The implicit midpoint rule's Newton iteration: the exact Jacobian the
 * expression route generates, checked against second derivatives worked by
 * hand, and the generic version for an opaque H or a vector field, whose
 * Jacobian is a central difference, checked against closed-form motion.
 */
import { describe, expect, it } from 'vitest';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { compileModel } from '../../../../core/model/compile-model.ts';
import { methodChoice } from '../../../../core/integrators/methods.ts';
import type { MidpointStats } from '../../../../core/integrators/midpoint.ts';

function jacobianOf(source: string, params: Float64Array, t: number, x: number[]): number[] {
  const evaluate = new Function(source)()(params) as (t: number, x: Float64Array, out: Float64Array) => void;
  const out = new Float64Array(x.length * x.length);
  evaluate(t, Float64Array.from(x), out);
  return Array.from(out);
}

describe('implicit midpoint rule', () => {
  it('has the exact Jacobian of the pendulum: ∂f/∂x = [[0, 1], [−cos q, 0]]', async () => {
    const compiled = await compileModel({ dof: 1, hamiltonian: 'p^2/2 - g*cos(q)', params: { g: 2 }, method: 'midpoint' });
    expect(compiled.method).toBe('midpoint');
    const j = jacobianOf(compiled.code!.jacobian!, Float64Array.of(2), 0, [0.7, 0.3]);
    expect(j[0]).toBe(0);
    expect(j[1]).toBe(1);
    expect(j[2]).toBeCloseTo(-2 * Math.cos(0.7), 15);
    expect(j[3]).toBe(0);
  });

  it('has the exact Jacobian of Kepler: ∂ṗ/∂q = −(I/r³ − 3qqᵀ/r⁵), ∂q̇/∂p = I', async () => {
    const compiled = await compileModel({ dof: 2, hamiltonian: 'p0^2/2 + p1^2/2 - 1/sqrt(q0^2 + q1^2)', method: 'midpoint' });
    const [x, y] = [0.6, -0.8];
    const r = Math.hypot(x, y);
    const j = jacobianOf(compiled.code!.jacobian!, new Float64Array(0), 0, [x, y, 0.1, 0.9]);
    // Rows: q̇0, q̇1, ṗ0, ṗ1; columns q0, q1, p0, p1.
    const expected = [
      [0, 0, 1, 0],
      [0, 0, 0, 1],
      [-(1 / r ** 3 - (3 * x * x) / r ** 5), (3 * x * y) / r ** 5, 0, 0],
      [(3 * x * y) / r ** 5, -(1 / r ** 3 - (3 * y * y) / r ** 5), 0, 0],
    ].flat();
    j.forEach((v, i) => expect(v).toBeCloseTo(expected[i], 13));
  });

  it('converges in a few Newton iterations per step with the exact Jacobian', async () => {
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 - cos(q)', method: methodChoice('midpoint') });
    const x = Float64Array.of(2, 0);
    model.stepper.advance(x, 1, model.params, 0, 0, 0.01, 1000);
    const stats = (model.stepper as unknown as { stats: MidpointStats }).stats;
    // Quadratic convergence from an O(h²) guess: 2–3 iterations reach a correction below 1e-10.
    expect(stats.iterations / stats.steps).toBeLessThanOrEqual(3);
  });

  it('runs an opaque JS H and a vector field with a difference Jacobian, at order 2 on the oscillator', async () => {
    const opaque = (t: number, x: Float64Array) => (x[0] * x[0] + x[1] * x[1]) / 2;
    const field = (t: number, x: Float64Array, dxdt: Float64Array) => {
      dxdt[0] = x[1];
      dxdt[1] = -x[0];
    };
    for (const model of [
      await canonicalEquations({ dof: 1, hamiltonian: opaque, differentiation: 'stencil', method: methodChoice('midpoint') }),
      await canonicalEquations({ dof: 1, vectorField: field, method: methodChoice('midpoint') }),
    ]) {
      expect(model.accuracy).toMatch(/central differences/);
      const error = (dt: number) => {
        const x = Float64Array.of(1, 0);
        model.stepper.advance(x, 1, model.params, 0, 0, dt, Math.round(10 / dt));
        return Math.hypot(x[0] - Math.cos(10), x[1] + Math.sin(10));
      };
      // Order 2: halving dt quarters the error (HLW, Geometric Numerical Integration, §II.1).
      expect(Math.log2(error(0.1) / error(0.05))).toBeCloseTo(2, 1);
    }
  });

  it('stops with one line when Newton cannot converge', async () => {
    // Steps of dt = 100 on a stiff quartic well (ω ~ 1e4 at q = 1): G(Y) is so nonlinear that Newton wanders off.
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + 1e8*q^4', method: methodChoice('midpoint') });
    const x = Float64Array.of(1, 0);
    expect(() => model.stepper.advance(x, 1, model.params, 0, 0, 100, 10)).toThrow(
      /^the implicit midpoint rule's Newton iteration did not converge in the step from t = \d+: take a smaller dt$/,
    );
  });
});
