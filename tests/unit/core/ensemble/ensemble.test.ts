/**
 * The ensemble (core/ensemble/ensemble.ts) against truth: a Vogel spiral
 * fills the disc evenly, so the share of its points within a fraction f of
 * the radius is f² (the area's share) to within a point; under the
 * oscillator's exact rotation, written here, every cloud point and the
 * boundary keep their distance from the origin, and the area is πr²; a
 * point that blows up stops the ensemble; bad setups are refused in words.
 */
import { describe, expect, test } from 'vitest';
import { discCloud, Ensemble } from '../../../../core/ensemble/ensemble.ts';
import type { Stepper } from '../../../../core/types.ts';

/** The exact flow of H = (p² + q²)/2: a rotation of the plane by dt each step. */
const rotation: Stepper = {
  dim: 2,
  advance(x, count, _params, _t0, _k0, dt, steps) {
    const [c, s] = [Math.cos(steps * dt), Math.sin(steps * dt)];
    for (let i = 0; i < count; i++) {
      const [q, p] = [x[2 * i], x[2 * i + 1]];
      x[2 * i] = c * q + s * p;
      x[2 * i + 1] = -s * q + c * p;
    }
    return steps;
  },
};

describe('discCloud', () => {
  test('the points fill the ellipse evenly: the share within f of its size is f²', () => {
    const n = 20_000;
    const cloud = discCloud([1, -2], [0.5, 0.25], n);
    const scaled = (i: number) => Math.hypot((cloud[2 * i] - 1) / 0.5, (cloud[2 * i + 1] + 2) / 0.25);
    for (let i = 0; i < n; i++) expect(scaled(i)).toBeLessThanOrEqual(1);
    for (const f of [0.3, 0.5, 0.8]) {
      let inside = 0;
      for (let i = 0; i < n; i++) if (scaled(i) < f) inside++;
      expect(Math.abs(inside - f * f * n)).toBeLessThanOrEqual(1);
    }
  });
});

describe('Ensemble', () => {
  test('under a rotation every point keeps its radius, and the area is πr² within the polygon’s bound', () => {
    const e = new Ensemble(rotation, new Float64Array(0), { center: [1, 0], radius: 0.3, points: 500, dt: 0.1 });
    const radii = Array.from({ length: 500 }, (_, i) => Math.hypot(e.cloud[2 * i], e.cloud[2 * i + 1]));
    e.advance(37);
    const state = e.state();
    expect(state.t).toBeCloseTo(3.7, 12);
    for (let i = 0; i < 500; i++) expect(Math.hypot(state.cloud[2 * i], state.cloud[2 * i + 1])).toBeCloseTo(radii[i], 12);
    expect(state.initialArea).toBeCloseTo(Math.PI * 0.09, 15);
    expect(Math.abs(state.area - Math.PI * 0.09)).toBeLessThanOrEqual(state.areaError);
    expect(state.failed).toBe(false);
  });

  test('a point that leaves the finite numbers stops it where it failed', () => {
    const blowUp: Stepper = { dim: 2, advance: (x, count, _p, _t, k0, _dt, steps) => (k0 + steps > 5 ? (x.fill(NaN), Math.max(0, 5 - k0)) : steps) };
    const e = new Ensemble(blowUp, new Float64Array(0), { center: [0, 0], radius: 1, points: 10, dt: 1 });
    e.advance(3);
    e.advance(4);
    expect(e.state().failed).toBe(true);
    expect(e.state().k).toBe(5);
  });

  test('bad setups are refused in words', () => {
    const make = (setup: object) => () => new Ensemble(rotation, new Float64Array(0), { center: [0, 0], radius: 1, points: 10, dt: 0.1, ...setup });
    expect(make({ radius: -1 })).toThrow(/radius must be positive/);
    expect(make({ points: 0 })).toThrow(/points must be a whole number/);
    expect(make({ dt: 0 })).toThrow(/dt must be a positive number/);
    expect(make({ center: [0, NaN] })).toThrow(/center must be two finite numbers/);
    expect(() => new Ensemble({ dim: 4, advance: () => 0 }, new Float64Array(0), { center: [0, 0], radius: 1, points: 1, dt: 1 })).toThrow(/one degree of freedom/);
  });
});
