import { describe, expect, it } from 'vitest';
import { crossings, meanPeriod } from '../../../../core/analysis/crossings.ts';
import { floquet, floquetGrid } from '../../../../core/analysis/floquet.ts';
import { keplerOrbit } from '../../../../core/analysis/kepler.ts';
import { angleBetween, deflectionFrom, rutherfordAngle } from '../../../../core/analysis/scattering.ts';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { Simulation } from '../../../../core/simulation.ts';

describe('crossings(t, y, level, direction)', () => {
  it('finds the upward zeros of sin 2πt/3 one period apart', () => {
    const t = Float64Array.from({ length: 1001 }, (_, i) => i * 0.01);
    const y = t.map((s) => Math.sin((2 * Math.PI * s) / 3 + 0.4));
    const up = crossings(t, y);
    expect(meanPeriod(up)).toBeCloseTo(3, 4);
    expect(crossings(t, y, 0, 0).length).toBe(2 * up.length + (crossings(t, y, 0, -1).length - up.length));
  });
});

describe('floquet(model, T, steps)', () => {
  const parametric = () =>
    canonicalEquations({
      dof: 1,
      hamiltonian: 'p^2/2 + omega^2*(1 + u*cos(gamma*t))*q^2/2',
      params: { omega: 10, u: 0.3, gamma: 21.3 },
    });

  it('has trace 2cos(ωT) without the drive (u = 0), the closed form of the harmonic oscillator', async () => {
    const model = await parametric();
    model.params[1] = 0;
    const T = (2 * Math.PI) / 21.3;
    const f = floquet(model, T, 400);
    expect(f.trace).toBeCloseTo(2 * Math.cos(10 * T), 10);
    expect(f.stable).toBe(true);
  });

  it('grows at the rate s = √((uω/4)² − ε²) inside the first resonance |γ − 2ω| < uω/2 (Landau & Lifshitz §27)', async () => {
    const model = await parametric();
    const T = (2 * Math.PI) / 21.3;
    const f = floquet(model, T, 400);
    expect(f.stable).toBe(false);
    // γ = 2ω + ε with ε = 1.3, u = 0.3, ω = 10: s = √(0.75² − 0.65²) = 0.374, to first order in u.
    const s = Math.sqrt((0.3 * 10 / 4) ** 2 - (1.3 / 2) ** 2);
    expect(Math.abs(f.growth - s) / s).toBeLessThan(0.1);
  });

  it('floquetGrid(model, grid) finds the instability tongue between γ/ω = 2 ± u/2 to first order in u', async () => {
    const model = await parametric();
    const gammas = Float64Array.from({ length: 41 }, (_, i) => 18 + i * 0.1);
    const us = Float64Array.of(0.1, 0.2, 0.3);
    const chart = floquetGrid(model, {
      x: { param: 'gamma', values: gammas },
      y: { param: 'u', values: us },
      period: (p, names) => (2 * Math.PI) / p[names.indexOf('gamma')],
    });
    for (let j = 0; j < us.length; j++) {
      for (let i = 0; i < gammas.length; i++) {
        const distance = Math.abs(gammas[i] / 10 - 2) - us[j] / 2; // < 0 inside the theoretical tongue
        // Away from the boundary (where the O(u²) correction matters) the chart agrees with the formula.
        if (Math.abs(distance) > 0.02 + us[j] ** 2 / 4) expect(chart[j * gammas.length + i] > 0).toBe(distance < 0);
      }
    }
    expect(model.params[1]).toBe(0.3); // parameters restored
  });
});

describe('keplerOrbit(x)', () => {
  it('predicts the period the simulation shows, and its invariants stay put', async () => {
    const model = await canonicalEquations({ dof: 4, hamiltonian: 'p0^2 + p1^2 + p2^2 + p3^2 - 500/sqrt((q0-q2)^2 + (q1-q3)^2)' });
    const start = [-3, -3, 3, 3, 2, -3, -2, 3];
    const orbit = keplerOrbit(start);
    expect(orbit.energy).toBeCloseTo(model.hamiltonian!(0, Float64Array.from(start)), 12);
    expect(orbit.eccentricity).toBeLessThan(1);
    const sim = new Simulation(model, { initial: start, every: 1 });
    sim.run(Math.round((3 * orbit.period) / sim.dt));
    const after = keplerOrbit(sim.state);
    expect(after.angularMomentum).toBeCloseTo(orbit.angularMomentum, 8);
    expect(after.lenz[0]).toBeCloseTo(orbit.lenz[0], 5);
    expect(after.lenz[1]).toBeCloseTo(orbit.lenz[1], 5);
    // Period from the pericentre passages: minima of r, i.e. upward zeros of the radial velocity r·ṙ.
    const t = sim.record.column('t');
    const rv = t.map((_, i) => {
      const g = (c: string) => sim.record.get(i, sim.record.columnIndex(c));
      return (g('q0') - g('q2')) * (g('p0') - g('p2')) + (g('q1') - g('q3')) * (g('p1') - g('p3'));
    });
    expect(Math.abs(meanPeriod(crossings(t, rv)) - orbit.period) / orbit.period).toBeLessThan(1e-5);
  });
});

describe('scattering', () => {
  it('deflectionFrom(start) predicts where a simulated particle leaves, and approaches Rutherford far out', async () => {
    const model = await canonicalEquations({ dof: 2, hamiltonian: 'p0^2 + p1^2 + 30/sqrt(q0^2 + q1^2)' });
    const b = 1.5;
    const sim = new Simulation(model, { initial: [-20, b, 4, 0], every: 1000 });
    sim.run(400_000); // t = 200: r ≈ 1600, the remaining turn is below 1e-4
    const [, , px, py] = sim.state;
    const predicted = deflectionFrom(-20, b, 4, 0, 30, 0.5);
    expect(Math.abs(angleBetween(4, 0, Math.atan2(py, px)) - predicted)).toBeLessThan(2e-4);
    // Rutherford with the initial kinetic energy 16 differs by the start's potential energy and direction…
    const rutherford = rutherfordAngle(b, 16, 30);
    expect(Math.abs(predicted - rutherford)).toBeGreaterThan(1e-3);
    // …a difference that vanishes for a start far away.
    const far = deflectionFrom(-1e7, b, 4, 0, 30, 0.5);
    expect(far).toBeCloseTo(rutherford, 5);
  });
});
