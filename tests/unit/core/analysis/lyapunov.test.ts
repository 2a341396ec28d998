/**
 * The largest Lyapunov exponent by tangent-space integration (Benettin et
 * al. 1980), checked against truth: the exact Jacobian against the symbolic
 * one of the expression route; the integrable oscillator's exponent is 0
 * (its tangent vectors stay bounded); a regular Hénon–Heiles orbit's
 * estimate decays like ln t / t; a chaotic one's tends to a positive limit,
 * which an independent method (two nearby orbits, renormalised; Benettin,
 * Galgani & Strelcyn 1976) reproduces.
 */
import { describe, expect, it } from 'vitest';
import { compileModel } from '../../../../core/model/compile-model.ts';
import { harmonicOscillator, henonHeiles } from '../../../../core/analysis/henon-heiles.ts';
import { largestLyapunov } from '../../../../core/analysis/lyapunov.ts';
import { launchState } from '../../../../core/analysis/poincare.ts';
import { rk38 } from '../../../../core/integrators/rk38.ts';

describe('the Hénon–Heiles Jacobian', () => {
  it('equals the exact one the expression route derives symbolically (core/expression/jacobian.ts)', async () => {
    const compiled = await compileModel({ dof: 2, hamiltonian: '(p0^2 + p1^2)/2 + (q0^2 + q1^2)/2 + q0^2*q1 - q1^3/3', method: 'midpoint' });
    const symbolic = new Function(compiled.code!.jacobian!)()(new Float64Array(0)) as (t: number, x: Float64Array, J: Float64Array) => void;
    for (const s of [[0.3, -0.2, 0.1, 0.4], [-0.5, 0.7, -0.2, 0.05]]) {
      const a = new Float64Array(16);
      const b = new Float64Array(16);
      symbolic(0, Float64Array.from(s), a);
      henonHeiles.jacobian(s, b);
      b.forEach((v, i) => expect(v).toBeCloseTo(a[i], 14));
    }
  });
});

/** λ by the two-orbit method: a companion at distance d0, pulled back to d0 every `every` time units. */
function twoOrbitExponent(start: ArrayLike<number>, time: number, dt = 0.02, d0 = 1e-8, every = 1): number {
  const step = rk38(henonHeiles.field, 4);
  const none = new Float64Array(0);
  const a = Float64Array.from(start);
  const b = Float64Array.from(start);
  b[0] += d0;
  const n = Math.round(every / dt);
  let sum = 0;
  const blocks = Math.round(time / every);
  for (let k = 0; k < blocks; k++) {
    step.advance(a, 1, none, 0, k * n, dt, n);
    step.advance(b, 1, none, 0, k * n, dt, n);
    const d = Math.hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2], b[3] - a[3]);
    sum += Math.log(d / d0);
    for (let i = 0; i < 4; i++) b[i] = a[i] + ((b[i] - a[i]) * d0) / d;
  }
  return sum / (blocks * every);
}

describe('largestLyapunov', () => {
  it('is 0 for the harmonic oscillator: λ(t)·t stays bounded (the tangent flow is a rotation)', () => {
    const run = largestLyapunov(harmonicOscillator, [0.3, 0, 0, 0.2], { time: 4000 });
    const at = (t: number) => run.estimates[run.times.findIndex((s) => s >= t)];
    expect(Math.abs(at(500) * 500)).toBeLessThan(2);
    expect(Math.abs(at(4000) * 4000)).toBeLessThan(2);
    expect(Math.abs(run.exponent)).toBeLessThan(1e-3);
  });

  it('decays like ln t / t on a regular Hénon–Heiles orbit (E = 1/12, on an invariant curve)', () => {
    const run = largestLyapunov(henonHeiles, launchState(henonHeiles, 1 / 12, 0.1, 0)!, { time: 8000, dt: 0.05 });
    const at = (t: number) => run.estimates[run.times.findIndex((s) => s >= t)];
    // ‖δ‖ grows at most linearly (shear between neighbouring tori), so λ(t)·t / ln t stays O(1)…
    for (const t of [1000, 2000, 4000, 8000]) expect(at(t) * t / Math.log(t)).toBeLessThan(2.5);
    // …and λ falls by about ln 8000/8000 ÷ ln 1000/1000 ≈ 0.16 from t = 1000 to 8000, not towards a plateau.
    expect(at(8000) / at(1000)).toBeLessThan(0.35);
  });

  it('tends to a positive limit on a chaotic orbit at E = 1/6 and at E = 1/8, matching the two-orbit method', () => {
    for (const [E, y] of [[1 / 6, -0.1], [1 / 8, -0.1]]) {
      const start = launchState(henonHeiles, E, y, 0, 'x')!;
      const run = largestLyapunov(henonHeiles, start, { time: 6000, dt: 0.05 });
      const at = (t: number) => run.estimates[run.times.findIndex((s) => s >= t)];
      expect(run.energyError).toBeLessThan(1e-4);
      expect(run.exponent).toBeGreaterThan(0.03);
      // a plateau: no ln t / t decay between t = 3000 and 6000 (that would halve it)
      expect(at(6000) / at(3000)).toBeGreaterThan(0.75);
      // the independent estimate from two nearby orbits, over the same time: the same limit within 25 %
      const other = twoOrbitExponent(start, 6000, 0.05);
      expect(Math.abs(other - run.exponent) / run.exponent).toBeLessThan(0.25);
    }
  });
});
