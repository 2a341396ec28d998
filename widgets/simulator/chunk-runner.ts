/**
 * The worker's half of chunked integration (chunk-protocol.ts), apart from
 * the worker itself so that it can be tested in one thread: a Simulation of
 * the model rebuilt from its source (portable-model.ts), advanced in slices of bounded
 * time and bytes, each slice one chunk.
 */
import { type BlowUpError, type Model, Simulation } from '../../core/index.ts';
import type { Chunk, StartRequest } from './chunk-protocol.ts';
import { modelFromPortable, type PortableModel } from './portable-model.ts';

/** How long and how large a chunk may get. */
export interface SliceLimits {
  /** integration time per chunk, ms */
  sliceMs: number;
  /** integration time between clock reads, ms */
  subMs: number;
  /** bytes of samples per chunk */
  bytes: number;
  /** the most state values a chunk carries at its end between samples */
  stateValues: number;
}

/** Long enough that messages cost little, short enough that a restart is taken almost at once. */
export const SLICE_LIMITS: SliceLimits = { sliceMs: 12, subMs: 2, bytes: 4 * 2 ** 20, stateValues: 2 ** 14 };

export class ChunkRunner {
  gen = 0;
  target = 0;
  private sim: Simulation | null = null;
  private built: { source: PortableModel; model: Model } | null = null;
  /** running estimate of one step's cost, ms */
  private cost = NaN;

  constructor(
    private readonly clock: () => number,
    private readonly limits: SliceLimits = SLICE_LIMITS,
  ) {}

  /** Takes a new generation (throws when the model cannot be built or the state is not finite). */
  start(request: StartRequest): void {
    this.gen = request.gen;
    this.sim = null;
    const { model: source, params } = request;
    if (params.length !== source.paramNames.length) throw new Error('the parameters do not match the model');
    const same = this.built && this.built.source.stepper === source.stepper && this.built.source.hamiltonian === source.hamiltonian;
    if (!same) this.built = { source, model: modelFromPortable(source, new Float64Array(params.length)) };
    const model = this.built!.model;
    model.params.set(params);
    const width = 1 + request.state.length + (request.energy ? request.state.length / model.dim : 0);
    const capacity = Math.max(1, Math.floor(this.limits.bytes / (8 * width)));
    const sim = new Simulation(model, { initial: request.state, t0: request.t0, dt: request.dt, every: request.every, energy: request.energy, capacity });
    sim.steps = request.steps;
    sim.record.clear();
    this.sim = sim;
    this.target = request.steps;
    this.cost = NaN;
  }

  /** Raises the target of the current generation. */
  advance(gen: number, target: number): void {
    if (gen !== this.gen || !this.sim) return;
    this.target = Math.max(this.target, target);
  }

  /** True while there is work left for the current generation. */
  get busy(): boolean {
    const sim = this.sim;
    return !!sim && !sim.error && sim.steps < this.target;
  }

  /**
   * Integrates for about `sliceMs` (or to the target, a full chunk, or a
   * blow-up) and returns the chunk, or null when there was nothing to do.
   */
  slice(): Chunk | null {
    const s = this.sim;
    if (!s || !this.busy) return null;
    const from = s.steps;
    const begin = this.clock();
    let now = begin;
    let error: BlowUpError | null = null;
    while (s.steps < this.target && !error && now - begin < this.limits.sliceMs) {
      // Never more samples than the record holds, so that none is dropped before it is sent.
      const room = (Math.floor(s.steps / s.every) + s.record.capacity - s.record.length) * s.every - s.steps;
      if (room < 1) break;
      // As on the page (frame-budget.ts), one step is timed before a longer run is committed to.
      const wanted = this.cost > 0 ? Math.max(1, Math.floor(this.limits.subMs / this.cost)) : 1;
      const taken = s.run(Math.min(wanted, room, this.target - s.steps));
      const after = this.clock();
      if (taken > 0) {
        const sample = Math.max(after - now, 0.005) / taken;
        this.cost = this.cost > 0 ? 0.7 * this.cost + 0.3 * sample : sample;
      }
      now = after;
      error = s.error;
    }
    const table = s.record.table();
    s.record.clear();
    const chunk: Chunk = { type: 'chunk', gen: this.gen, from, end: s.steps, rows: table.data, width: s.record.width, ms: now - begin };
    // The last sample carries the state already; a huge state between samples is not worth its copies (chunk-protocol.ts).
    if (error || (s.steps % s.every !== 0 && s.state.length <= this.limits.stateValues)) chunk.state = Float64Array.from(s.state);
    if (error) {
      const { t, component, value, trajectory } = error;
      chunk.error = { t, component, value, trajectory };
    }
    return chunk;
  }
}
