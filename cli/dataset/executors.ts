/**
 * Where tasks run: in this thread, in stretches that return to the event
 * loop so that Ctrl-C is heard (as paced-run.ts does for a single run), or
 * in worker threads, one task at a time each.
 */
import { Worker } from 'node:worker_threads';
import { BlowUpError, InputError, type Model } from '../../core/index.ts';
import type { WorkerError, WorkerInit } from './worker-thread.ts';
import { TaskRunner, type Task, type TaskResult, type TaskSetup } from './run-task.ts';

export interface Executor {
  run(task: Task): Promise<TaskResult>;
  /**
   * Tasks it may be given before the first is done. A worker takes them in
   * order from its queue, so it starts the next at once instead of waiting
   * for the main thread to answer: on a machine loaded 4× over its cores, a
   * worker given one task at a time sat idle 7–8 % as long as it worked,
   * with two 0.2–0.8 %. This thread's executor runs one at a time.
   */
  depth: number;
  /** hands back a result's buffer once written, to be filled again */
  recycle(data: Float64Array | Uint8Array): void;
  /** stops at once, abandoning any task under way */
  close(): Promise<void>;
}

/** Aimed-at duration of one stretch of computing between two returns to the event loop. */
const STRETCH_MS = 20;

const yieldToEventLoop = () => new Promise<void>((resolve) => setImmediate(resolve));

/** Tasks run here, a stretch of rows at a time; `tick` is called at each return to the event loop. */
export function localExecutor(model: Model, setup: TaskSetup, signal: AbortSignal | undefined, tick: (steps: number) => void): Executor {
  const runner = new TaskRunner(model, setup);
  let stride = 1;
  let lastYield = performance.now();
  return {
    async run(task) {
      const { out } = runner.begin(task);
      const span = task.rowTo - task.rowFrom;
      let steps = 0;
      for (let done = 0; done < span; ) {
        const rows = Math.min(stride, span - done);
        const start = performance.now();
        const taken = runner.produce(task, out, done, rows);
        const now = performance.now();
        steps += taken;
        done += rows;
        tick(taken);
        // Grow at most fourfold at a time, aimed at STRETCH_MS (see paced-run.ts).
        const elapsed = now - start;
        stride = Math.max(1, Math.min(4 * stride, elapsed > 0 ? Math.floor((rows * STRETCH_MS) / elapsed) : 4 * stride));
        if (now - lastYield >= STRETCH_MS) {
          await yieldToEventLoop();
          signal?.throwIfAborted();
          lastYield = performance.now();
        }
      }
      return runner.end(task, out, steps);
    },
    depth: 1,
    recycle: (data) => runner.recycle(data.buffer as ArrayBuffer),
    async close() {},
  };
}

/** The error a worker reported, raised again here as what it was. */
export function errorFromData(error: WorkerError): Error {
  if (error.kind === 'blow-up') return new BlowUpError(error.t, error.component, error.value, error.trajectory);
  if (error.kind === 'input') return new InputError(error.message);
  return new Error(error.message);
}

/**
 * Where the worker's code is: beside this module in the compiled CLI
 * (build/cli/worker-thread.js); run from the TypeScript sources (tests, the
 * tsx fallback), a small module that registers tsx and imports the source.
 */
function workerScript(): { url: URL; eval: false } | { code: string; eval: true } {
  const here = import.meta.url;
  if (/\.js$/.test(here)) return { url: new URL('./worker-thread.js', here), eval: false };
  const source = new URL('./worker-thread.ts', here).href;
  return { code: `import('tsx/esm/api').then(({ register }) => { register(); return import(${JSON.stringify(source)}); });`, eval: true };
}

/** A worker thread running tasks one at a time. */
export function workerExecutor(init: WorkerInit): Executor {
  const script = workerScript();
  const { execArgv, resourceLimits } = workerFlags(process.execArgv);
  const worker = script.eval
    ? new Worker(script.code, { eval: true, workerData: init, execArgv, resourceLimits })
    : new Worker(script.url, { workerData: init, execArgv, resourceLimits });
  const pending = new Map<number, { resolve: (r: TaskResult) => void; reject: (e: Error) => void }>();
  let failure: Error | undefined;
  const failAll = (error: Error) => {
    failure ??= error;
    for (const { reject } of pending.values()) reject(failure);
    pending.clear();
  };
  worker.on('message', (message: TaskResult & { error?: WorkerError }) => {
    if (message.error) {
      const error = errorFromData(message.error);
      if (message.id < 0) return failAll(error);
      pending.get(message.id)?.reject(error);
    } else pending.get(message.id)?.resolve(message);
    pending.delete(message.id);
  });
  worker.on('error', (error) => failAll(error));
  worker.on('exit', (code) => failAll(new Error(`a worker thread stopped (exit code ${code})`)));
  return {
    run(task) {
      if (failure) return Promise.reject(failure);
      return new Promise((resolve, reject) => {
        pending.set(task.id, { resolve, reject });
        worker.postMessage(task);
      });
    },
    depth: 2,
    recycle(data) {
      if (!failure) worker.postMessage({ recycle: data.buffer }, [data.buffer as ArrayBuffer]);
    },
    async close() {
      failure ??= new Error('the worker was stopped');
      await worker.terminate();
    },
  };
}

/**
 * A worker's young generation, in MB: semi-spaces of 1 MB, the size V8
 * starts them at, so it never grows, and a run that writes every step holds
 * no more than one that writes every thousandth (with 6 MB, 4 MB more).
 */
const YOUNG_MB = 3;

/**
 * Node's flags as a worker takes them: a worker refuses V8's heap flags and
 * --input-type, so a heap cap (--max-old-space-size) becomes the worker's
 * own resource limit, and the rest pass on.
 */
export function workerFlags(flags: readonly string[]): { execArgv: string[]; resourceLimits: { maxOldGenerationSizeMb?: number; maxYoungGenerationSizeMb?: number } } {
  const execArgv: string[] = [];
  // A worker's garbage is short-lived (a line of text, a task's numbers): a small young generation collects it as
  // often as needed, where V8's default lets it grow to 48 MB per thread and the process's memory with it.
  const resourceLimits: { maxOldGenerationSizeMb?: number; maxYoungGenerationSizeMb?: number } = { maxYoungGenerationSizeMb: YOUNG_MB };
  for (const flag of flags) {
    const heap = /^--max[-_]old[-_]space[-_]size=(\d+)$/.exec(flag);
    if (heap) resourceLimits.maxOldGenerationSizeMb = Number(heap[1]);
    else if (!/^--(input-type|max[-_]semi[-_]space[-_]size|stack[-_]size)\b/.test(flag)) execArgv.push(flag);
  }
  return { execArgv, resourceLimits };
}
