/**
 * The action measured from samples (core/analysis/action.ts) against
 * truth: the harmonic oscillator's exact orbit q = A cos ωt, p = −Aω sin ωt,
 * whose action is E/ω = A²ω/2 (Landau & Lifshitz §49) and whose polygon of
 * samples θ = ωh apart has exactly sin θ/θ of the ellipse's area; the
 * pendulum integrated here by a plain RK4 against the closed form
 * J = (8ω/π)[E(k) − k′²K(k)] and T = 4K/ω (Landau & Lifshitz §11, §50), with
 * the polygon's shortfall against the chord-segment estimate
 * (h²/24π)∮(p²V″ + V′²) dt, computed here from the samples.
 */
import { describe, expect, test } from 'vitest';
import { loopAction } from '../../../../core/analysis/action.ts';
import { pendulumAction, pendulumPeriod } from '../../../../core/analysis/pendulum.ts';

/** The harmonic oscillator's exact orbit with amplitude A and phase φ, sampled at the times t. */
function harmonic(A: number, omega: number, phase: number, t: ArrayLike<number>) {
  const q = Float64Array.from(t, (s) => A * Math.cos(omega * s + phase));
  const p = Float64Array.from(t, (s) => -A * omega * Math.sin(omega * s + phase));
  return { q, p, t };
}

const uniform = (h: number, steps: number) => Float64Array.from({ length: steps + 1 }, (_, i) => i * h);

/** The pendulum q′ = p, p′ = −ω² sin q by the classical fourth-order Runge–Kutta method, every step kept. */
function pendulumRK4(q0: number, p0: number, omega: number, dt: number, steps: number) {
  const w2 = omega * omega;
  const [q, p, t] = [new Float64Array(steps + 1), new Float64Array(steps + 1), uniform(dt, steps)];
  let [x, y] = [q0, p0];
  [q[0], p[0]] = [x, y];
  for (let i = 1; i <= steps; i++) {
    const [k1q, k1p] = [y, -w2 * Math.sin(x)];
    const [k2q, k2p] = [y + (dt / 2) * k1p, -w2 * Math.sin(x + (dt / 2) * k1q)];
    const [k3q, k3p] = [y + (dt / 2) * k2p, -w2 * Math.sin(x + (dt / 2) * k2q)];
    const [k4q, k4p] = [y + dt * k3p, -w2 * Math.sin(x + dt * k3q)];
    x += (dt / 6) * (k1q + 2 * k2q + 2 * k3q + k4q);
    y += (dt / 6) * (k1p + 2 * k2p + 2 * k3p + k4p);
    [q[i], p[i]] = [x, y];
  }
  return { q, p, t };
}

describe('loopAction(q, p, t) on the harmonic oscillator', () => {
  const [A, omega] = [1.3, 2.1];
  const T = (2 * Math.PI) / omega;
  const exact = (A * A * omega) / 2;

  test('gives E/ω = A²ω/2 with the polygon’s error, 1 − sin θ/θ for samples θ = ωh apart, from a turning point and from anywhere', () => {
    for (const phase of [0, 0.7, 2]) {
      // a step that does not divide the period, so that the returns fall between samples
      for (const m of [50.37, 2000.37]) {
        const h = T / m;
        const { q, p, t } = harmonic(A, omega, phase, uniform(h, Math.round(3 * m + 17)));
        const r = loopAction(q, p, t)!;
        expect(r.loops).toBe(3);
        const theta = omega * h;
        const polygon = exact * (Math.sin(theta) / theta);
        // the last chord is cut at an interpolated point: an O(h³) part of the O(h²) shortfall, 0.025/m of it observed
        expect(Math.abs(r.action - polygon) / (exact - polygon)).toBeLessThan(0.05 / m);
        // the crossing time by linear interpolation errs by O(h²) (observed up to 0.0024θ²)
        expect(Math.abs(r.period / T - 1)).toBeLessThan(theta ** 2 / 200);
      }
    }
  });

  test('its error shrinks fourfold when h halves, and is θ²/6 ≈ 1.6·10⁻⁶ at h = T/2000, below 10⁻⁶ only from h = T/4000', () => {
    const error = (m: number) => {
      const h = T / m;
      const { q, p, t } = harmonic(A, omega, 0.4, uniform(h, Math.round(2.6 * m)));
      return Math.abs(loopAction(q, p, t)!.action / exact - 1);
    };
    for (const m of [100, 400, 1000]) {
      const ratio = error(m) / error(2 * m);
      expect(ratio).toBeGreaterThan(3.5);
      expect(ratio).toBeLessThan(4.5);
    }
    const theta = (2 * Math.PI) / 2000;
    expect(error(2000) / (theta ** 2 / 6)).toBeCloseTo(1, 2);
    expect(error(2000)).toBeLessThan(2e-6);
    expect(error(4000)).toBeLessThan(1e-6);
  });

  test('takes non-uniform times: samples jittered by up to 40% of the step still give the exact polygon’s area (each chord short of the ellipse by (A²ω/2)(Δθ − sin Δθ))', () => {
    const m = 400;
    const h = T / m;
    const t = Float64Array.from({ length: 3 * m }, (_, i) => i * h + 0.4 * h * Math.sin(1.7 * i) * (i > 0 ? 1 : 0));
    const { q, p } = harmonic(A, omega, 0.3, t);
    const r = loopAction(q, p, t)!;
    expect(r.loops).toBe(2);
    // the samples up to the last return, and the exact area of the ellipse less the segments their chords cut off
    const last = t.findIndex((s) => s > r.period * 2 + 1e-12);
    let segments = 0;
    for (let i = 0; i + 1 < last; i++) {
      const d = omega * (t[i + 1] - t[i]);
      segments += ((A * A * omega) / 2) * (d - Math.sin(d));
    }
    const predicted = exact - segments / (2 * Math.PI * 2);
    expect(Math.abs(r.action - predicted) / (exact - predicted)).toBeLessThan(0.01);
    expect(Math.abs(r.period / T - 1)).toBeLessThan(1e-5);
  });

  test('takes the orbit run backwards, counterclockwise, to the same positive action', () => {
    const h = T / 500;
    const { q, p, t } = harmonic(A, omega, 1, uniform(h, 1300));
    const forward = loopAction(q, p, t)!;
    const backward = loopAction(q, p.map((x) => -x), t)!;
    expect(backward.action).toBeGreaterThan(0);
    expect(backward.action).toBeCloseTo(forward.action, 14);
    expect(backward.loops).toBe(forward.loops);
  });

  test('is null with less than one loop, for a state that never moves, and refuses samples that do not match', () => {
    const h = T / 500;
    for (const phase of [0, 1]) {
      const { q, p, t } = harmonic(A, omega, phase, uniform(h, 495));
      expect(loopAction(q, p, t)).toBeNull();
      const more = harmonic(A, omega, phase, uniform(h, 505));
      expect(loopAction(more.q, more.p, more.t)?.loops).toBe(1);
    }
    expect(loopAction([1, 1, 1], [0, 0, 0], [0, 1, 2])).toBeNull();
    expect(() => loopAction([1, 2, 3], [0, 0], [0, 1, 2])).toThrow(/one length/);
    expect(() => loopAction([1, 2, 3], [0, 0, 1], [0, 2, 1])).toThrow(/increase/);
  });
});

