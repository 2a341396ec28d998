/**
 * The Kepler truths against independent values: the period against a plain
 * RK4 integration of the relative motion r̈ = −(k/μ)r/r³ (the time the line
 * between the stars takes to turn once), and against the circular orbit's
 * T = 2πr^{3/2}√(μ/k); the length of A against μke with e from the energy
 * and L (Landau & Lifshitz §15, e = √(1 + 2EL²/μk²)); the strength at which
 * the paper's Hamiltonian itself reads E = 0.
 */
import { describe, expect, test } from 'vitest';
import { KEPLER_TRUTHS } from '../../../../../../widgets/chapter/exercise/truths/kepler.ts';

const PAPER = { x1: -3, y1: -3, x2: 3, y2: 3, px1: 2, py1: -3, px2: -2, py2: 3 };
const MU = 0.25;

/** The time for the relative position, from r with velocity v = p/μ, to turn once about the focus, by classical RK4 (step h). */
function turnTime(r: [number, number], v: [number, number], k: number, h = 1e-4): number {
  let [x, y, vx, vy, t, turned] = [...r, ...v, 0, 0];
  const accel = (x: number, y: number) => {
    const c = -k / MU / Math.hypot(x, y) ** 3;
    return [c * x, c * y];
  };
  for (;;) {
    const [a1x, a1y] = accel(x, y);
    const [a2x, a2y] = accel(x + (h / 2) * vx, y + (h / 2) * vy);
    const [a3x, a3y] = accel(x + (h / 2) * (vx + (h / 2) * a1x), y + (h / 2) * (vy + (h / 2) * a1y));
    const [a4x, a4y] = accel(x + h * (vx + (h / 2) * a2x), y + h * (vy + (h / 2) * a2y));
    const nx = x + h * vx + (h * h / 6) * (a1x + a2x + a3x);
    const ny = y + h * vy + (h * h / 6) * (a1y + a2y + a3y);
    vx += (h / 6) * (a1x + 2 * a2x + 2 * a3x + a4x);
    vy += (h / 6) * (a1y + 2 * a2y + 2 * a3y + a4y);
    const step = Math.atan2(x * ny - y * nx, x * nx + y * ny);
    if (turned + step >= 2 * Math.PI) return t + (h * (2 * Math.PI - turned)) / step;
    [x, y, t, turned] = [nx, ny, t + h, turned + step];
  }
}

describe('keplerPeriod', () => {
  test.each([500, 400])('for the paper’s start at k = %i it equals the time an independent RK4 integration takes to turn once', (k) => {
    const T = KEPLER_TRUTHS.keplerPeriod.compute({ ...PAPER, k });
    // r = r1 − r2 = (−6, −6), p = (2, −3), v = p/μ.
    expect(Math.abs(T - turnTime([-6, -6], [2 / MU, -3 / MU], k))).toBeLessThan(1e-6);
  });
  test('on a circular orbit it is 2πr^{3/2}√(μ/k)', () => {
    const k = 500, r = 6 * Math.SQRT2, p = Math.sqrt((MU * k) / r) / Math.SQRT2;
    const T = KEPLER_TRUTHS.keplerPeriod.compute({ ...PAPER, px1: p, py1: -p, px2: -p, py2: p, k });
    expect(T).toBeCloseTo(2 * Math.PI * r ** 1.5 * Math.sqrt(MU / k), 12);
  });
  test('an unbound start has no period', () => {
    expect(KEPLER_TRUTHS.keplerPeriod.compute({ ...PAPER, k: 200 })).toBeNaN();
  });
});

test('lenzLength is μke, with e = √(1 + 2EL²/μk²) from the energy and angular momentum', () => {
  const k = 500, r = 6 * Math.SQRT2, E = 13 / (2 * MU) - k / r, L = 30;
  const e = Math.sqrt(1 + (2 * E * L * L) / (MU * k * k));
  expect(KEPLER_TRUTHS.lenzLength.compute({ ...PAPER, k })).toBeCloseTo(MU * k * e, 10);
});

test('unboundStrength is the k at which the paper’s H = Σp² − k/r is zero', () => {
  const k = KEPLER_TRUTHS.unboundStrength.compute(PAPER);
  const H = 2 ** 2 + 3 ** 2 + 2 ** 2 + 3 ** 2 - k / (6 * Math.SQRT2);
  expect(Math.abs(H)).toBeLessThan(1e-12);
  expect(k).toBeGreaterThan(200);
});
