/**
 * Runs the method comparison (method-comparison.ts) off the main thread: a
 * long run of each method, recorded step by step, a timed run, and the
 * order study's runs are some 10⁵–10⁶ steps, which would freeze the page.
 * The runs themselves are method-comparison-run.ts; the models come
 * compiled, so this worker needs no mathjs.
 *
 * Messages in: ComparisonRequest. Out: {progress, stage} as it goes, then
 * {result} or {error}.
 */
import { runComparison, type ComparisonRequest } from './method-comparison-run.ts';

export type { ComparisonRequest } from './method-comparison-run.ts';

self.onmessage = (event: MessageEvent<ComparisonRequest>) => {
  try {
    const result = runComparison(event.data, (progress, stage) => postMessage({ progress, stage }));
    postMessage({ result });
  } catch (error) {
    postMessage({ error: (error as Error).message });
  }
};
