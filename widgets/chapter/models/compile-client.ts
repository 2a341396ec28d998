/**
 * The page's side of model compilation: sends a spec to the compile worker
 * (compile-worker.ts) and resolves with the compiled model, reporting
 * progress and honouring cancellation. Where a worker cannot be started (an
 * old browser, a policy that forbids it) the model is compiled on the page
 * as before: slower to start, the same result.
 */
import { type BuildControl, type CompiledModel, InputError, MAX_DOF, type ModelKeySpec, outside } from '../../../core/index.ts';
import type { CompileReply, CompileRequest } from './compile-worker.ts';

interface Pending {
  readonly spec: ModelKeySpec;
  resolve(model: CompiledModel): void;
  reject(error: Error): void;
  progress?: (done: number, total: number) => void;
}

let worker: Worker | null | undefined;
let nextId = 1;
const pending = new Map<number, Pending>();

/** Rebuilds an error from the worker with its name, so an InputError reads as the reader's mistake. */
function errorFrom({ name, message }: { name: string; message: string }): Error {
  if (name === 'InputError') return new InputError(message);
  const error = new Error(message);
  error.name = name;
  return error;
}

function startWorker(): Worker | null {
  try {
    const started = new Worker(new URL('./compile-worker.ts', import.meta.url), { type: 'module', name: 'phasebook-compile' });
    started.onmessage = (event: MessageEvent<CompileReply>) => {
      const reply = event.data;
      const job = pending.get(reply.id);
      if (!job) return;
      if ('progress' in reply) {
        job.progress?.(reply.progress, 1);
        return;
      }
      pending.delete(reply.id);
      if ('model' in reply) job.resolve(reply.model);
      else job.reject(errorFrom(reply.error));
    };
    // A worker that cannot load its script fails every build it was given, and later ones go to the page.
    started.onerror = (event) => {
      event.preventDefault();
      worker = null;
      for (const [id, job] of pending) {
        pending.delete(id);
        void compileOnPage(job);
      }
    };
    return started;
  } catch {
    return null;
  }
}

/** The build of a spec the worker could not take: on the main thread, as the page did before the worker. */
async function compileOnPage(job: Pending): Promise<void> {
  try {
    const { compileModel } = await import('../../../core/model/compile-model.ts');
    job.resolve(await compileModel(job.spec, { progress: job.progress }));
  } catch (error) {
    job.reject(error instanceof Error ? error : new Error(String(error)));
  }
}

/**
 * Compiles `spec` in the compile worker (see the module comment). A model
 * past the page's bound on degrees of freedom (core/limits.ts) is refused
 * first: 500 took the page over 4 s to compile and typeset before the
 * simulator said that 500 is above 200.
 */
export function compileInWorker(spec: ModelKeySpec, control: BuildControl = {}): Promise<CompiledModel> {
  const bound = outside('dof', spec.dof, 1, MAX_DOF);
  if (bound) return Promise.reject(new InputError(bound));
  const { signal, progress } = control;
  if (signal?.aborted) return Promise.reject(new DOMException('the model build was cancelled', 'AbortError'));
  if (worker === undefined) worker = startWorker();
  if (typeof spec.hamiltonian !== 'string') {
    // A function value cannot cross to a worker; its source can, and that is what is compiled.
    spec = { ...spec, hamiltonian: spec.hamiltonian.toString() };
  }
  return new Promise<CompiledModel>((resolve, reject) => {
    const job: Pending = { spec, resolve, reject, progress };
    if (!worker) {
      void compileOnPage(job);
      return;
    }
    const id = nextId++;
    pending.set(id, job);
    worker.postMessage({ id, spec } satisfies CompileRequest);
    signal?.addEventListener(
      'abort',
      () => {
        if (!pending.delete(id)) return;
        worker?.postMessage({ cancel: id } satisfies CompileRequest);
        reject(new DOMException('the model build was cancelled', 'AbortError'));
      },
      { once: true },
    );
  });
}
