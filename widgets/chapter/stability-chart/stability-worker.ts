/**
 * Computes a stability chart off the main thread: a grid of Floquet growth
 * rates takes a second or more, which would freeze the page it sits in.
 * Messages in: StabilityRequest. Out: {progress} per row, then {rates} or {error}.
 */
import { type CompiledModel, floquetGrid, modelFromCompiled } from '../../../core/index.ts';

export interface StabilityRequest {
  /** compiled on the page (or by the build), so this worker needs no mathjs */
  model: CompiledModel;
  params: Record<string, number>;
  x: { param: string; values: number[] };
  y: { param: string; values: number[] };
  /** the parameter that sets the drive frequency: the period is 2π over it */
  frequencyParam: string;
  stepsPerPeriod: number;
}

self.onmessage = (event: MessageEvent<StabilityRequest>) => {
  const request = event.data;
  try {
    const model = modelFromCompiled(request.model, request.params);
    const index = model.paramNames.indexOf(request.frequencyParam);
    if (index < 0) throw new Error(`the model has no parameter ${request.frequencyParam}`);
    const rates = floquetGrid(model, {
      x: request.x,
      y: request.y,
      period: (p) => (2 * Math.PI) / p[index],
      stepsPerPeriod: request.stepsPerPeriod,
      progress: (fraction) => postMessage({ progress: fraction }),
    });
    postMessage({ rates }, { transfer: [rates.buffer] });
  } catch (error) {
    postMessage({ error: (error as Error).message });
  }
};
