/**
 * The core of a dataset run: the counter-based generator against Random123's
 * published answers, grids as numpy.linspace lays them, initial states on
 * an energy surface against the pendulum's closed form, listed output times
 * and derivatives against the harmonic oscillator's.
 */
import { describe, expect, it } from 'vitest';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { BatchRun, rowColumns } from '../../../../core/dataset/batch-run.ts';
import { gridPoint } from '../../../../core/dataset/grid.ts';
import { fillInitial, trajectoryCount, type InitialSet } from '../../../../core/dataset/initial-set.ts';
import { CounterRandom, philox4x32 } from '../../../../core/dataset/philox.ts';
import { everyKSteps, listedTimes } from '../../../../core/dataset/sample-times.ts';
import { BlowUpError, InputError } from '../../../../core/errors.ts';

const hex = (words: Uint32Array) => Array.from(words, (w) => w.toString(16).padStart(8, '0'));

describe('philox4x32', () => {
  // Known-answer vectors of Philox4x32-10 from Random123's kat_vectors (Salmon et al., SC '11).
  it.each([
    [[0, 0, 0, 0], [0, 0], ['6627e8d5', 'e169c58d', 'bc57ac4c', '9b00dbd8']],
    [[0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff], [0xffffffff, 0xffffffff], ['408f276d', '41c83b0e', 'a20bc7c6', '6d5451fd']],
    [[0x243f6a88, 0x85a308d3, 0x13198a2e, 0x03707344], [0xa4093822, 0x299f31d0], ['d16cfe09', '94fdcceb', '5001e420', '24126ea1']],
  ])('gives Random123\'s answer for counter %j, key %j', (counter, key, expected) => {
    const out = new Uint32Array(4);
    philox4x32(counter, key, out);
    expect(hex(out)).toEqual(expected);
  });

  it('gives uniform numbers in [0, 1) that depend on the address alone', () => {
    const a = new CounterRandom(42);
    const b = new CounterRandom(42);
    const draws = Array.from({ length: 20000 }, (_, j) => a.uniform(j, 0, 0, j % 3));
    expect(draws.every((u) => u >= 0 && u < 1)).toBe(true);
    // Mean 1/2 and variance 1/12 of the uniform law, within 5 standard errors.
    const mean = draws.reduce((s, u) => s + u, 0) / draws.length;
    expect(Math.abs(mean - 0.5)).toBeLessThan(5 * Math.sqrt(1 / 12 / draws.length));
    expect(b.uniform(777, 0, 0, 777 % 3)).toBe(draws[777]);
    expect(new CounterRandom(43).uniform(777, 0, 0, 777 % 3)).not.toBe(draws[777]);
  });
});

describe('initial sets', () => {
  const context = { dim: 2, t0: 0, names: ['q', 'p'] };

  it('lays a grid out in C order, with numpy.linspace\'s points', () => {
    const set: InitialSet = { kind: 'grid', axes: [{ lo: -1, hi: 1, n: 3 }, { lo: 0, hi: 0.3, n: 4 }] };
    expect(trajectoryCount(set)).toBe(12);
    const out = new Float64Array(24);
    fillInitial(set, 0, 12, out, context);
    // numpy.linspace(0, 0.3, 4) = [0, 0.09999999999999999, 0.19999999999999998, 0.3]: i·step + lo, the last exactly hi.
    const p = [0, 1 * (0.3 / 3), 2 * (0.3 / 3), 0.3];
    const expected = [-1, 0, 1].flatMap((q) => p.flatMap((v) => [q, v]));
    expect(Array.from(out)).toEqual(expected);
    const one = new Float64Array(2);
    gridPoint(set.axes, 7, one);
    expect(Array.from(one)).toEqual([0, p[3]]);
  });

  it('draws the same state for a trajectory however the set is cut', () => {
    const set: InitialSet = { kind: 'sample', count: 100, seed: 7, box: [{ lo: -3, hi: 3 }, { lo: 2, hi: 2 }] };
    const whole = new Float64Array(200);
    fillInitial(set, 0, 100, whole, context);
    const part = new Float64Array(20);
    fillInitial(set, 40, 10, part, context);
    expect(Array.from(part)).toEqual(Array.from(whole.subarray(80, 100)));
    for (let j = 0; j < 100; j++) {
      expect(whole[2 * j]).toBeGreaterThanOrEqual(-3);
      expect(whole[2 * j]).toBeLessThan(3);
      expect(whole[2 * j + 1]).toBe(2);
    }
  });

  it('puts every point on the pendulum\'s energy surface, p = ±√(2(E + cos q)), both signs drawn', async () => {
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 - cos(q)' });
    const E = 0.3;
    const set: InitialSet = { kind: 'sample', count: 400, seed: 1, box: [{ lo: -Math.PI, hi: Math.PI }, { lo: -3, hi: 3 }], energy: { value: E, component: 1 } };
    const out = new Float64Array(800);
    fillInitial(set, 0, 400, out, { ...context, hamiltonian: model.hamiltonian });
    let positive = 0;
    for (let j = 0; j < 400; j++) {
      const [q, p] = [out[2 * j], out[2 * j + 1]];
      // The closed form: |p| = √(2(E + cos q)), exact to the last bits of the bisection.
      expect(Math.abs(Math.abs(p) - Math.sqrt(2 * (E + Math.cos(q))))).toBeLessThan(1e-14);
      if (p > 0) positive++;
    }
    // Each sign with probability 1/2: 200 ± 5σ (σ = 10).
    expect(Math.abs(positive - 200)).toBeLessThan(50);
  });

  it('refuses an energy no point of the box reaches, saying the range it saw', async () => {
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 - cos(q)' });
    const set: InitialSet = { kind: 'sample', count: 3, seed: 1, box: [{ lo: -1, hi: 1 }, { lo: -3, hi: 3 }], energy: { value: -5, component: 1 } };
    expect(() => fillInitial(set, 0, 3, new Float64Array(6), { ...context, hamiltonian: model.hamiltonian })).toThrow(InputError);
    expect(() => fillInitial(set, 0, 3, new Float64Array(6), { ...context, hamiltonian: model.hamiltonian })).toThrow(/no point of the box reaches H = -5 with p in \[-3, 3\]/);
  });
});

