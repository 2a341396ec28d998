/**
 * Planar systems with two degrees of freedom, state [x, y, px, py], written
 * in closed form with their exact Jacobians, for surfaces of section and
 * Lyapunov exponents. These run in a worker thousands of times per chart,
 * so they are plain functions rather than compiled expressions; the
 * Jacobian here is checked in the tests against the symbolic one of
 * core/expression/jacobian.ts and against differences of the field.
 */
import type { VectorField } from '../types.ts';

export interface PlanarSystem {
  readonly name: string;
  /** V(x, y); the kinetic energy is (px² + py²)/2 in every system here */
  potential(x: number, y: number): number;
  /** H at the state s = [x, y, px, py] */
  energy(s: ArrayLike<number>): number;
  /** Hamilton's equations: (px, py, −∂V/∂x, −∂V/∂y) */
  field: VectorField;
  /** ∂f/∂s, row-major 4×4, written into J */
  jacobian(s: ArrayLike<number>, J: Float64Array): void;
}

/**
 * Hénon & Heiles (1964), Astron. J. 69, 73:
 *   H = (px² + py²)/2 + (x² + y²)/2 + x²y − y³/3.
 * Bounded motion for E < 1/6, the energy of the three saddles of V.
 */
export const henonHeiles: PlanarSystem = {
  name: 'Hénon–Heiles',
  potential: (x, y) => 0.5 * (x * x + y * y) + x * x * y - (y * y * y) / 3,
  energy(s) {
    return 0.5 * (s[2] * s[2] + s[3] * s[3]) + this.potential(s[0], s[1]);
  },
  field(_t, s, out) {
    const x = s[0];
    const y = s[1];
    out[0] = s[2];
    out[1] = s[3];
    out[2] = -x - 2 * x * y;
    out[3] = -y - x * x + y * y;
  },
  jacobian(s, J) {
    const x = s[0];
    const y = s[1];
    J.fill(0);
    J[0 * 4 + 2] = 1;
    J[1 * 4 + 3] = 1;
    // ∂/∂(x, y) of −∂V/∂x = −x − 2xy and of −∂V/∂y = −y − x² + y²: minus V's Hessian
    J[2 * 4 + 0] = -1 - 2 * y;
    J[2 * 4 + 1] = -2 * x;
    J[3 * 4 + 0] = -2 * x;
    J[3 * 4 + 1] = -1 + 2 * y;
  },
};

/** The isotropic harmonic oscillator H = (px² + py² + x² + y²)/2: integrable, every exponent zero. */
export const harmonicOscillator: PlanarSystem = {
  name: 'harmonic oscillator',
  potential: (x, y) => 0.5 * (x * x + y * y),
  energy(s) {
    return 0.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + s[3] * s[3]);
  },
  field(_t, s, out) {
    out[0] = s[2];
    out[1] = s[3];
    out[2] = -s[0];
    out[3] = -s[1];
  },
  jacobian(_s, J) {
    J.fill(0);
    J[2] = 1;
    J[7] = 1;
    J[8] = -1;
    J[13] = -1;
  },
};
