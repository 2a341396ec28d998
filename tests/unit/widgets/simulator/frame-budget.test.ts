import { describe, expect, it } from 'vitest';
import { carryOver, chunkSteps, DEFAULT_BUDGET, FIRST_CHUNK, integrateFrame, owedSteps, updateCost } from '../../../../widgets/simulator/frame-budget.ts';

/** A model that costs `msPerStep` of a fake clock per step, optionally failing at step `failAt`. */
function fakeModel(msPerStep: number, failAt = Infinity) {
  let now = 0;
  let steps = 0;
  return {
    clock: () => now,
    run: (n: number) => {
      const taken = Math.max(0, Math.min(n, failAt - steps));
      steps += taken;
      now += taken * msPerStep;
      return taken;
    },
    get steps() {
      return steps;
    },
  };
}

describe('simulator/frame-budget', () => {
  it('owedSteps(carry, elapsed, speed, dt) is speed · elapsed / dt: the default model runs 2000 steps per second', () => {
    expect(owedSteps(0, 1000 / 60, 1, 5e-4) * 60).toBeCloseTo(2000, 9);
    expect(owedSteps(0, 50, 1, 5e-4)).toBeCloseTo(100, 9);
    expect(owedSteps(0.5, 1000 / 60, 50, 5e-4)).toBeCloseTo(1667.17, 2); // 100 000 steps/s
  });

  it('owedSteps(…) counts at most maxElapsedMs of real time: no burst after a stall or a hidden tab', () => {
    expect(owedSteps(0, 5000, 1, 5e-4)).toBeCloseTo(DEFAULT_BUDGET.maxElapsedMs * 2, 9);
    expect(owedSteps(0, -3, 1, 5e-4)).toBe(0);
  });

  it('chunkSteps(cost, left, leftMs) aims at chunkMs of work, at least one step, never more than owed', () => {
    expect(chunkSteps(NaN, 1000, 6)).toBe(FIRST_CHUNK);
    expect(chunkSteps(0.001, 5000, 6)).toBe(1000); // 1 ms at 1 µs per step
    expect(chunkSteps(0.001, 300, 6)).toBe(300);
    expect(chunkSteps(0.001, 5000, 0.25)).toBe(250); // the time left
    expect(chunkSteps(10, 5000, 6)).toBe(1); // one step is more than a chunk: still progress
    expect(chunkSteps(0.001, 0.7, 6)).toBe(0); // less than one whole step owed
  });

  it('updateCost(cost, ms, steps) averages measurements and survives a clock that reads 0', () => {
    expect(updateCost(NaN, 2, 1000)).toBeCloseTo(0.002, 9);
    expect(updateCost(0.002, 4, 1000)).toBeCloseTo(0.7 * 0.002 + 0.3 * 0.004, 9);
    expect(updateCost(NaN, 0, 100)).toBeGreaterThan(0);
    expect(updateCost(0.5, 1, 0)).toBe(0.5);
  });

  it('carryOver(owed, done, outOfBudget) keeps the fraction only when the budget ran out', () => {
    expect(carryOver(33.4, 33, false)).toBeCloseTo(0.4, 9);
    expect(carryOver(1000.25, 300, true)).toBeCloseTo(0.25, 9);
    expect(carryOver(10, 12, false)).toBe(0);
  });

  it('integrateFrame(…) does all the owed steps of a fast model in few clock reads', () => {
    const model = fakeModel(0.0001); // 100 ns per step
    let cost = NaN;
    for (let frame = 0; frame < 5; frame++) {
      const work = integrateFrame(model.run, 1667, cost, model.clock);
      cost = work.costMs;
      expect(work.steps).toBe(1667);
      expect(work.outOfBudget).toBe(false);
    }
    expect(cost).toBeGreaterThanOrEqual(0.0001);
    expect(cost).toBeLessThan(0.0002); // the clock floor of the tiny first chunk has averaged out
  });

  it('integrateFrame(…) stops a slow model at the budget: it falls behind instead of freezing', () => {
    const model = fakeModel(0.5); // 0.5 ms per step: 12 steps fit in 6 ms
    let cost = NaN;
    let carry = 0;
    for (let frame = 0; frame < 20; frame++) {
      const owed = owedSteps(carry, 1000 / 60, 1, 5e-4);
      const start = model.clock();
      const work = integrateFrame(model.run, owed, cost, model.clock);
      cost = work.costMs;
      carry = carryOver(owed, work.steps, work.outOfBudget);
      expect(model.clock() - start).toBeLessThanOrEqual(DEFAULT_BUDGET.frameMs + DEFAULT_BUDGET.chunkMs + 0.5 + (frame === 0 ? FIRST_CHUNK * 0.5 : 0));
      if (frame > 0) {
        expect(work.outOfBudget).toBe(true);
        expect(carry).toBeLessThan(1); // the backlog is dropped, so it cannot snowball
      }
    }
  });

  it('integrateFrame(…) stops at a blow-up with the steps actually taken', () => {
    const model = fakeModel(0.0001, 500);
    const work = integrateFrame(model.run, 2000, NaN, model.clock);
    expect(work.steps).toBe(500);
    expect(model.steps).toBe(500);
  });

  it('integrateFrame(…) times one step before committing to a chunk: a 160 ms step costs its first frame one step, not sixteen', () => {
    // A JS H of 5 ms per call under the 5-point stencil: 32 calls per RK 3/8 step of one degree of freedom.
    const model = fakeModel(160);
    const start = model.clock();
    const work = integrateFrame(model.run, 1667, NaN, model.clock);
    expect(work.steps).toBe(1);
    expect(model.clock() - start).toBe(160);
    expect(work.costMs).toBe(160);
    // And the next frame, knowing the cost, still takes one step only.
    const next = integrateFrame(model.run, 1667, work.costMs, model.clock);
    expect(next.steps).toBe(1);
  });
});
