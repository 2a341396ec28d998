/**
 * Moves an ensemble off the main thread: tens of thousands of points and a
 * boundary of thousands of vertices are a few milliseconds of steps a
 * frame, which the page's own frames should not wait on. The model comes
 * as its generated source (simulator/portable-model.ts), so the worker
 * computes what the page would, bit for bit.
 *
 * Messages in: EnsembleRequest ('start' builds the ensemble, 'advance'
 * carries it on); out: the frame after each, or {error}.
 */
import { Ensemble } from '../../../core/index.ts';
import { modelFromPortable } from '../../simulator/portable-model.ts';
import { ensembleFrame, frameBuffers } from './ensemble-frame.ts';
import type { EnsembleRequest } from './ensemble-protocol.ts';

let ensemble: Ensemble | null = null;

function serve(request: EnsembleRequest): void {
  if (request.kind === 'start') {
    const model = modelFromPortable(request.model, request.params);
    ensemble = new Ensemble(model.stepper, model.params, request.setup);
  } else {
    if (!ensemble) throw new Error('the ensemble was asked to move before it was started');
    ensemble.advance(request.steps);
  }
  const frame = ensembleFrame(ensemble);
  postMessage({ id: request.id, frame }, { transfer: frameBuffers(frame) });
}

self.onmessage = (event: MessageEvent<EnsembleRequest>) => {
  try {
    serve(event.data);
  } catch (error) {
    postMessage({ id: event.data.id, error: (error as Error)?.message ?? String(error) });
  }
};
