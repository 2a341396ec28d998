/**
 * The special-relativity chapter's truths against independent values: the
 * rapidity form of the speed, and turning points from a plain RK4
 * integration of H = √(p² + m²) − Fq.
 */
import { describe, expect, test } from 'vitest';
import { RELATIVITY_TRUTHS } from '../../../../../../widgets/chapter/exercise/truths/relativity.ts';
import { integrateUntil } from './rk4.ts';

const { relativisticSpeed, hyperbolicTurningPoint, startMomentumToTurnAt } = RELATIVITY_TRUTHS;
const m = Math.sqrt(10);

/** Hamilton's equations of the chapter's H, integrated until p changes sign: the turning point. */
function turningPoint(q0: number, p0: number, F: number) {
  const { before } = integrateUntil((_t, [, p]) => [p / Math.hypot(p, m), F], 0, [q0, p0], 1e-4, ([, p]) => Math.sign(p) !== Math.sign(p0));
  return before[0];
}

describe('relativisticSpeed', () => {
  test('it is 1/√2 at p = m, and tanh of the rapidity arsinh(p/m) everywhere (Landau & Lifshitz, Fields, §4, §9)', () => {
    expect(relativisticSpeed.compute({ p: m, m })).toBeCloseTo(Math.SQRT1_2, 15);
    for (const p of [-22, -1, 0.3, 5, 400]) expect(relativisticSpeed.compute({ p, m })).toBeCloseTo(Math.tanh(Math.asinh(p / m)), 13);
  });
});

describe('hyperbolicTurningPoint', () => {
  test('the paper’s start under F = 2, integrated with RK4, turns where the closed form says; a start along the force never turns', () => {
    expect(hyperbolicTurningPoint.compute({ q0: -10, p0: -10, m, F: 2 })).toBeCloseTo(turningPoint(-10, -10, 2), 6);
    expect(hyperbolicTurningPoint.compute({ q0: -10, p0: 10, m, F: 2 })).toBeNaN();
  });
});

describe('startMomentumToTurnAt', () => {
  test('released with it, a particle integrated with RK4 turns at q = −20', () => {
    const p0 = startMomentumToTurnAt.compute({ q0: -10, qTurn: -20, m, F: 0.8 });
    expect(p0).toBeLessThan(0);
    expect(turningPoint(-10, p0, 0.8)).toBeCloseTo(-20, 6);
    expect(startMomentumToTurnAt.compute({ q0: -10, qTurn: -5, m, F: 0.8 })).toBeNaN();
  });
});
