/**
 * Liouville's theorem on the pendulum H = p²/2 − cos q, a disc of initial
 * conditions about (q, p) = (1.5, 0) of radius 0.5: inside the separatrix,
 * but spanning amplitudes from 1 to 2 rad whose periods differ by a quarter,
 * so the flow shears it into a filament.
 *
 * Truths: the exact flow keeps the disc's area π·0.25 (Liouville); a
 * symplectic splitting (Störmer–Verlet) is itself an area-preserving map,
 * so its boundary keeps that area at any dt, up to the polygon's error; RK
 * 3/8 is not symplectic, and its area error vanishes as dt → 0 (bounded
 * here by a run at dt/2); at a large step its stability function, of modulus
 * below 1 on the imaginary axis (1 − y⁶/72 + y⁸/576 squared, for every
 * four-stage fourth-order rule), shrinks every oscillation, and the area
 * with it. And a vertex added where the boundary stretched is the state its
 * initial point reaches when advanced alone, bit for bit.
 */
import { beforeAll, describe, expect, test } from 'vitest';
import { canonicalEquations } from '../../../../core/index.ts';
import { discArea, discBoundary } from '../../../../core/ensemble/boundary-curve.ts';
import { TrackedBoundary } from '../../../../core/ensemble/tracked-boundary.ts';
import type { Model } from '../../../../core/types.ts';

const PENDULUM = 'p^2/2 - cos(q)';
const curve = discBoundary([1.5, 0], 0.5);
const AREA = discArea(0.5);
const INITIAL = 256;

/** The boundary carried to t = 30 in frames of 20 steps, as a page's worker would. */
function tracked(model: Model, dt: number): TrackedBoundary {
  const b = new TrackedBoundary({ stepper: model.stepper, params: model.params, curve, dim: 2, dt, initialVertices: INITIAL, maxSegment: 0.02, maxTurn: 0.1 });
  const steps = Math.round(30 / dt);
  for (let done = 0; done < steps; done += 20) b.advance(Math.min(20, steps - done));
  expect(b.t).toBeCloseTo(30, 12);
  expect([b.saturated, b.unresolved, b.failed]).toEqual([false, false, false]);
  return b;
}

let rk38: Model;
let verlet: Model;
beforeAll(async () => {
  rk38 = await canonicalEquations({ dof: 1, hamiltonian: PENDULUM });
  verlet = await canonicalEquations({ dof: 1, hamiltonian: PENDULUM, method: { name: 'verlet' } });
});

describe('the pendulum’s disc by RK 3/8', () => {
  test('it is drawn into a filament, and keeps its area π·0.25 within the polygon’s error and the integrator’s, bounded by a run at dt/2', () => {
    const h = 0.05;
    const [coarse, fine] = [tracked(rk38, h), tracked(rk38, h / 2)];
    expect(fine.count).toBeGreaterThan(4 * INITIAL);
    // A_h = A + P_h + I_h, P the polygon's error (|P| ≤ areaError), I the integrator's. If halving dt at
    // least halves I (any convergent method in its asymptotic range; RK 3/8 divides it by 16), then
    // |I_{h/2}| ≤ |I_h − I_{h/2}| ≤ |A_h − A_{h/2}| + areaError_h + areaError_{h/2}.
    const integrator = Math.abs(coarse.area() - fine.area()) + coarse.areaError() + fine.areaError();
    expect(Math.abs(fine.area() - AREA)).toBeLessThanOrEqual(fine.areaError() + integrator);
    expect(fine.areaError() + integrator).toBeLessThan(1e-3 * AREA);
  });

  test('a vertex added late is bit for bit its initial point advanced alone from t = 0; one tracked from the start in frames is its point advanced in one call', () => {
    const dt = 0.05;
    const b = tracked(rk38, dt);
    const s = b.parameters();
    const x = b.states();
    const initial = [...s.keys()].filter((i) => Number.isInteger(s[i] * INITIAL));
    const added = [...s.keys()].filter((i) => !Number.isInteger(s[i] * INITIAL));
    expect(initial.length).toBe(INITIAL);
    expect(added.length).toBeGreaterThan(INITIAL);
    const chosen = [...initial.filter((_, j) => j % 50 === 0), ...added.filter((_, j) => j % 97 === 0), added[added.length - 1]];
    for (const i of chosen) {
      const alone = new Float64Array(2);
      curve.point(s[i], alone);
      expect(rk38.stepper.advance(alone, 1, rk38.params, 0, 0, dt, b.steps)).toBe(b.steps);
      expect([...alone]).toEqual([x[2 * i], x[2 * i + 1]]);
    }
  });

  test('at dt = 0.5 the area shrinks by far more than the polygon’s error: RK 3/8 damps every oscillation', () => {
    const b = tracked(rk38, 0.5);
    expect(AREA - b.area()).toBeGreaterThan(10 * b.areaError());
  });
});

describe('the pendulum’s disc by Störmer–Verlet', () => {
  test('the area is π·0.25 within the polygon’s error alone, at dt = 0.05 and at dt = 0.5 alike: the splitting is an area-preserving map', () => {
    for (const dt of [0.05, 0.5]) {
      const b = tracked(verlet, dt);
      expect(b.count).toBeGreaterThan(4 * INITIAL);
      expect(Math.abs(b.area() - AREA)).toBeLessThanOrEqual(b.areaError() + 1e-12);
      expect(b.areaError()).toBeLessThan(5e-4 * AREA);
    }
  });
});
