/**
 * What the order-and-chaos chapter's Kepler checks are built from
 * (widgets/chapter/analysis/kepler-run.ts, section-systems.ts), against truth: at
 * isotropy the paper's orbit returns with Kepler's third law (Landau &
 * Lifshitz, Mechanics §15) and its exponent stays inside the bound ln κ / T
 * of a tangent flow that only turns; the second isotropic factor, −1, gives
 * the paper's state L = 0 exactly (u = −x1 − x2 = 0 and p_u = 0); at 1.5 the
 * energy error falls with the tolerance and the exponent is positive.
 * A factor that is no number, or that unbinds the orbit, is refused with
 * its reason.
 */
import { describe, expect, it } from 'vitest';
import { keplerRun } from '../../../../../widgets/chapter/analysis/kepler-run.ts';
import { henonHeilesView, keplerSetting, keplerView, launchGrid } from '../../../../../widgets/chapter/poincare-section/section-systems.ts';
import { allowed, henonHeiles } from '../../../../../core/index.ts';

describe('keplerSetting', () => {
  it('reduces the paper’s factor to μ = 1.625 and refuses factors that are no number or unbind the orbit', () => {
    expect(keplerSetting(1.5).mu).toBe(1.625);
    expect(keplerSetting(1).mu).toBe(1);
    expect(() => keplerSetting(Number.NaN)).toThrow(TypeError);
    expect(() => keplerSetting('1.5' as unknown as number)).toThrow(/finite number/);
    // E = 4(c + 1)²/(c² + 1) + 18 − 500/√(9(c + 1)² + 36) > 0 at c = 10
    expect(() => keplerSetting(10)).toThrow(/unbound \(E = .* ≥ 0\)/);
  });
});

describe('the section views', () => {
  it('launch the Kepler section inside the unit disk and off the collision line σ = 0', () => {
    const view = keplerView(keplerSetting(1.5));
    const grid = launchGrid(view, 24, 0.35);
    expect(grid.length).toBeGreaterThan(20);
    for (const [u, pu] of grid) {
      expect(u * u + pu * pu).toBeLessThan(1);
      expect(u).not.toBe(0);
    }
    expect(view.allowed(0, 0.5)).toBe(false);
    expect(view.allowed(0.5, 0.9)).toBe(false);
    expect(view.rim(0.6)).toBeCloseTo(0.8, 14);
  });

  it('keep Hénon–Heiles as it was: the allowed region of core/analysis/poincare.ts, its rim V + p²/2 = E', () => {
    const view = henonHeilesView(1 / 8, 'y');
    for (const [u, pu] of [[0.2, -0.1], [0.4, 0.31], [0.4, 0.29]]) expect(view.allowed(u, pu)).toBe(allowed(henonHeiles, 1 / 8, u, pu, 'y'));
    expect(view.rim(0.3)).toBeCloseTo(Math.sqrt(2 * (1 / 8) - 0.09), 14);
    expect(launchGrid(view, 24, 0).every(([u, pu]) => view.allowed(u, pu))).toBe(true);
  });
});

describe('keplerRun', () => {
  it('at isotropy: Kepler’s third law within the tolerance change, λ inside ln κ / T', () => {
    const run = keplerRun(1, 200);
    expect(run.isotropic).toBe(true);
    expect(run.collision).toBe(false);
    // 2π√(m A³/k), m = 1/4, A = 500/(2|E|), E = 26 − 500/√72
    const E = 26 - 500 / Math.sqrt(72);
    expect(run.energy).toBeCloseTo(E, 12);
    expect(run.period.kepler).toBeCloseTo(2 * Math.PI * Math.sqrt((0.25 * (500 / (2 * -E)) ** 3) / 500), 12);
    const difference = Math.abs(run.period.measured - run.period.kepler);
    expect(difference / run.period.kepler).toBeLessThan(1e-8);
    expect(difference).toBeLessThanOrEqual(Math.abs(run.period.measured - run.period.coarse));
    expect(Math.abs(run.exponent.measured)).toBeLessThanOrEqual(run.exponent.bound);
    expect(run.energyError.measured).toBeLessThan(run.energyError.coarse);
  });

  it('at the other isotropic factor, −1, flags the paper’s orbit as a collision orbit', () => {
    const run = keplerRun(-1, 50);
    expect(run.isotropic).toBe(true);
    expect(run.angularMomentum).toBe(0);
    expect(run.collision).toBe(true);
  });

  it('at the paper’s 1.5: the energy error falls with the tolerance through the approaches, and λ is positive', () => {
    const run = keplerRun(1.5, 300);
    expect(run.isotropic).toBe(false);
    expect(run.energyError.approaches).toBeGreaterThan(5);
    expect(run.energyError.crossings).toBeGreaterThan(20);
    expect(run.energyError.measured).toBeLessThan(1e-8);
    expect(run.energyError.measured).toBeLessThan(run.energyError.coarse);
    expect(run.exponent.measured).toBeGreaterThan(0.1);
    // no period: the crossings do not recur at Kepler's interval
    expect(Math.abs(run.period.measured - run.period.kepler) / run.period.kepler).toBeGreaterThan(0.05);
  });

  it('refuses a time that is not positive', () => {
    expect(() => keplerRun(1.5, 0)).toThrow(/time/);
    expect(() => keplerRun(1.5, Number.NaN)).toThrow(/time/);
  });
});
