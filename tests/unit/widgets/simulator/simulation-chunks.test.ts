/**
 * The simulator's worker protocol, run in one thread: the worker's ChunkRunner
 * integrates in slices, the page's ChunkQueue takes their chunks, and
 * consumeChunks appends them to the page's Simulation. The record so made must
 * be the record the Simulation makes by itself, bit for bit (both run the same
 * generated stepper from the same state; the independent check is the core's
 * own Simulation.run, whose RK 3/8 is tested against closed forms in
 * integrator.test.ts); stale generations must never reach it.
 */
import { beforeAll, describe, expect, it } from 'vitest';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { Simulation, type DerivedSeries } from '../../../../core/simulation.ts';
import type { Model } from '../../../../core/types.ts';
import { ChunkQueue, LOOKAHEAD_BYTES, lookaheadTarget, nextSample, samplesBetween, type Chunk, type StartRequest } from '../../../../widgets/simulator/chunk-protocol.ts';
import { ChunkRunner } from '../../../../widgets/simulator/chunk-runner.ts';
import { DEFAULT_BUDGET } from '../../../../widgets/simulator/frame-budget.ts';
import { hamiltonianTravels, modelFromPortable, portableModel } from '../../../../widgets/simulator/portable-model.ts';
import { consumeChunks } from '../../../../widgets/simulator/worker-integrator.ts';

/** The playground's driven oscillator: time-dependent, with parameters. */
const DRIVEN = 'p^2/2 + omega^2*(1 + u*cos(gamma*t))*q^2/2 - f*q*cos(kappa*t + beta)';
const DRIVEN_PARAMS = { u: 0.3, gamma: 21.7, beta: 0.2, kappa: 8, omega: 10, f: 20 };

/** A clock that moves by `tick` ms at each read, so slices and budgets end after a known number of reads. */
function fakeClock(tick: number) {
  let now = 0;
  return () => (now += tick);
}

function startOf(sim: Simulation, gen: number): StartRequest {
  const model = portableModel(sim.model)!;
  return {
    type: 'start',
    gen,
    model,
    params: Float64Array.from(sim.model.params),
    state: Float64Array.from(sim.state),
    steps: sim.steps,
    t0: sim.t0,
    dt: sim.dt,
    every: sim.every,
    energy: hamiltonianTravels(sim.model) && sim.derived[0]?.evaluate === sim.model.hamiltonian,
  };
}

/** Every chunk the runner makes until it reaches `target`. */
function chunksTo(runner: ChunkRunner, gen: number, target: number): Chunk[] {
  runner.advance(gen, target);
  const chunks: Chunk[] = [];
  for (let chunk = runner.slice(); chunk; chunk = runner.slice()) chunks.push(chunk);
  return chunks;
}

/** The record's rows as numbers, so that toEqual compares them exactly (NaN and -0 included, via Object.is). */
const rowsOf = (sim: Simulation) => Array.from(sim.record.table().data);

async function driven(): Promise<Model> {
  return canonicalEquations({ dof: 1, hamiltonian: DRIVEN, params: DRIVEN_PARAMS });
}

// The first compile loads mathjs, which takes seconds on a busy machine.
beforeAll(() => driven(), 60_000);

describe('simulator/chunk-protocol: sample arithmetic', () => {
  it('samplesBetween(from, end, every) counts the multiples of every in (from, end]', () => {
    expect(samplesBetween(0, 20, 20)).toBe(1);
    expect(samplesBetween(0, 19, 20)).toBe(0);
    expect(samplesBetween(19, 41, 20)).toBe(2);
    expect(samplesBetween(5, 5, 1)).toBe(0);
    expect(samplesBetween(5, 8, 1)).toBe(3);
    expect(nextSample(0, 20)).toBe(20);
    expect(nextSample(20, 20)).toBe(40);
    expect(nextSample(7, 1)).toBe(8);
  });

  it('lookaheadTarget keeps a quarter second ahead, bounded by bytes, and at least one sample', () => {
    expect(lookaheadTarget(100, 2000, 32, 1)).toBe(100 + 500);
    // A 100 000-trajectory sample of 2.4 MB: three samples fit the byte bound.
    const rowBytes = 8 * 300_001;
    expect(lookaheadTarget(0, 2000, rowBytes, 20)).toBe(Math.floor(LOOKAHEAD_BYTES / rowBytes) * 20);
    expect(lookaheadTarget(0, 1, 8 * 1e7, 20)).toBe(20);
  });
});

