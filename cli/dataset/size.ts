/**
 * How big a `simulate` run is before it starts, and the limits beyond which
 * it needs --force. A slip of the finger (--dt 1e-300, a t-end with three
 * zeros too many) otherwise means hours of computing or a disk filled with
 * gigabytes nobody wanted; a run that large on purpose costs one flag.
 */
import { InputError } from '../../core/index.ts';

/** About twenty seconds of a one-degree-of-freedom model at the fused stepper's ~50 million steps a second, minutes for larger ones. */
export const STEP_LIMIT = 1e9;
/** 1 GiB. */
export const OUTPUT_LIMIT = 2 ** 30;

/**
 * Bytes per number with its separator. A full-precision double prints as 17
 * to 20 characters, t and round values as fewer: the README's oscillator
 * writes 65 bytes per row of 4 numbers in CSV, 68 in JSON.
 */
const BYTES_PER_VALUE = 18;
/** A JSON row adds its brackets and a comma. */
const JSON_ROW_BYTES = 3;
/** The header, and JSON's meta (the source of H and the parameters): a generous allowance. */
const HEAD_BYTES = 4096;

export interface RunSize {
  steps: number;
  rows: number;
  /** an estimate of the output's size */
  bytes: number;
}

export interface RunShape {
  tEnd: number;
  dt: number;
  every: number;
  /** columns of each row: t, the state, H */
  columns: number;
  format: 'csv' | 'json';
}

/** The steps, rows and (estimated) bytes of a run; the steps are those the run takes. */
export function runSize({ tEnd, dt, every, columns, format }: RunShape): RunSize {
  // t-end is reached by a whole number of steps; a hair of tolerance keeps 10/5e-4 from losing its last step.
  const steps = Math.floor(tEnd / dt + 1e-9);
  const rows = Math.floor(steps / every) + 1;
  const bytes = rows * (columns * BYTES_PER_VALUE + (format === 'json' ? JSON_ROW_BYTES : 0)) + HEAD_BYTES;
  return { steps, rows, bytes };
}

/** A count as a person reads it: 20001, 2.5e+7, 1e+301. */
export function count(n: number): string {
  return n < 1e6 ? String(n) : Number(n.toPrecision(3)).toExponential();
}

/** A size in bytes, in binary units up to EiB. */
export function byteSize(bytes: number): string {
  const units = ['bytes', 'KiB', 'MiB', 'GiB', 'TiB', 'PiB', 'EiB'];
  let value = bytes;
  let unit = 0;
  while (value >= 1024 && unit < units.length - 1) {
    value /= 1024;
    unit++;
  }
  if (value >= 1024) return `${count(bytes)} bytes`;
  return unit === 0 ? `${value} bytes` : `${Number(value.toPrecision(3))} ${units[unit]}`;
}

/**
 * Throws an InputError, with the estimate and the limits it exceeds, for a
 * run beyond STEP_LIMIT steps or OUTPUT_LIMIT bytes, unless `force`. A run
 * whose step count overflows is refused even then: it could never end.
 */
export function checkRunSize(size: RunSize, force: boolean): void {
  if (!Number.isFinite(size.steps)) throw new InputError('--t-end / --dt is too many steps to count; raise --dt or lower --t-end');
  const tooLong = size.steps > STEP_LIMIT;
  const tooBig = size.bytes > OUTPUT_LIMIT;
  if (force || (!tooLong && !tooBig)) return;
  const steps = `${count(size.steps)} steps${tooLong ? ` (the limit is ${count(STEP_LIMIT)}; raise --dt or lower --t-end)` : ''}`;
  const output = `about ${byteSize(size.bytes)} of output${tooBig ? ` (the limit is ${byteSize(OUTPUT_LIMIT)}; raise --every or lower --t-end)` : ''}`;
  throw new InputError(`this run would take ${steps} and write ${output}; add --force to run it anyway`);
}

export interface DatasetShapeForSize {
  /** steps per trajectory */
  steps: number;
  samples: number;
  trajectories: number;
  /** numbers per sample, the trajectory's index included */
  columns: number;
  format: 'csv' | 'json' | 'npz' | 'parquet';
}

/**
 * The steps and (estimated) bytes of a dataset run: text as runSize counts
 * it, NPZ and Parquet at 8 bytes a number.
 */
export function datasetSize({ steps, samples, trajectories, columns, format }: DatasetShapeForSize): RunSize {
  const rows = samples * trajectories;
  const perRow = format === 'npz' || format === 'parquet' ? 8 * columns : columns * BYTES_PER_VALUE + (format === 'json' ? JSON_ROW_BYTES : 0);
  return { steps: steps * trajectories, rows, bytes: rows * perRow + HEAD_BYTES };
}
