import { describe, expect, it } from 'vitest';
import { Interrupted, InterruptGuard } from '../../../../cli/interrupt.ts';
import { nextStride, pacedRun } from '../../../../cli/output/paced-run.ts';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { BlowUpError } from '../../../../core/errors.ts';
import { Simulation } from '../../../../core/simulation.ts';

const oscillator = () => canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + q^2/2', params: {} });

/** A clock that moves `stepMs` each time it is read, so every stretch looks long and the run returns to the event loop often. */
const slowClock = (stepMs: number) => {
  let now = 0;
  return () => (now += stepMs);
};

/** Runs `steps` steps paced, collecting every row the flushes hand over. */
async function pacedRows(simulation: Simulation, steps: number, options: { clock?: () => number; signal?: AbortSignal } = {}) {
  const rows: number[] = [];
  let yields = 0;
  await pacedRun(simulation, steps, {
    ...options,
    flush: () => {
      for (const { data, from, to } of simulation.record.slices()) rows.push(...data.subarray(from * simulation.record.width, to * simulation.record.width));
      simulation.record.clear();
    },
    progress: () => yields++,
  });
  return { rows, yields };
}

describe('pacedRun(simulation, steps, options)', () => {
  it.each([1, 7, 1000])('hands over exactly the rows of one unbroken run, every = %i, through a record far smaller than the run', async (every) => {
    const model = await oscillator();
    const steps = 20_011;
    const paced = new Simulation(model, { initial: [1, 0], every, capacity: 17 });
    const { rows, yields } = await pacedRows(paced, steps, { clock: slowClock(25) });
    expect(yields).toBeGreaterThan(10);
    const whole = new Simulation(model, { initial: [1, 0], every });
    whole.run(steps);
    expect(paced.steps).toBe(steps);
    expect(rows).toEqual(Array.from(whole.record.table().data));
  });

  it('lets timers and signal listeners run during a long run, and stops with the abort reason', async () => {
    const model = await oscillator();
    const simulation = new Simulation(model, { initial: [1, 0], every: 1_000_000, capacity: 8 });
    const guard = new InterruptGuard();
    guard.hold();
    try {
      // Delivered as the process delivers a real SIGINT: to the listeners, from the event loop.
      setTimeout(() => process.emit('SIGINT'), 50);
      const run = pacedRows(simulation, 1e12, { signal: guard.signal });
      await expect(run).rejects.toBeInstanceOf(Interrupted);
      await expect(run).rejects.toMatchObject({ signal: 'SIGINT', status: 130 });
      // Stopped at the signal, 50 ms in, not at the end of the run: told by the steps done, not by a clock
      // (1e10 steps would be minutes of integration; a busy machine only does fewer).
      expect(simulation.steps).toBeGreaterThan(0);
      expect(simulation.steps).toBeLessThan(1e10);
    } finally {
      guard.release();
    }
  });

  it('throws the BlowUpError of a state that stops being finite', async () => {
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 - q^4', params: {} });
    const simulation = new Simulation(model, { initial: [1, 0], capacity: 64 });
    await expect(pacedRows(simulation, 10_000)).rejects.toBeInstanceOf(BlowUpError);
  });
});

describe('nextStride(stride, elapsedMs)', () => {
  it('aims each stretch at about 20 ms, growing at most fourfold and never below one step', () => {
    expect(nextStride(1000, 40)).toBe(500);
    expect(nextStride(1000, 10)).toBe(2000);
    expect(nextStride(1000, 0.001)).toBe(4000);
    expect(nextStride(1000, 0)).toBe(4000);
    expect(nextStride(1, 5000)).toBe(1);
  });
});

describe('InterruptGuard', () => {
  it('listens only while held, and aborts with the status a shell gives each signal', () => {
    const before = process.listenerCount('SIGTERM');
    const guard = new InterruptGuard();
    expect(process.listenerCount('SIGTERM')).toBe(before);
    guard.hold();
    guard.hold();
    expect(process.listenerCount('SIGTERM')).toBe(before + 1);
    process.emit('SIGTERM');
    expect(guard.signal.reason).toMatchObject({ signal: 'SIGTERM', status: 143 });
    guard.release();
    expect(process.listenerCount('SIGTERM')).toBe(before);
    expect(new Interrupted('SIGINT').status).toBe(130);
  });
});
