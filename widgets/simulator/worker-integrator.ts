/**
 * The page's side of integrating in the simulation worker
 * (simulation-worker.ts): keeps the worker a fraction of a second ahead of
 * what the page shows, and each frame moves the page's Simulation forward
 * through the samples already computed, appending them to its record. The
 * Simulation object stays the one views, readouts and downloads read: its
 * steps, state, error and record are set here exactly as its own `run` would
 * have set them.
 *
 * Only a model of generated code can go (portable-model.ts); an
 * opaque JS function stays on the page. Until the worker has loaded, and
 * whenever it cannot be used (no Worker, a policy that blocks it, a model it
 * fails to build), the driver integrates on the page as before.
 */
import { BlowUpError, type Simulation } from '../../core/index.ts';
import { ChunkQueue, lookaheadTarget, type StartRequest, type WorkerReply, type WorkerRequest } from './chunk-protocol.ts';
import type { Budget } from './frame-budget.ts';
import { hamiltonianTravels, portableModel } from './portable-model.ts';

/** Set once a worker failed to load: later simulators do not try again. */
let unavailable = false;

/** What a frame's consumption did. */
export interface Consumed {
  steps: number;
  ms: number;
  /** the frame's time budget ran out with samples left */
  outOfBudget: boolean;
  /** the worker had not yet computed what real time asked for */
  starved: boolean;
}

export class WorkerIntegrator {
  /** True once the worker has loaded and holds the current simulation: frames then take its samples. */
  live = false;
  private readonly worker: Worker;
  private queue: ChunkQueue | null = null;
  private gen = 0;
  private requested = 0;
  /** the pace last asked for, steps per second, so that a new generation is asked ahead at once */
  private rate = 0;
  private sentParams: Float64Array | null = null;
  private readonly row = { scratch: new Float64Array(0) };
  private disposed = false;
  private loaded = false;
  /** true from a new generation until the worker has passed the page, which integrates meanwhile */
  private catchingUp = false;

  /**
   * A worker for the simulation's model, or null where none can run or the
   * model cannot go; `onReady` is called once it has loaded, `onFailure` when it cannot
   * be used after all.
   */
  static start(simulation: Simulation, onReady: () => void, onFailure: () => void): WorkerIntegrator | null {
    if (unavailable || typeof Worker === 'undefined' || !portableModel(simulation.model)) return null;
    try {
      const worker = new Worker(new URL('./simulation-worker.ts', import.meta.url), { type: 'module', name: 'phasebook-simulation' });
      return new WorkerIntegrator(worker, onReady, onFailure);
    } catch {
      unavailable = true;
      return null;
    }
  }

  private constructor(worker: Worker, onReady: () => void, private readonly onFailure: () => void) {
    this.worker = worker;
    worker.onmessage = (event: MessageEvent<WorkerReply>) => {
      const reply = event.data;
      if (this.disposed) return;
      if (reply.type === 'ready') {
        this.loaded = true;
        onReady();
      }
      else if (reply.type === 'failed') {
        if (reply.gen === this.gen) this.fail();
      } else this.queue?.accept(reply);
    };
    // A worker that cannot load (a policy that forbids it, a missing file) leaves this page to integrate, and later
    // simulators do not try; one that fails later (out of memory, say) leaves it to this simulator's page.
    worker.onerror = (event) => {
      event.preventDefault();
      if (!this.loaded) unavailable = true;
      this.fail();
    };
  }

  /**
   * Starts a new generation from the simulation's present state (after a
   * restart, a new dt, a step on the page, or when the worker first comes
   * up): whatever the worker computed before is dropped.
   */
  sync(simulation: Simulation): void {
    if (this.disposed) return;
    const model = portableModel(simulation.model);
    if (!model) {
      this.live = false;
      return;
    }
    this.gen++;
    this.queue = new ChunkQueue(simulation.every);
    this.queue.reset(this.gen, simulation.steps);
    this.requested = simulation.steps;
    this.live = true;
    this.catchingUp = true;
    // A stopped simulation runs no further: the worker is left idle, and its old chunks are dropped.
    if (simulation.error) return;
    this.sentParams = Float64Array.from(simulation.model.params);
    const start: StartRequest = {
      type: 'start',
      gen: this.gen,
      model,
      params: this.sentParams,
      state: Float64Array.from(simulation.state),
      steps: simulation.steps,
      t0: simulation.t0,
      dt: simulation.dt,
      every: simulation.every,
      energy: hasEnergy(simulation),
    };
    this.post(start);
    // Ahead at once, not at the next frame: the first frame after a restart then rarely waits.
    if (this.rate > 0) this.request(simulation, this.rate);
  }

  /** True when the worker computes what the page shows (it is live and has passed the page). */
  get serving(): boolean {
    return this.live && !this.catchingUp;
  }

  /**
   * True while the page should integrate by itself: from a new generation
   * (the worker's start, a restart, a new dt) until the worker has computed
   * past where the page now is. Both run the same code from the same state,
   * so the page then simply goes on with the worker's samples beyond its own
   * step, and no frame waits for the worker to start.
   */
  handingOver(simulation: Simulation): boolean {
    const queue = this.queue;
    if (!this.catchingUp || !queue) return this.catchingUp;
    if (simulation.steps < queue.position) {
      this.sync(simulation);
      return true;
    }
    if (!queue.skipTo(simulation.steps, simulation.state.length)) return true;
    this.catchingUp = false;
    return false;
  }

