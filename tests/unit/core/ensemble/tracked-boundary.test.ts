/**
 * The tracked boundary (core/ensemble/tracked-boundary.ts) under steppers
 * written here from flows known in closed form:
 * - the harmonic oscillator's exact flow, a rigid rotation of the phase
 *   plane, which carries a circle onto a circle (so nothing is refined) and
 *   keeps its area;
 * - the exact flow of H = ρ²/2 + ρ⁴/4 (ρ² = q² + p²), a twist: each circle
 *   about the origin turns at its own rate 1 + ρ², so a disc off the origin
 *   is sheared into a spiral filament, while its area stays (Liouville: the
 *   flow of any H keeps area);
 * - the damped oscillator q̇ = p, ṗ = −q − γp, whose field has divergence
 *   −γ, so areas shrink as e^{−γt} (Liouville's formula for det of the flow's
 *   Jacobian);
 * - maps that fail (a NaN) or tear the plane, for the flags.
 */
import { describe, expect, test } from 'vitest';
import { discArea, discBoundary } from '../../../../core/ensemble/boundary-curve.ts';
import { MIN_PARAMETER_GAP, TrackedBoundary } from '../../../../core/ensemble/tracked-boundary.ts';
import type { Stepper } from '../../../../core/types.ts';

/** A stepper of one degree of freedom from a map of one step, applied state by state. */
function mapStepper(step: (q: number, p: number, t: number) => [number, number]): Stepper {
  return {
    dim: 2,
    advance(x, count, _params, t0, k0, dt, steps) {
      for (let m = 0; m < count; m++) {
        let [q, p] = [x[2 * m], x[2 * m + 1]];
        for (let k = 0; k < steps; k++) {
          [q, p] = step(q, p, t0 + (k0 + k) * dt);
          if (!Number.isFinite(q + p)) {
            [x[2 * m], x[2 * m + 1]] = [q, p];
            return k;
          }
        }
        [x[2 * m], x[2 * m + 1]] = [q, p];
      }
      return steps;
    },
  };
}

/** The exact flow over dt of H = ρ²/2 + ρ⁴/4: a clockwise turn by (1 + ρ²)·dt, ρ kept. */
const twist = (dt: number) =>
  mapStepper((q, p) => {
    const angle = -(1 + q * q + p * p) * dt;
    const [c, s] = [Math.cos(angle), Math.sin(angle)];
    return [q * c - p * s, q * s + p * c];
  });

/** The exact flow over dt of H = (p² + ω²q²)/2. */
const oscillator = (omega: number, dt: number) => {
  const [c, s] = [Math.cos(omega * dt), Math.sin(omega * dt)];
  return mapStepper((q, p) => [q * c + (p / omega) * s, -q * omega * s + p * c]);
};

/** The exact flow over dt of q̇ = p, ṗ = −q − γp, underdamped (γ < 2): with β = γ/2, ω = √(1 − β²). */
const dampedOscillator = (gamma: number, dt: number) => {
  const beta = gamma / 2;
  const omega = Math.sqrt(1 - beta * beta);
  const [c, s, decay] = [Math.cos(omega * dt), Math.sin(omega * dt), Math.exp(-beta * dt)];
  return mapStepper((q, p) => [decay * (q * c + ((p + beta * q) / omega) * s), decay * (p * c - ((q + beta * p) / omega) * s)]);
};

const none = new Float64Array(0);

/** The turn at each vertex and the length of each side of the closed polygon, measured afresh here. */
function sidesAndTurns(q: Float64Array, p: Float64Array) {
  const n = q.length;
  const sides: number[] = [];
  const turns: number[] = [];
  for (let i = 0; i < n; i++) {
    const [prev, next] = [(i + n - 1) % n, (i + 1) % n];
    const [aq, ap, bq, bp] = [q[i] - q[prev], p[i] - p[prev], q[next] - q[i], p[next] - p[i]];
    sides.push(Math.hypot(bq, bp));
    turns.push(Math.abs(Math.atan2(aq * bp - ap * bq, aq * bq + ap * bp)));
  }
  return { sides, turns };
}