describe('simulator/chunk-protocol: the queue', () => {
  const chunk = (gen: number, from: number, end: number, every = 1, width = 3): Chunk => ({
    type: 'chunk',
    gen,
    from,
    end,
    rows: new Float64Array(samplesBetween(from, end, every) * width).map((_, i) => from + i),
    width,
    state: new Float64Array(2),
    ms: 0,
  });

  it('drops chunks of another generation, out of order, or with the wrong number of rows', () => {
    const q = new ChunkQueue(1);
    q.reset(2, 10);
    expect(q.accept(chunk(1, 10, 15))).toBe(false);
    expect(q.accept(chunk(3, 10, 15))).toBe(false);
    expect(q.accept(chunk(2, 11, 15))).toBe(false);
    expect(q.accept({ ...chunk(2, 10, 15), rows: new Float64Array(3) })).toBe(false);
    expect(q.buffered).toBe(0);
    expect(q.accept(chunk(2, 10, 15))).toBe(true);
    expect(q.accept(chunk(2, 10, 15))).toBe(false);
    expect(q.accept(chunk(2, 15, 17))).toBe(true);
    expect(q.buffered).toBe(7);
  });

  it('after a reset, nothing of the old generation is handed out, even what was already queued', () => {
    const q = new ChunkQueue(1);
    q.reset(1, 0);
    q.accept(chunk(1, 0, 5));
    q.reset(2, 0);
    expect(q.peek()).toBe(Infinity);
    expect(q.accept(chunk(1, 5, 9))).toBe(false);
    expect(q.accept(chunk(2, 0, 2))).toBe(true);
    expect([q.take(2).step, q.take(2).step, q.peek()]).toEqual([1, 2, Infinity]);
  });

  it('hands out each sample, then a chunk end that is not a sample, in step order', () => {
    const q = new ChunkQueue(4);
    q.reset(1, 3);
    q.accept(chunk(1, 3, 10, 4));
    const steps = [];
    while (q.peek() < Infinity) steps.push(q.take(2));
    expect(steps.map((p) => [p.step, !!p.row])).toEqual([
      [4, true],
      [8, true],
      [10, false],
    ]);
    expect(q.position).toBe(10);
  });

  it('a blow-up ends the generation: it is met on the step after the chunk, and nothing follows', () => {
    const q = new ChunkQueue(1);
    q.reset(1, 0);
    q.accept({ ...chunk(1, 0, 3), error: { t: 0.4, component: 'q', value: Infinity } });
    expect(q.ended).toBe(true);
    expect(q.accept(chunk(1, 3, 5))).toBe(false);
    for (let i = 0; i < 3; i++) q.take(2);
    expect(q.peek()).toBe(4);
    const point = q.take(2);
    expect(point.error?.value).toBe(Infinity);
    expect(point.step).toBe(3);
  });
});