describe('BatchRun', () => {
  it('samples at listed times between steps, each exact to RK 3/8\'s error (oscillator: q = cos t)', async () => {
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + q^2/2' });
    const times = [0, 0.1234567, 1, Math.PI, 7.77];
    const plan = listedTimes(0, 1e-3, times);
    const run = new BatchRun(model, plan, Float64Array.of(1, 0, 0, 2), 0, 1e-3);
    const out = new Float64Array(2 * times.length * run.width);
    run.produce(times.length, out, { base: 0, trajectoryStride: times.length * run.width, rowStride: run.width });
    times.forEach((t, r) => {
      const a = r * run.width;
      const b = (times.length + r) * run.width;
      expect(out[a]).toBe(t);
      // q = q0 cos t + p0 sin t, p = p0 cos t − q0 sin t; RK 3/8 at dt = 1e-3 errs by ~1e-13 over 8 time units.
      expect(Math.abs(out[a + 1] - Math.cos(t))).toBeLessThan(1e-11);
      expect(Math.abs(out[a + 2] + Math.sin(t))).toBeLessThan(1e-11);
      expect(Math.abs(out[b + 1] - 2 * Math.sin(t))).toBeLessThan(1e-11);
    });
  });

  it('writes dx/dt from the canonical equations at each sample: (p, −q) for the oscillator, exactly', async () => {
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + q^2/2' });
    expect(rowColumns(model, true)).toEqual(['t', 'q', 'p', 'H', 'dq/dt', 'dp/dt']);
    const plan = everyKSteps(0, 1e-3, 1000, 100);
    const run = new BatchRun(model, plan, Float64Array.of(0.3, -0.2), 0, 1e-3, { derivatives: true });
    const out = new Float64Array(plan.count * run.width);
    run.produce(plan.count, out, { base: 0, trajectoryStride: 0, rowStride: run.width });
    for (let r = 0; r < plan.count; r++) {
      const [, q, p, , dq, dp] = out.subarray(r * run.width, (r + 1) * run.width);
      expect(dq).toBe(p);
      expect(dp).toBe(-q);
    }
  });

  it('names the trajectory of a batch whose state blows up', async () => {
    // V = −q⁴ sends q to infinity in finite time from q = 2 (t ≈ 0.37), not from q = 0.
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 - q^4' });
    const run = new BatchRun(model, everyKSteps(0, 1e-3, 2000, 100), Float64Array.of(0, 0, 2, 0), 0, 1e-3, { first: 10 });
    const out = new Float64Array(2 * 21 * run.width);
    let caught: unknown;
    try {
      run.produce(21, out, { base: 0, trajectoryStride: 21 * run.width, rowStride: run.width });
    } catch (error) {
      caught = error;
    }
    expect(caught).toBeInstanceOf(BlowUpError);
    expect((caught as BlowUpError).trajectory).toBe(11);
    expect((caught as BlowUpError).message).toMatch(/ in [qp] of trajectory 11;/);
  });
});
