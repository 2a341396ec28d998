/**
 * A worker thread of a dataset run: builds the model from the recipe it is
 * given (no compiler needed), then runs the tasks the main thread sends,
 * one at a time, and posts each result back, its numbers transferred
 * rather than copied.
 */
import { parentPort, workerData } from 'node:worker_threads';
import { BlowUpError, InputError } from '../../core/index.ts';
import { modelFromRecipe, type ModelRecipe } from '../model/model.ts';
import { TaskRunner, type Task, type TaskSetup } from './run-task.ts';

export interface WorkerInit {
  recipe: ModelRecipe;
  setup: TaskSetup;
}

/** An error as data: its kind decides how the main thread raises it again. */
export type WorkerError =
  | { kind: 'input'; message: string }
  | { kind: 'blow-up'; t: number; component: string; value: number; trajectory?: number }
  | { kind: 'internal'; message: string };

export function errorAsData(error: unknown): WorkerError {
  if (error instanceof BlowUpError) return { kind: 'blow-up', t: error.t, component: error.component, value: error.value, trajectory: error.trajectory };
  if (error instanceof InputError) return { kind: 'input', message: error.message };
  return { kind: 'internal', message: (error as Error)?.message ?? String(error) };
}

async function serve(): Promise<void> {
  const port = parentPort!;
  const init = workerData as WorkerInit;
  let runner: TaskRunner;
  try {
    runner = new TaskRunner(await modelFromRecipe(init.recipe), init.setup);
  } catch (error) {
    port.postMessage({ id: -1, error: errorAsData(error) });
    return;
  }
  port.on('message', (message: Task | { recycle: ArrayBuffer }) => {
    if ('recycle' in message) return runner.recycle(message.recycle);
    const task = message;
    try {
      const result = runner.runWhole(task);
      const payload = result.data ?? result.text;
      port.postMessage(result, payload ? [payload.buffer as ArrayBuffer] : []);
    } catch (error) {
      port.postMessage({ id: task.id, error: errorAsData(error) });
    }
  });
}

if (parentPort) void serve();