describe('loopAction(q, p, t) on the pendulum integrated by RK4', () => {
  const omega = 1;
  const k = 0.8;

  test('at k = 0.8 and dt = 10⁻³ gives J = (8ω/π)[E − k′²K] and T = 4K/ω to 10⁻⁶, from the turning point, the bottom and in between', () => {
    const qMax = 2 * Math.asin(k);
    const starts: [number, number][] = [[qMax, 0], [0, 2 * omega * k], [1, Math.sqrt(2 * omega * omega * (Math.cos(1) - Math.cos(qMax)))]];
    for (const [q0, p0] of starts) {
      const [J, T] = [pendulumAction(q0, p0, omega), pendulumPeriod(q0, p0, omega)];
      const dt = 1e-3;
      const { q, p, t } = pendulumRK4(q0, p0, omega, dt, Math.round((3.3 * T) / dt));
      const r = loopAction(q, p, t)!;
      expect(r.loops).toBe(3);
      expect(Math.abs(r.action / J - 1)).toBeLessThan(1e-6);
      expect(Math.abs(r.period / T - 1)).toBeLessThan(1e-6);
    }
  });

  test('falls short by the chords’ segments, (h²/24π)∮(ω²p² cos q + ω⁴ sin² q) dt, to 1% at dt = 0.01 and 0.005', () => {
    const qMax = 2 * Math.asin(k);
    const [J, T] = [pendulumAction(qMax, 0, omega), pendulumPeriod(qMax, 0, omega)];
    for (const dt of [0.01, 0.005]) {
      const { q, p, t } = pendulumRK4(qMax, 0, omega, dt, Math.round((2.5 * T) / dt));
      const r = loopAction(q, p, t)!;
      // q̇p̈ − ṗq̈ for q̇ = p, ṗ = −ω² sin q, by the trapezoid rule in time over one period of the samples
      const curvature = (i: number) => omega ** 2 * p[i] ** 2 * Math.cos(q[i]) + omega ** 4 * Math.sin(q[i]) ** 2;
      let integral = 0;
      for (let i = 0; i + 1 < Math.round(T / dt); i++) integral += ((curvature(i) + curvature(i + 1)) / 2) * dt;
      const shortfall = ((dt * dt) / (24 * Math.PI)) * integral;
      expect(Math.abs((J - r.action) / shortfall - 1)).toBeLessThan(0.01);
    }
  });

  test('is null for a rotation, from the bottom (q never comes back to its start) and from q = π/2 (where the section is p = p(0), which p crosses every turn, with q a turn further on each time)', () => {
    for (const [q0, p0] of [[0, 2.5], [Math.PI / 2, 2.1]]) {
      const { q, p, t } = pendulumRK4(q0, p0, omega, 0.01, 4000);
      expect(loopAction(q, p, t)).toBeNull();
    }
  });
});
