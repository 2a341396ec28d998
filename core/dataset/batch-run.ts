/**
 * Many trajectories of one model through one set of sample times, advanced
 * together by the model's stepper (one call moves the whole batch), their
 * samples written straight into a caller's buffer.
 *
 * A row is t, the state, H when the model knows it, and with `derivatives`
 * dx/dt from the model's canonical equations at the sample: the exact
 * derivatives of H for an expression (what a Hamiltonian neural network is
 * trained on), the 5-point differences of an opaque JS H, or the field as
 * written.
 *
 * Every trajectory's numbers depend only on its initial state and the
 * model, never on which others share its batch: the stepper advances each on
 * its own. That is why any split of a dataset (workers, shards, blocks)
 * writes the same bytes.
 */
import { BlowUpError } from '../errors.ts';
import type { Model } from '../types.ts';
import type { SampleTimes } from './sample-times.ts';

/** Where sample r of trajectory j goes in an output buffer: base + j·trajectoryStride + r·rowStride. */
export interface RowLayout {
  base: number;
  trajectoryStride: number;
  rowStride: number;
}

export interface BatchRunOptions {
  /** the global index of this batch's first trajectory, named in messages; a lone trajectory without it is not numbered */
  first?: number;
  /** dx/dt at each sample */
  derivatives?: boolean;
}

/**
 * The columns of a row: t, the state, H when known, then dx/dt when asked
 * for, named d<name>/dt. Only whether there is an H matters, so a caller that
 * knows of a model without holding it (the CLI, whose model may run in
 * another process) can ask too.
 */
export function rowColumns(model: Pick<Model, 'names'> & { readonly hamiltonian?: unknown }, derivatives: boolean): string[] {
  const columns = ['t', ...model.names];
  if (model.hamiltonian) columns.push('H');
  if (derivatives) columns.push(...model.names.map((n) => `d${n}/dt`));
  return columns;
}

export class BatchRun {
  readonly count: number;
  readonly width: number;
  /** the next sample row to produce */
  row = 0;
  /** steps taken, summed over the batch */
  stepsDone = 0;
  private readonly state: Float64Array;
  private readonly scratch: Float64Array;
  private readonly one: Float64Array;
  private readonly rate: Float64Array;
  private readonly first: number | undefined;
  private readonly derivatives: boolean;
  /** whole steps the state has taken */
  private k = 0;

  constructor(
    readonly model: Model,
    readonly times: SampleTimes,
    initial: Float64Array,
    readonly t0: number,
    readonly dt: number,
    options: BatchRunOptions = {},
  ) {
    const { dim } = model;
    this.count = initial.length / dim;
    this.state = Float64Array.from(initial);
    this.scratch = new Float64Array(initial.length);
    this.one = new Float64Array(dim);
    this.rate = new Float64Array(dim);
    this.first = options.first;
    this.derivatives = options.derivatives ?? false;
    this.width = 1 + dim + (model.hamiltonian ? 1 : 0) + (this.derivatives ? dim : 0);
  }

  /** Steps the whole run takes per trajectory: to the last sample. */
  get totalSteps(): number {
    const last = this.times.count - 1;
    return this.times.step(last) + (this.times.extra(last) > 0 ? 1 : 0);
  }

  /**
   * Produces the next `rows` samples of every trajectory into `out` at
   * `layout`. Throws a BlowUpError naming the trajectory whose state stopped
   * being finite.
   */
  produce(rows: number, out: Float64Array, layout: RowLayout): void {
    const { model, times, state, count, dt, t0 } = this;
    const end = Math.min(this.row + rows, times.count);
    for (let r = 0; this.row < end; r++, this.row++) {
      const i = this.row;
      const target = times.step(i);
      if (target > this.k) {
        const n = target - this.k;
        const ok = model.stepper.advance(state, count, model.params, t0, this.k, dt, n);
        this.stepsDone += ok * count;
        if (ok < n) throw this.blowUp(state, t0 + (this.k + ok + 1) * dt);
        this.k = target;
      }
      let sampled = state;
      const h = times.extra(i);
      if (h > 0) {
        // One short step of a copy to the time asked for; the run stays on its grid.
        this.scratch.set(state);
        const tk = t0 + this.k * dt;
        if (model.stepper.advance(this.scratch, count, model.params, tk, 0, h, 1) < 1) throw this.blowUp(this.scratch, tk + h);
        sampled = this.scratch;
      }
      this.sample(times.time(i), sampled, out, layout, r);
    }
  }

  private sample(t: number, x: Float64Array, out: Float64Array, layout: RowLayout, r: number): void {
    const { model, count, one, rate } = this;
    const dim = model.dim;
    const h = model.hamiltonian;
    for (let j = 0; j < count; j++) {
      let at = layout.base + j * layout.trajectoryStride + r * layout.rowStride;
      const o = j * dim;
      out[at++] = t;
      for (let c = 0; c < dim; c++) out[at++] = x[o + c];
      if (h) out[at++] = h(t, x, o);
      if (this.derivatives) {
        for (let c = 0; c < dim; c++) one[c] = x[o + c];
        model.field(t, one, rate);
        for (let c = 0; c < dim; c++) out[at++] = rate[c];
      }
    }
  }

  private blowUp(x: Float64Array, t: number): BlowUpError {
    const { dim, names } = this.model;
    for (let i = 0; i < x.length; i++) {
      if (!Number.isFinite(x[i])) {
        const j = Math.floor(i / dim);
        const index = this.first === undefined && this.count === 1 ? undefined : (this.first ?? 0) + j;
        return new BlowUpError(t, names[i % dim], x[i], index);
      }
    }
    return new BlowUpError(t, 'the state', NaN);
  }
}
