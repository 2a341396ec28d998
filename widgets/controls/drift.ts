import { relativeChange, type RecordLayout, type TrajectoryRecord } from '../../core/index.ts';

/**
 * The energy drift |H − H₀| / |H₀| of the readouts. H₀ is taken from the
 * first sample after a restart and kept, so it survives the record dropping
 * its oldest rows. For a batch the worst trajectory is reported.
 */

/** Record columns holding H, one per trajectory; empty when the model has no H. */
export function energyColumns(layout: Pick<RecordLayout, 'series'>): number[] {
  return [...(layout.series.find((s) => s.name === 'H')?.columns ?? [])];
}

/** Tracks the drift of every H column against its value at the start. */
export class DriftTracker {
  private readonly columns: number[];
  private readonly h0: Float64Array;
  private started = false;

  constructor(layout: Pick<RecordLayout, 'series'>) {
    this.columns = energyColumns(layout);
    this.h0 = new Float64Array(this.columns.length);
  }

  get hasEnergy(): boolean {
    return this.columns.length > 0;
  }

  /** Takes H₀ from row 0 of the record (the initial state, unless rows were dropped); call after a restart. */
  start(record: TrajectoryRecord): void {
    this.started = record.length > 0;
    if (!this.started) return;
    this.columns.forEach((c, k) => (this.h0[k] = record.get(0, c)));
  }

  /** The latest H (of trajectory 0) and the worst drift over the batch, or null before any data. */
  latest(record: TrajectoryRecord): { h: number; drift: number; worst: number } | null {
    if (!this.hasEnergy || record.length === 0) return null;
    if (!this.started) this.start(record);
    const row = record.length - 1;
    let drift = 0;
    let worst = 0;
    this.columns.forEach((c, k) => {
      const d = relativeChange(record.get(row, c), this.h0[k]);
      if (k === 0) drift = d;
      if (d > worst || Number.isNaN(d)) worst = d;
    });
    return { h: record.get(row, this.columns[0]), drift, worst: Math.max(worst, drift) };
  }
}