describe('TrackedBoundary under a rotation (the harmonic oscillator’s exact flow)', () => {
  test('the circle stays a circle, so nothing is refined; its vertices sit where the rotation puts them; its area is πr² within the polygon’s error', () => {
    const dt = 0.1;
    const curve = discBoundary([1, 0.5], 0.3);
    const b = new TrackedBoundary({ stepper: oscillator(1, dt), params: none, curve, dim: 2, dt, maxSegment: 0.05 });
    expect(b.count).toBe(256);
    for (let frame = 0; frame < 20; frame++) b.advance(25);
    expect(b.t).toBeCloseTo(50, 12);
    expect(b.count).toBe(256);
    expect([b.saturated, b.unresolved, b.failed]).toEqual([false, false, false]);
    const truth = discArea(0.3);
    expect(Math.abs(b.area() - truth)).toBeLessThanOrEqual(b.areaError());
    // The polygon's own error: the inscribed 256-gon's, (n/2)r² sin(2π/n) short of πr².
    expect(b.area()).toBeCloseTo(128 * 0.09 * Math.sin((2 * Math.PI) / 256), 12);
    const [q, p] = [b.q(), b.p()];
    const at = new Float64Array(2);
    const s = b.parameters();
    const [c, sn] = [Math.cos(b.t), Math.sin(b.t)];
    for (let i = 0; i < b.count; i++) {
      curve.point(s[i], at);
      expect(q[i]).toBeCloseTo(at[0] * c + at[1] * sn, 12);
      expect(p[i]).toBeCloseTo(-at[0] * sn + at[1] * c, 12);
    }
  });
});

describe('TrackedBoundary under a twist (the flow of H = ρ²/2 + ρ⁴/4)', () => {
  const dt = 0.05;
  const curve = discBoundary([1.5, 0], 0.5);
  const stepper = twist(dt);
  const b = new TrackedBoundary({ stepper, params: none, curve, dim: 2, dt, maxSegment: 0.02, maxTurn: 0.2 });
  for (let frame = 0; frame < 20; frame++) b.advance(10);

  test('the disc is drawn into a filament: the boundary has grown many vertices, and every side and turn is within the limits', () => {
    expect(b.count).toBeGreaterThan(1000);
    expect([b.saturated, b.unresolved, b.failed]).toEqual([false, false, false]);
    const { sides, turns } = sidesAndTurns(b.q(), b.p());
    expect(Math.max(...sides)).toBeLessThanOrEqual(0.02);
    expect(Math.max(...turns)).toBeLessThanOrEqual(0.2);
  });

  test('its area is still πr², within the polygon’s error; the signed estimate of that error accounts for nearly all of it', () => {
    const truth = discArea(0.5);
    const error = b.area() - truth;
    expect(Math.abs(error)).toBeLessThanOrEqual(b.areaError());
    expect(b.areaError()).toBeLessThan(3e-3 * truth);
    // The filament's two sides bend opposite ways and their chord errors cancel, which the bound cannot know.
    expect(Math.abs(error + b.areaShortfall())).toBeLessThan(0.1 * Math.abs(error));
  });

  test('every vertex is the exact flow of its point on the initial curve: the parameters are in order and each state matches its own', () => {
    const s = b.parameters();
    const x = b.states();
    const at = new Float64Array(2);
    expect(s[0]).toBe(0);
    let [disorder, miss] = [0, 0];
    for (let i = 0; i < b.count; i++) {
      if (i > 0 && !(s[i] > s[i - 1])) disorder++;
      curve.point(s[i], at);
      const angle = -(1 + at[0] ** 2 + at[1] ** 2) * b.t;
      const [q, p] = [at[0] * Math.cos(angle) - at[1] * Math.sin(angle), at[0] * Math.sin(angle) + at[1] * Math.cos(angle)];
      miss = Math.max(miss, Math.hypot(x[2 * i] - q, x[2 * i + 1] - p));
    }
    expect(disorder).toBe(0);
    expect(miss).toBeLessThan(1e-11);
    expect(s[b.count - 1]).toBeLessThan(1);
  });

  test('a vertex added late is bit for bit its point advanced alone from t = 0, and so is one tracked from the start', () => {
    const s = b.parameters();
    const x = b.states();
    const late = [...s.keys()].filter((i) => !Number.isInteger(s[i] * 256));
    expect(late.length).toBeGreaterThan(0);
    for (const i of [0, late[0], late[Math.floor(late.length / 2)], late[late.length - 1]]) {
      const alone = new Float64Array(2);
      curve.point(s[i], alone);
      expect(stepper.advance(alone, 1, none, 0, 0, dt, b.steps)).toBe(b.steps);
      expect([...alone]).toEqual([x[2 * i], x[2 * i + 1]]);
    }
  });

  test('too few vertices allowed: the boundary stops at maxVertices and says it is saturated', () => {
    const small = new TrackedBoundary({ stepper, params: none, curve, dim: 2, dt, maxSegment: 0.05, maxTurn: 0.2, maxVertices: 400 });
    for (let frame = 0; frame < 20 && !small.saturated; frame++) small.advance(10);
    expect(small.saturated).toBe(true);
    expect(small.count).toBe(400);
    expect(small.failed).toBe(false);
    const s = small.parameters();
    for (let i = 1; i < small.count; i++) expect(s[i]).toBeGreaterThan(s[i - 1]);
  });
});