  /**
   * Asks the worker to stay LOOKAHEAD_SECONDS ahead at this pace (called
   * each frame while playing). A parameter written into the model since
   * takes effect from the present step, as on the page: the worker starts
   * again from here with it.
   */
  request(simulation: Simulation, stepsPerSecond: number): void {
    this.rate = stepsPerSecond;
    if (!this.live || simulation.error) return;
    if (this.paramsChanged(simulation.model.params)) this.sync(simulation);
    const queue = this.queue;
    if (!queue || queue.ended) return;
    const here = simulation.steps;
    const target = lookaheadTarget(here, stepsPerSecond, 8 * simulation.record.width, simulation.every);
    if (target - this.requested < Math.max(1, (target - here) / 4)) return;
    this.requested = target;
    this.post({ type: 'advance', gen: this.gen, target });
  }

  /**
   * Moves the simulation forward through received samples, up to `owed`
   * steps and within the frame's budget: each sample goes into the record,
   * the state and step count follow, and a blow-up the worker met becomes
   * the simulation's error at the same step.
   */
  advance(simulation: Simulation, owed: number, clock: () => number, budget: Budget): Consumed {
    const queue = this.queue;
    if (!queue) return { steps: 0, ms: 0, outOfBudget: false, starved: true };
    if (simulation.steps !== queue.position) {
      // Something moved the simulation behind the worker's back (a cell called run or restart): start again from there.
      this.sync(simulation);
      return { steps: 0, ms: 0, outOfBudget: false, starved: true };
    }
    return consumeChunks(queue, simulation, owed, clock, budget, this.row);
  }

  /**
   * Advances by `steps` at once (the Step button): through received samples
   * where there are enough, else on the page, after which the worker starts
   * again from the new state.
   */
  step(simulation: Simulation, steps: number): void {
    const goal = simulation.steps + steps;
    if (this.handingOver(simulation)) {
      simulation.run(steps);
      return;
    }
    this.advance(simulation, steps, () => 0, { frameMs: Infinity, chunkMs: Infinity, maxElapsedMs: Infinity });
    if (simulation.steps < goal && !simulation.error) {
      simulation.run(goal - simulation.steps);
      this.sync(simulation);
    }
  }

  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.live = false;
    this.queue = null;
    this.worker.terminate();
  }

  private fail(): void {
    if (this.disposed) return;
    this.dispose();
    this.onFailure();
  }

  private post(message: WorkerRequest): void {
    this.worker.postMessage(message);
  }

  private paramsChanged(params: Float64Array): boolean {
    const sent = this.sentParams;
    return !!sent && params.some((value, i) => !Object.is(value, sent[i]));
  }
}

/** True when the record's first derived series is the model's own H, and the worker computes it too. */
function hasEnergy(simulation: Simulation): boolean {
  const first = simulation.derived[0];
  return !!first && first.name === 'H' && first.evaluate === simulation.model.hamiltonian && hamiltonianTravels(simulation.model);
}

/**
 * Moves a simulation forward through a queue's points, up to `owed` steps
 * and within the frame's budget: each sample goes into the record, the
 * state and step count follow, and a blow-up the worker met becomes the
 * simulation's error at the same step, as its own `run` would have left it.
 */
export function consumeChunks(
  queue: ChunkQueue,
  simulation: Simulation,
  owed: number,
  clock: () => number,
  budget: Budget,
  row: { scratch: Float64Array } = { scratch: new Float64Array(0) },
): Consumed {
  const start = clock();
  const before = simulation.steps;
  const limit = before + owed;
  // The clock is read every few thousand values copied.
  const stride = Math.max(1, Math.ceil(4096 / simulation.record.width));
  let taken = 0;
  let state: Float64Array | null = null;
  let outOfBudget = false;
  while (queue.peek() <= limit && !simulation.error) {
    if (taken > 0 && taken % stride === 0 && clock() - start > budget.frameMs) {
      outOfBudget = true;
      break;
    }
    const point = queue.take(simulation.state.length);
    taken++;
    if (point.row) appendSample(simulation, point.row.data, point.row.offset, row);
    simulation.steps = point.step;
    state = point.state;
    if (point.error) {
      const { t, component, value, trajectory } = point.error;
      simulation.error = new BlowUpError(t, component, value, trajectory);
    }
  }
  if (state) simulation.state.set(state);
  const starved = !outOfBudget && !simulation.error && queue.peek() === Infinity && limit - simulation.steps >= 1;
  return { steps: simulation.steps - before, ms: clock() - start, outOfBudget, starved };
}

/**
 * Appends one sample from the worker: as it came when the record's columns
 * are the worker's (t, the states, H), else with the cell's own derived
 * series computed here, since those are closures of the page.
 */
export function appendSample(simulation: Simulation, data: Float64Array, offset: number, row: { scratch: Float64Array }): void {
  const { record, count, derived } = simulation;
  const dim = simulation.model.dim;
  const energy = hasEnergy(simulation) ? 1 : 0;
  if (derived.length === energy) {
    record.push(data, offset);
    return;
  }
  if (row.scratch.length !== record.width) row.scratch = new Float64Array(record.width);
  const out = row.scratch;
  const states = count * dim;
  const t = data[offset];
  out[0] = t;
  out.set(data.subarray(offset + 1, offset + 1 + states), 1);
  let c = 1 + states;
  for (let j = 0; j < count; j++) {
    for (let d = 0; d < derived.length; d++) {
      out[c++] = d < energy ? data[offset + 1 + states + j] : derived[d].evaluate(t, data, offset + 1 + j * dim);
    }
  }
  record.push(out);
}
