/**
 * The messages between an ensemble on the page and the worker that moves it
 * (ensemble-worker.ts), and the one frame both sides agree on. The cloud
 * travels as 32-bit floats: it is drawn as pixels, where single precision
 * is far below a pixel, and it halves what crosses each frame. The
 * boundary travels at full precision, for its area and the CSV.
 */
import type { EnsembleSetup } from '../../../core/index.ts';
import type { PortableModel } from '../../simulator/portable-model.ts';

export type EnsembleRequest =
  | { kind: 'start'; id: number; model: PortableModel; params: Float64Array; setup: EnsembleSetup }
  | { kind: 'advance'; id: number; steps: number };

/** The ensemble after a request: what the page draws and reads out. */
export interface EnsembleFrame {
  t: number;
  k: number;
  /** q, p pairs */
  cloud: Float32Array;
  /** the boundary's vertices, their parameters s on the initial circle, q and p */
  s: Float64Array;
  q: Float64Array;
  p: Float64Array;
  area: number;
  areaError: number;
  initialArea: number;
  saturated: boolean;
  failed: boolean;
}

export type EnsembleReply = { id: number; frame: EnsembleFrame } | { id: number; error: string };
