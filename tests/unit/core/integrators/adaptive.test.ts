/**
 * The adaptive method (Dormand–Prince 5(4) with dense output) against
 * closed forms. Error model: each accepted step's local error is held below
 * tol = atol + rtol·|x| (HNW, Solving ODEs I, §II.4), so after N steps the
 * global error is at most the sum of N local errors carried by the flow; the
 * harmonic oscillator's flow is a rotation and carries an error unchanged,
 * Kepler's shears it, growing a phase error linearly in time (HLW, Geometric
 * Numerical Integration, §I.2), which over one period we bound by a factor 3.
 * The dense output's own error is of the same order as the step's
 * (continuous extension of order 4, HNW §II.6).
 */
import { describe, expect, it } from 'vitest';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import type { AdaptiveStats } from '../../../../core/integrators/dormand-prince.ts';
import { methodChoice } from '../../../../core/integrators/methods.ts';
import type { Model } from '../../../../core/types.ts';

const ATOL = 1e-14;
const statsOf = (model: Model) => (model.stepper as unknown as { stats: AdaptiveStats }).stats;

async function oscillator(rtol: number) {
  const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + q^2/2', method: methodChoice('adaptive', rtol, ATOL) });
  // Samples every 0.01 over [0, 20]: most fall inside a step, so they come from the dense output.
  const x = Float64Array.from([1, 0]);
  let worst = 0;
  for (let k = 0; k < 2000; k++) {
    expect(model.stepper.advance(x, 1, model.params, 0, k, 0.01, 1)).toBe(1);
    const t = (k + 1) * 0.01;
    worst = Math.max(worst, Math.abs(x[0] - Math.cos(t)), Math.abs(x[1] + Math.sin(t)));
  }
  return { worst, stats: statsOf(model) };
}

const E = 0.5;
async function keplerPeriod(rtol: number) {
  const model = await canonicalEquations({
    dof: 2,
    hamiltonian: 'px^2/2 + py^2/2 - 1/sqrt(x^2 + y^2)',
    coordinates: ['x', 'y'],
    momenta: ['px', 'py'],
    method: methodChoice('adaptive', rtol, ATOL),
  });
  // From pericentre of the orbit a = 1, e = 0.5 (GM = 1), the body is back there after one period 2π (Kepler's third law).
  const start = [1 - E, 0, 0, Math.sqrt((1 + E) / (1 - E))];
  const x = Float64Array.from(start);
  expect(model.stepper.advance(x, 1, model.params, 0, 0, 2 * Math.PI, 1)).toBe(1);
  return { error: Math.hypot(x[0] - start[0], x[1] - start[1]), stats: statsOf(model) };
}

describe('adaptive method against closed forms', () => {
  for (const rtol of [1e-6, 1e-10]) {
    it(`follows q = cos t on [0, 20] within its tolerance at every sample, rtol = ${rtol}`, async () => {
      const { worst, stats } = await oscillator(rtol);
      expect(worst).toBeLessThan(stats.accepted * (ATOL + rtol * 1));
      expect(stats.accepted).toBeGreaterThan(0);
    });
    it(`returns to pericentre after one Kepler period within its tolerance, rtol = ${rtol}`, async () => {
      const { error, stats } = await keplerPeriod(rtol);
      expect(error).toBeLessThan(3 * stats.accepted * (ATOL + rtol * 1.5));
    });
  }

  it('its error is proportional to the tolerance: 1e4 times tighter gives 1e3–1e5 times smaller', async () => {
    const loose = await oscillator(1e-6);
    const tight = await oscillator(1e-10);
    expect(loose.worst / tight.worst).toBeGreaterThan(1e3);
    expect(loose.worst / tight.worst).toBeLessThan(1e5);
    const kLoose = await keplerPeriod(1e-6);
    const kTight = await keplerPeriod(1e-10);
    expect(kLoose.error / kTight.error).toBeGreaterThan(1e3);
    expect(kLoose.error / kTight.error).toBeLessThan(1e5);
  });

  it('gives the same numbers however the run is cut into calls, and whatever shares its batch', async () => {
    const make = () => canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 - cos(q)', method: methodChoice('adaptive', 1e-8, 1e-12) });
    const whole = await make();
    const a = Float64Array.from([2, 0]);
    whole.stepper.advance(a, 1, whole.params, 0, 0, 0.05, 400);
    // One sample per call, interleaved with another trajectory on the same stepper.
    const cut = await make();
    const b = Float64Array.from([2, 0]);
    const other = Float64Array.from([0.3, 0.1]);
    for (let k = 0; k < 400; k++) {
      cut.stepper.advance(b, 1, cut.params, 0, k, 0.05, 1);
      cut.stepper.advance(other, 1, cut.params, 0, k, 0.05, 1);
    }
    expect(Array.from(b)).toEqual(Array.from(a));
    // In a batch of two, advanced in uneven chunks.
    const batched = await make();
    const pair = Float64Array.from([0.3, 0.1, 2, 0]);
    let k = 0;
    for (const n of [1, 7, 92, 300]) {
      batched.stepper.advance(pair, 2, batched.params, 0, k, 0.05, n);
      k += n;
    }
    expect(Array.from(pair.subarray(2))).toEqual(Array.from(a));
    expect(Array.from(pair.subarray(0, 2))).toEqual(Array.from(other));
  });

  it('refuses tolerances that are no numbers or ask for more than doubles hold', () => {
    expect(() => methodChoice('adaptive', 1e-16)).toThrow(/more than double precision/);
    expect(() => methodChoice('adaptive', -1)).toThrow(/rtol must be a finite number ≥ 0/);
    expect(() => methodChoice('adaptive', undefined, Number.NaN)).toThrow(/atol/);
    expect(() => methodChoice('verlet', 1e-8)).toThrow(/tolerances of the adaptive method/);
    expect(methodChoice('adaptive')).toEqual({ name: 'adaptive', rtol: 1e-9, atol: 1e-12 });
  });
});
