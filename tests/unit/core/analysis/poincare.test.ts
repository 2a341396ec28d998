/**
 * Surfaces of section of Hénon–Heiles (Hénon & Heiles 1964, Astron. J. 69, 73),
 * checked against conservation laws and the geometry the paper describes:
 * invariant curves at E = 1/12, an area-filling sea at E = 1/6.
 */
import { describe, expect, it } from 'vitest';
import { harmonicOscillator, henonHeiles } from '../../../../core/analysis/henon-heiles.ts';
import { allowed, launchState, section } from '../../../../core/analysis/poincare.ts';

/** Largest jump of the radius between neighbours in angle around the points' centroid, over the mean radius. */
function radialJump(u: number[], pu: number[]): number {
  const cu = u.reduce((a, b) => a + b) / u.length;
  const cp = pu.reduce((a, b) => a + b) / pu.length;
  const polar = u.map((x, i) => [Math.atan2(pu[i] - cp, x - cu), Math.hypot(pu[i] - cp, x - cu)]).sort((a, b) => a[0] - b[0]);
  const mean = polar.reduce((a, p) => a + p[1], 0) / polar.length;
  let jump = 0;
  for (let i = 0; i < polar.length; i++) jump = Math.max(jump, Math.abs(polar[(i + 1) % polar.length][1] - polar[i][1]));
  return jump / mean;
}

/** Share of the allowed region's cells (n × n over its box) that the points visit. */
function coverage(u: number[], pu: number[], E: number, n = 16): number {
  const a = 1.2 * Math.sqrt(2 * E);
  const seen = new Set<number>();
  u.forEach((x, i) => seen.add(Math.floor(((x + a) / (2 * a)) * n) * n + Math.floor(((pu[i] + a) / (2 * a)) * n)));
  let inside = 0;
  for (let i = 0; i < n; i++)
    for (let j = 0; j < n; j++) if (allowed(henonHeiles, E, -a + ((i + 0.5) * 2 * a) / n, -a + ((j + 0.5) * 2 * a) / n)) inside++;
  return seen.size / inside;
}

describe('launchState: p_y from the energy', () => {
  it('puts the launch point on the energy surface and on the plane, and refuses points outside the allowed region', () => {
    const s = launchState(henonHeiles, 1 / 8, 0.2, -0.1)!;
    expect(s[1]).toBe(0);
    expect(s[3]).toBeGreaterThan(0);
    expect(henonHeiles.energy(s)).toBeCloseTo(1 / 8, 14);
    // On y = 0 the allowed region is x² + px² < 2E: a circle of radius 0.5 at E = 1/8.
    expect(launchState(henonHeiles, 1 / 8, 0.4, 0.31)).toBeNull();
    expect(launchState(henonHeiles, 1 / 8, 0.4, 0.29)).not.toBeNull();
    expect(launchState(henonHeiles, 1 / 8, Number.NaN, 0)).toBeNull();
  });

  it('solves for p_x on Hénon and Heiles\'s own plane x = 0, where V(0, y) = y²/2 − y³/3', () => {
    const s = launchState(henonHeiles, 1 / 12, 0.3, 0.1, 'x')!;
    expect(s[0]).toBe(0);
    expect(s[2]).toBeCloseTo(Math.sqrt(2 / 12 - 0.01 - 0.09 + (2 * 0.027) / 3), 14);
  });
});

describe('section: crossings of y = 0 with p_y > 0, located by Hénon\'s trick', () => {
  const E = 1 / 8;
  const run = section(henonHeiles, launchState(henonHeiles, E, 0.1, 0.05)!, { count: 300, dt: 0.02 });

  it('lands on the plane to rounding, with p_y > 0', () => {
    expect(run.u.length).toBe(300);
    for (let i = 0; i < run.u.length; i++) {
      expect(Math.abs(run.states[4 * i + 1])).toBeLessThan(1e-10);
      expect(run.states[4 * i + 3]).toBeGreaterThan(0);
    }
  });

  it('conserves the energy on every crossing to the RK 3/8 step\'s accuracy (error ∝ dt⁴: halving dt shrinks it ~16×)', () => {
    const worst = (r: typeof run) => Math.max(...r.u.map((_, i) => Math.abs(henonHeiles.energy(r.states.slice(4 * i, 4 * i + 4)) - E)));
    const coarse = worst(section(henonHeiles, launchState(henonHeiles, E, 0.1, 0.05)!, { count: 100, dt: 0.08 }));
    const fine = worst(section(henonHeiles, launchState(henonHeiles, E, 0.1, 0.05)!, { count: 100, dt: 0.04 }));
    expect(worst(run)).toBeLessThan(1e-6);
    // Fourth order for the whole path, the located crossing included: a linear interpolation would stall at O(dt²).
    expect(coarse / fine).toBeGreaterThan(8);
  });

  it('finds the harmonic oscillator\'s crossings where the closed form puts them: y = A sin t crosses upward once per 2π, at x = B cos(t)', () => {
    // x = B cos t, y = A sin t (launched on y = 0 with p_y = A): every upward crossing is at t = 2πk, x = B, p_x = 0.
    const B = 0.3;
    const r = section(harmonicOscillator, [B, 0, 0, 0.4], { count: 20, dt: 0.05 });
    expect(r.u.length).toBe(20);
    for (let i = 0; i < r.u.length; i++) {
      expect(r.u[i]).toBeCloseTo(B, 6);
      expect(r.pu[i]).toBeCloseTo(0, 6);
    }
    expect(r.time).toBeCloseTo(20 * 2 * Math.PI, 0);
  });
});

describe('order at E = 1/12, chaos at E = 1/6 (Hénon & Heiles 1964, Figs. 2 and 5)', () => {
  it('a regular orbit at E = 1/12 lies on a smooth closed curve; a chaotic one at E = 1/6 fills area', () => {
    const regular = section(henonHeiles, launchState(henonHeiles, 1 / 12, 0.1, 0)!, { count: 600 });
    const chaotic = section(henonHeiles, launchState(henonHeiles, 1 / 6, 0.1, 0.1)!, { count: 600 });
    // Smooth curve: neighbours in angle have nearly equal radii; scattered points do not.
    expect(radialJump(regular.u, regular.pu)).toBeLessThan(0.05);
    expect(radialJump(chaotic.u, chaotic.pu)).toBeGreaterThan(0.5);
    // Area: a curve visits a thin ring of cells, the sea most of the allowed region.
    expect(coverage(regular.u, regular.pu, 1 / 12)).toBeLessThan(0.3);
    expect(coverage(chaotic.u, chaotic.pu, 1 / 6)).toBeGreaterThan(0.5);
  });
});
