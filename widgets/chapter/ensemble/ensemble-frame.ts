/**
 * An ensemble's state made into a frame to draw (ensemble-protocol.ts): the
 * same on the page and in the worker, so that a model which cannot travel
 * to a worker is moved on the page with the same numbers.
 */
import type { Ensemble } from '../../../core/index.ts';
import type { EnsembleFrame } from './ensemble-protocol.ts';

export function ensembleFrame(ensemble: Ensemble): EnsembleFrame {
  const state = ensemble.state();
  const boundary = ensemble.boundary;
  return {
    t: state.t,
    k: state.k,
    cloud: Float32Array.from(state.cloud),
    // Copies: the boundary's own arrays are views it overwrites, and a frame's buffers are handed to the page.
    s: Float64Array.from(boundary.parameters()),
    q: Float64Array.from(boundary.q()),
    p: Float64Array.from(boundary.p()),
    area: state.area,
    areaError: state.areaError,
    initialArea: state.initialArea,
    saturated: state.saturated,
    failed: state.failed,
  };
}

/** The buffers of a frame, handed over rather than copied when it is posted. */
export function frameBuffers(frame: EnsembleFrame): ArrayBuffer[] {
  return [frame.cloud.buffer, frame.s.buffer, frame.q.buffer, frame.p.buffer] as ArrayBuffer[];
}