describe('simulator/portable-model', () => {
  it('an expression model travels as source and comes back computing the same numbers', async () => {
    const model = await driven();
    const source = portableModel(model);
    expect(source).not.toBeNull();
    expect(source!.hamiltonian).toBeDefined();
    const copy = modelFromPortable(source!, Float64Array.from(model.params));
    const a = Float64Array.of(2, 0.5);
    const b = Float64Array.from(a);
    model.stepper.advance(a, 1, model.params, 0, 0, 1e-3, 1000);
    copy.stepper.advance(b, 1, copy.params, 0, 0, 1e-3, 1000);
    expect(Array.from(b)).toEqual(Array.from(a));
    expect(copy.hamiltonian!(0.3, b, 0)).toBe(model.hamiltonian!(0.3, a, 0));
  });

  it('a splitting method’s generated stepper travels too; the midpoint rule and the adaptive method, closures of the page, do not', async () => {
    const H = 'p^2/2 + omega^2*q^2/2 + cos(t)*q';
    for (const name of ['verlet', 'yoshida4'] as const) {
      const model = await canonicalEquations({ dof: 1, hamiltonian: H, params: { omega: 3 }, method: { name } });
      const copy = modelFromPortable(portableModel(model)!, Float64Array.from(model.params));
      const a = Float64Array.of(1, 0.2);
      const b = Float64Array.from(a);
      model.stepper.advance(a, 1, model.params, 0, 0, 1e-3, 5000);
      copy.stepper.advance(b, 1, copy.params, 0, 0, 1e-3, 5000);
      expect(Array.from(b)).toEqual(Array.from(a));
    }
    const midpoint = await canonicalEquations({ dof: 1, hamiltonian: H, params: { omega: 3 }, method: { name: 'midpoint' } });
    expect(portableModel(midpoint)).toBeNull();
    const adaptive = await canonicalEquations({ dof: 1, hamiltonian: H, params: { omega: 3 }, method: { name: 'adaptive', rtol: 1e-9, atol: 1e-12 } });
    expect(portableModel(adaptive)).toBeNull();
  });

  it('an opaque JS function, a vector field, or code that is not a generated stepper does not travel', async () => {
    const opaque = await canonicalEquations({ dof: 1, hamiltonian: (t: number, x: Float64Array) => { let s = 0; for (const v of x) s += v * v; return s / 2; } });
    expect(opaque.route).toBe('js-stencil');
    expect(portableModel(opaque)).toBeNull();
    const field = await canonicalEquations({ dof: 1, vectorField: (t, x, d) => { d[0] = x[1]; d[1] = -x[0]; } });
    expect(portableModel(field)).toBeNull();
    const model = await driven();
    const forged = { ...portableModel(model)!, stepper: 'function advance() { fetch("https://example.com") }' };
    expect(() => modelFromPortable(forged, new Float64Array(6))).toThrow(/generated stepper/);
  });
});