describe('TrackedBoundary under a damped oscillator', () => {
  test('the area shrinks as πr² e^{−γt} (div f = −γ), within the polygon’s error', () => {
    const [gamma, dt] = [0.3, 0.05];
    const b = new TrackedBoundary({ stepper: dampedOscillator(gamma, dt), params: none, curve: discBoundary([1, 0], 0.4), dim: 2, dt, maxSegment: 0.05 });
    for (let frame = 0; frame < 20; frame++) {
      b.advance(10);
      const truth = discArea(0.4) * Math.exp(-gamma * b.t);
      expect(Math.abs(b.area() - truth)).toBeLessThanOrEqual(b.areaError() + 1e-13 * truth);
      expect(b.areaError()).toBeLessThan(2e-4 * truth);
    }
    expect(b.t).toBeCloseTo(10, 12);
  });
});

describe('TrackedBoundary flags', () => {
  test('a step that leaves a NaN fails the boundary, which keeps its last good state and moves no further', () => {
    const dt = 0.1;
    const rotate = oscillator(1, dt);
    // The rotation, but from step 5 on every state becomes NaN.
    const failing: Stepper = {
      dim: 2,
      advance(x, count, params, t0, k0, step, steps) {
        const good = Math.max(0, Math.min(steps, 5 - k0));
        rotate.advance(x, count, params, t0, k0, step, good);
        if (good === steps) return steps;
        x[0] = NaN;
        return good;
      },
    };
    const b = new TrackedBoundary({ stepper: failing, params: none, curve: discBoundary([0, 0], 1), dim: 2, dt, maxSegment: 0.1 });
    b.advance(3);
    expect(b.failed).toBe(false);
    const before = b.states().slice();
    b.advance(4);
    expect(b.failed).toBe(true);
    expect(b.steps).toBe(3);
    expect(b.t).toBeCloseTo(0.3, 15);
    expect(b.states()).toEqual(before);
    expect(b.states().every(Number.isFinite)).toBe(true);
    b.advance(1);
    expect(b.steps).toBe(3);
  });

  test('a new vertex that fails on its way from t = 0 fails the boundary, which keeps the vertices it had', () => {
    const dt = 0.05;
    const turn = twist(dt);
    // The twist, except that a run of more than 5 steps from step 0 — a vertex added after step 5 — ends in NaN.
    const failing: Stepper = {
      dim: 2,
      advance(x, count, params, t0, k0, step, steps) {
        if (k0 > 0 || steps <= 5) return turn.advance(x, count, params, t0, k0, step, steps);
        turn.advance(x, count, params, t0, k0, step, 5);
        x[0] = NaN;
        return 5;
      },
    };
    const b = new TrackedBoundary({ stepper: failing, params: none, curve: discBoundary([1.5, 0], 0.5), dim: 2, dt, maxSegment: 0.05 });
    let before = b.count;
    for (let frame = 0; frame < 40 && !b.failed; frame++) {
      before = b.count;
      b.advance(5);
    }
    expect(b.failed).toBe(true);
    expect(b.count).toBe(before);
    expect(b.states().every(Number.isFinite)).toBe(true);
    const steps = b.steps;
    b.advance(5);
    expect(b.steps).toBe(steps);
  });

  test('a map that tears the plane apart leaves sides no halving can shorten: the boundary is unresolved there', () => {
    // Each step moves the upper half plane (p > 0) right by 1: the boundary of a disc about the origin tears at p = 0.
    const tear = mapStepper((q, p) => [p > 0 ? q + 1 : q, p]);
    const b = new TrackedBoundary({ stepper: tear, params: none, curve: discBoundary([0, 0], 0.5), dim: 2, dt: 1, maxSegment: 0.1 });
    expect(b.unresolved).toBe(false);
    b.advance(1);
    expect(b.unresolved).toBe(true);
    expect(b.failed).toBe(false);
    expect(b.saturated).toBe(false);
    // About each tear, the gaps in s were halved down to MIN_PARAMETER_GAP and no further.
    const s = b.parameters();
    let smallest = 1;
    for (let i = 0; i < b.count; i++) smallest = Math.min(smallest, (i + 1 < b.count ? s[i + 1] : 1) - s[i]);
    expect(smallest).toBeLessThanOrEqual(MIN_PARAMETER_GAP);
    expect(smallest).toBeGreaterThanOrEqual(MIN_PARAMETER_GAP / 2);
  });

  test('two degrees of freedom: q() and p() are the first coordinate and the first momentum', () => {
    // Two uncoupled rotations, of frequencies 1 and 2, in (q0, p0) and (q1, p1).
    const [dt, c1, s1, c2, s2] = [0.1, Math.cos(0.1), Math.sin(0.1), Math.cos(0.2), Math.sin(0.2)];
    const two: Stepper = {
      dim: 4,
      advance(x, count, _params, _t0, _k0, _dt, steps) {
        for (let m = 0; m < count; m++) {
          const o = 4 * m;
          for (let k = 0; k < steps; k++) {
            const [q0, q1, p0, p1] = [x[o], x[o + 1], x[o + 2], x[o + 3]];
            [x[o], x[o + 2]] = [q0 * c1 + p0 * s1, -q0 * s1 + p0 * c1];
            [x[o + 1], x[o + 3]] = [q1 * c2 + (p1 / 2) * s2, -q1 * 2 * s2 + p1 * c2];
          }
        }
        return steps;
      },
    };
    const b = new TrackedBoundary({ stepper: two, params: none, curve: discBoundary([1, 0.3, 0, 0.2], 0.25), dim: 4, dt, maxSegment: 0.1 });
    b.advance(7);
    const x = b.states();
    expect(x.length).toBe(4 * b.count);
    expect([...b.q()]).toEqual(Array.from({ length: b.count }, (_, i) => x[4 * i]));
    expect([...b.p()]).toEqual(Array.from({ length: b.count }, (_, i) => x[4 * i + 2]));
    expect(Math.abs(b.area() - discArea(0.25))).toBeLessThanOrEqual(b.areaError());
  });

  test('options that cannot work are refused', () => {
    const stepper = oscillator(1, 0.1);
    const base = { stepper, params: none, curve: discBoundary([0, 0], 1), dim: 2, dt: 0.1, maxSegment: 0.1 };
    expect(() => new TrackedBoundary({ ...base, dim: 4 })).toThrow(/dim/);
    expect(() => new TrackedBoundary({ ...base, maxSegment: 0 })).toThrow(/maxSegment/);
    expect(() => new TrackedBoundary({ ...base, maxVertices: 100 })).toThrow(/maxVertices/);
    expect(() => new TrackedBoundary({ ...base, maxTurn: 4 })).toThrow(/maxTurn/);
    expect(() => new TrackedBoundary(base).advance(1.5)).toThrow(/steps/);
  });
});
