/**
 * The scattering chapter's truths against independent values: Rutherford's
 * angle at a special point, turning points and deflections from a plain RK4
 * integration of the orbit, and the far-start limit of the exact orbit.
 */
import { describe, expect, test } from 'vitest';
import { SCATTERING_TRUTHS } from '../../../../../../widgets/chapter/exercise/truths/scattering.ts';
import { integrateUntil } from './rk4.ts';

const { rutherfordDeflection, headOnTurningPoint, rightAngleImpact } = SCATTERING_TRUTHS;

/** Hamilton's equations of H = |p|²/2m + α/r in the plane (q0, q1, p0, p1). */
const coulomb = (alpha: number, mass: number) => (_t: number, [x, y, px, py]: readonly number[]) => {
  const r3 = Math.hypot(x, y) ** 3;
  return [px / mass, py / mass, (alpha * x) / r3, (alpha * y) / r3];
};

describe('rutherfordDeflection', () => {
  test('tan(θ/2) = α/2Eb is 1 at b = α/2E: a right angle (Landau & Lifshitz §19)', () => {
    expect(rutherfordDeflection.compute({ alpha: 30, E: 16, b: 30 / 32 })).toBeCloseTo(Math.PI / 2, 14);
  });
  test('a particle integrated with RK4 from x = −2000 leaves at Rutherford’s angle, to the start’s 1/|x₀| effects', () => {
    const [alpha, mass, p0, b] = [30, 0.5, 4, 1.5];
    const { x } = integrateUntil(coulomb(alpha, mass), 0, [-2000, b, p0, 0], 2e-3, ([x, y]) => Math.hypot(x, y) > 2000 && x > 0);
    const angle = Math.atan2(x[3], x[2]);
    expect(Math.abs(angle - rutherfordDeflection.compute({ alpha, E: (p0 * p0) / (2 * mass), b }))).toBeLessThan(2e-3);
  });
});

describe('headOnTurningPoint', () => {
  test('the head-on particle integrated with RK4 from x = −20 with p = 3 stops where the truth says', () => {
    const [alpha, mass] = [30, 0.5];
    const { before } = integrateUntil(coulomb(alpha, mass), 0, [-20, 0, 3, 0], 1e-5, ([, , px]) => px < 0);
    expect(headOnTurningPoint.compute({ alpha, p0: 3, mass, x0: -20 })).toBeCloseTo(before[0], 5);
    expect(headOnTurningPoint.compute({ alpha: -30, p0: 3, mass, x0: -20 })).toBeNaN();
  });
});

describe('rightAngleImpact', () => {
  test('from a far start it is Rutherford’s α/2E₀ (Landau & Lifshitz §19)', () => {
    const far = rightAngleImpact.compute({ alpha: 30, p0: 4, mass: 0.5, x0: -1e7 });
    expect(far).toBeCloseTo(30 / 32, 5);
  });
  test('from x₀ = −20, a particle integrated with RK4 at that b leaves at a right angle', () => {
    const [alpha, mass, p0] = [30, 0.5, 4];
    const b = rightAngleImpact.compute({ alpha, p0, mass, x0: -20 });
    const { x } = integrateUntil(coulomb(alpha, mass), 0, [-20, b, p0, 0], 1e-3, ([x, y]) => Math.hypot(x, y) > 3000);
    expect(Math.abs(Math.atan2(x[3], x[2]) - Math.PI / 2)).toBeLessThan(1e-4);
  });
});