describe('simulator: chunks from the runner make the record the page would make', () => {
  /** Runs `steps` through runner → queue → consumeChunks in frames of `owed` steps; returns the page's Simulation. */
  function viaChunks(model: Model, options: ConstructorParameters<typeof Simulation>[1], steps: number, owed: number, limits = { sliceMs: 1, subMs: 0.3, bytes: 2000, stateValues: 64 }) {
    const page = new Simulation(model, options);
    const runner = new ChunkRunner(fakeClock(0.1), limits);
    const queue = new ChunkQueue(page.every);
    runner.start(startOf(page, 1));
    queue.reset(1, page.steps);
    for (const chunk of chunksTo(runner, 1, steps)) expect(queue.accept(chunk)).toBe(true);
    while (page.steps < steps && !page.error) {
      const work = consumeChunks(queue, page, Math.min(owed, steps - page.steps), fakeClock(0.001), DEFAULT_BUDGET);
      if (work.steps === 0) break;
    }
    return page;
  }

  it('one trajectory, a sample every step: the same rows, state and t, bit for bit', async () => {
    const model = await driven();
    const direct = new Simulation(model, { initial: [2, 0], dt: 5e-4, every: 1, capacity: 5000 });
    direct.run(3001);
    const page = viaChunks(model, { initial: [2, 0], dt: 5e-4, every: 1, capacity: 5000 }, 3001, 37.3);
    expect(page.steps).toBe(3001);
    expect(page.t).toBe(direct.t);
    expect(Array.from(page.state)).toEqual(Array.from(direct.state));
    expect(rowsOf(page)).toEqual(rowsOf(direct));
  });

  it('a batch with every = 20 and a derived series of the cell’s: the same record, the series computed on the page', async () => {
    const model = await driven();
    const initial = Array.from({ length: 7 }, (_, i) => [1 + i / 10, -i / 20]).flat();
    const action: DerivedSeries = { name: 'I', evaluate: (t, x, o) => (x[o] * x[o] + x[o + 1] * x[o + 1]) / (1 + t) };
    const options = { initial, dt: 1e-3, every: 20, derived: [action], capacity: 100 };
    const direct = new Simulation(model, options);
    direct.run(2345);
    const page = viaChunks(model, options, 2345, 33.3);
    expect(page.record.columns).toEqual(direct.record.columns);
    expect(page.record.dropped).toBe(direct.record.dropped);
    expect(page.steps).toBe(2345);
    expect(Array.from(page.state)).toEqual(Array.from(direct.state));
    expect(rowsOf(page)).toEqual(rowsOf(direct));
  });

  it('a batch whose state is too large to send between samples advances a sample at a time, to the same record', async () => {
    const model = await driven();
    const initial = Array.from({ length: 50 }, (_, i) => [2 - i / 50, i / 100]).flat();
    const options = { initial, dt: 5e-4, every: 20, capacity: 50 };
    const direct = new Simulation(model, options);
    direct.run(2000);
    const page = new Simulation(model, options);
    const runner = new ChunkRunner(fakeClock(0.1), { sliceMs: 1, subMs: 0.3, bytes: 1e6, stateValues: 99 });
    const queue = new ChunkQueue(page.every);
    runner.start(startOf(page, 1));
    queue.reset(1, 0);
    const chunks = chunksTo(runner, 1, 2000);
    expect(chunks.some((c) => c.end % 20 !== 0)).toBe(true);
    expect(chunks.every((c) => c.state === undefined)).toBe(true);
    for (const chunk of chunks) queue.accept(chunk);
    const seen = new Set<number>();
    // Frames of 27 steps, as a driver carrying the remainder would ask.
    for (let frame = 0; frame < 1000 && page.steps < 2000; frame++) {
      consumeChunks(queue, page, 27, fakeClock(0.001), DEFAULT_BUDGET);
      seen.add(page.steps % 20);
    }
    expect([...seen]).toEqual([0]);
    expect(Array.from(page.state)).toEqual(Array.from(direct.state));
    expect(rowsOf(page)).toEqual(rowsOf(direct));
  });

  it('a blow-up stops the page at the same step, with the same message and state', async () => {
    // q̈ = 6q⁵ from q = 1.2 reaches infinity in finite time (about 0.2 time units).
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 - q^6' });
    const direct = new Simulation(model, { initial: [1.2, 0], dt: 1e-3, every: 3 });
    direct.run(10_000);
    expect(direct.error).not.toBeNull();
    const page = viaChunks(model, { initial: [1.2, 0], dt: 1e-3, every: 3 }, 10_000, 50);
    expect(page.error?.message).toBe(direct.error!.message);
    expect(page.steps).toBe(direct.steps);
    expect(Array.from(page.state)).toEqual(Array.from(direct.state));
    expect(rowsOf(page)).toEqual(rowsOf(direct));
  });

  it('a restart mid-flight: chunks of the old generation that arrive late are dropped, and the record is a fresh run’s', async () => {
    const model = await driven();
    const options = { initial: [2, 0], dt: 5e-4, every: 2, capacity: 10_000 };
    const page = new Simulation(model, options);
    const runner = new ChunkRunner(fakeClock(0.1), { sliceMs: 1, subMs: 0.3, bytes: 4000, stateValues: 64 });
    const queue = new ChunkQueue(page.every);
    runner.start(startOf(page, 1));
    queue.reset(1, 0);
    const old = chunksTo(runner, 1, 1000);
    for (const chunk of old.slice(0, 3)) queue.accept(chunk);
    consumeChunks(queue, page, 200, fakeClock(0.001), DEFAULT_BUDGET);
    expect(page.steps).toBeGreaterThan(0);
    // Restart: the page's Simulation starts over, then a new generation.
    page.restart();
    queue.reset(2, 0);
    runner.start(startOf(page, 2));
    const fresh = chunksTo(runner, 2, 1000);
    // The old generation's chunks still in the post arrive first, then the new ones.
    expect(old.slice(3).map((c) => queue.accept(c)).some(Boolean)).toBe(false);
    for (const chunk of fresh) expect(queue.accept(chunk)).toBe(true);
    for (let frame = 0; frame < 1000 && page.steps < 1000; frame++) consumeChunks(queue, page, 64, fakeClock(0.001), DEFAULT_BUDGET);
    const direct = new Simulation(model, options);
    direct.run(1000);
    expect(rowsOf(page)).toEqual(rowsOf(direct));
  });

  it('the hand-over: the page integrates by itself while the worker starts, then goes on with its samples past its own step', async () => {
    const model = await driven();
    const options = { initial: [2, 0], dt: 5e-4, every: 3, capacity: 10_000 };
    const page = new Simulation(model, options);
    const runner = new ChunkRunner(fakeClock(0.1), { sliceMs: 1, subMs: 0.3, bytes: 2000, stateValues: 64 });
    const queue = new ChunkQueue(page.every);
    runner.start(startOf(page, 1));
    queue.reset(1, 0);
    page.run(400);
    // The worker has not yet passed the page: nothing to go on with.
    for (const chunk of chunksTo(runner, 1, 300)) queue.accept(chunk);
    expect(queue.skipTo(page.steps, 2)).toBe(false);
    page.run(101);
    for (const chunk of chunksTo(runner, 1, 3000)) queue.accept(chunk);
    expect(queue.skipTo(page.steps, 2)).toBe(true);
    expect(queue.position).toBe(501);
    for (let frame = 0; frame < 1000 && page.steps < 3000; frame++) consumeChunks(queue, page, 41, fakeClock(0.001), DEFAULT_BUDGET);
    const direct = new Simulation(model, options);
    direct.run(3000);
    expect(page.steps).toBe(3000);
    expect(Array.from(page.state)).toEqual(Array.from(direct.state));
    expect(rowsOf(page)).toEqual(rowsOf(direct));
  });

  it('consumption keeps to the frame budget, and says when it waits on the worker', async () => {
    const model = await driven();
    const page = new Simulation(model, { initial: [2, 0], every: 1, capacity: 100_000 });
    const runner = new ChunkRunner(fakeClock(0.1));
    const queue = new ChunkQueue(1);
    runner.start(startOf(page, 1));
    queue.reset(1, 0);
    // Before the first chunk: nothing to take, and it says it waits.
    const first = consumeChunks(queue, page, 30, fakeClock(0), DEFAULT_BUDGET);
    expect([first.steps, first.starved]).toEqual([0, true]);
    for (const chunk of chunksTo(runner, 1, 20_000)) queue.accept(chunk);
    // Each clock read costs 1 ms of the budget's 6: consumption stops early, out of budget.
    const slow = consumeChunks(queue, page, 20_000, fakeClock(1), DEFAULT_BUDGET);
    expect(slow.outOfBudget).toBe(true);
    expect(slow.steps).toBeGreaterThan(0);
    expect(slow.steps).toBeLessThan(20_000);
    const rest = consumeChunks(queue, page, 1e9, fakeClock(0), DEFAULT_BUDGET);
    expect(page.steps).toBe(20_000);
    expect(rest.starved).toBe(true);
  });
});
