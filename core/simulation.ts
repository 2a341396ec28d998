import { BlowUpError, InputError } from './errors.ts';
import { recordLayout, TrajectoryRecord } from './record.ts';
import { SUMMARY } from './summary.ts';
import type { Model } from './types.ts';

/** A series computed from each sample, e.g. H or an action I = H/ω. */
export interface DerivedSeries {
  name: string;
  evaluate: (t: number, x: Float64Array, offset: number) => number;
}

export interface SimulationOptions {
  /** the initial state, count·dim values for a batch of count trajectories */
  initial: ArrayLike<number>;
  /** the time step; the paper's 5e-4 by default */
  dt?: number;
  t0?: number;
  /** record a sample every K steps */
  every?: number;
  /** series recorded beside the state; H is added first when the model knows H, unless `energy` is false */
  derived?: readonly DerivedSeries[];
  energy?: boolean;
  /** the record's cap in rows; the oldest rows are dropped beyond it */
  capacity?: number;
}

export const DEFAULT_DT = 5e-4;

/**
 * Integrates a model from an initial state, sampling into a trajectory
 * record. The model is the physics, the stepper the solver, this the advance
 * policy; views read the record.
 */
export class Simulation {
  readonly dt: number;
  readonly t0: number;
  readonly every: number;
  /** trajectories in the batch */
  readonly count: number;
  readonly initial: Float64Array;
  readonly state: Float64Array;
  readonly derived: readonly DerivedSeries[];
  readonly record: TrajectoryRecord;
  /** steps taken since the start */
  steps = 0;
  /** set when the state stopped being finite; the simulation then refuses to run */
  error: BlowUpError | null = null;
  private readonly row: Float64Array;

  constructor(
    readonly model: Model,
    options: SimulationOptions,
  ) {
    const { dim } = model;
    this.dt = options.dt ?? DEFAULT_DT;
    if (!(this.dt > 0) || !Number.isFinite(this.dt)) throw new InputError(`dt must be a positive number, not ${options.dt}`);
    this.t0 = options.t0 ?? 0;
    if (!Number.isFinite(this.t0)) throw new InputError(`t0 must be a finite number, not ${options.t0}`);
    this.every = options.every ?? 1;
    if (!Number.isInteger(this.every) || this.every < 1) {
      throw new InputError(`the sampling interval must be a whole number of steps ≥ 1, not ${options.every}`);
    }
    const n = options.initial.length;
    if (n === 0 || n % dim !== 0) {
      throw new InputError(`${n} initial values given; the state of ${model.dof} degree(s) of freedom needs ${dim} (or a multiple, for a batch)`);
    }
    this.initial = Float64Array.from(options.initial);
    this.initial.forEach((v, i) => {
      if (!Number.isFinite(v)) throw new InputError(`initial value ${i + 1} is ${v}, not a finite number`);
    });
    this.count = n / dim;
    this.state = Float64Array.from(this.initial);
    const h = model.hamiltonian;
    const energy = options.energy !== false && h ? [{ name: 'H', evaluate: h }] : [];
    this.derived = [...energy, ...(options.derived ?? [])];
    this.record = new TrajectoryRecord(
      recordLayout(
        this.model.names,
        this.derived.map((d) => d.name),
        this.count,
      ),
      options.capacity ?? 1_000_000,
    );
    this.row = new Float64Array(this.record.width);
    this.sample();
  }

  /** The current time, t0 + steps·dt. */
  get t(): number {
    return this.t0 + this.steps * this.dt;
  }

  /**
   * Advances by up to `steps` steps, recording every `every`-th; returns the
   * steps taken, fewer only when the state blew up (see `error`).
   */
  /** One line for the cells' inspector (core/summary.ts). */
  [SUMMARY](): string {
    const trajectories = this.count === 1 ? '1 trajectory' : `${this.count.toLocaleString('en')} trajectories`;
    return `Simulation: t = ${Number(this.t.toPrecision(6))}, ${this.steps.toLocaleString('en')} steps of dt = ${this.dt}, ${trajectories}${this.error ? ', stopped: blow-up' : ''}`;
  }

  run(steps: number): number {
    if (this.error) return 0;
    const { model, state, count, dt, every } = this;
    let done = 0;
    while (done < steps) {
      const chunk = Math.min(every - (this.steps % every), steps - done);
      const ok = model.stepper.advance(state, count, model.params, this.t0, this.steps, dt, chunk);
      this.steps += ok;
      done += ok;
      if (ok < chunk) {
        this.error = this.blowUp();
        break;
      }
      if (this.steps % every === 0) this.sample();
    }
    return done;
  }

  /** Back to the initial state (or a new one of the same size), with an empty record. */
  restart(initial?: ArrayLike<number>): void {
    if (initial) {
      if (initial.length !== this.initial.length) {
        throw new InputError(`${initial.length} initial values given, ${this.initial.length} needed`);
      }
      this.initial.set(initial);
    }
    this.state.set(this.initial);
    this.steps = 0;
    this.error = null;
    this.record.clear();
    this.sample();
  }

  private sample(): void {
    const { row, state, derived, count } = this;
    const dim = this.model.dim;
    const t = this.t;
    row[0] = t;
    row.set(state, 1);
    let c = 1 + count * dim;
    for (let j = 0; j < count; j++) {
      for (let d = 0; d < derived.length; d++) row[c++] = derived[d].evaluate(t, state, j * dim);
    }
    this.record.push(row);
  }

  private blowUp(): BlowUpError {
    const { state, model } = this;
    const t = this.t0 + (this.steps + 1) * this.dt;
    for (let i = 0; i < state.length; i++) {
      if (!Number.isFinite(state[i])) {
        const j = Math.floor(i / model.dim);
        return new BlowUpError(t, model.names[i % model.dim], state[i], this.count > 1 ? j : undefined);
      }
    }
    return new BlowUpError(t, 'the state', NaN);
  }
}
