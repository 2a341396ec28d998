/**
 * The sandbox's own process (see sandbox-process.ts for the CLI's side and
 * sandbox-flags.ts for the permissions it runs under): builds the model of
 * the recipe it is sent — compiling the user's JavaScript — and answers the
 * CLI's requests one at a time: evaluate once, then compute tasks, whose
 * numbers go back as they are. It formats nothing and writes nothing; the
 * CLI makes the file from the numbers.
 *
 * `process` and the network's globals are taken away (sandbox-harden.ts)
 * before the first request is read, so before any user code is compiled.
 */
import { fillInitial, type InitialSet, type Model } from '../../core/index.ts';
import { errorAsData } from '../dataset/worker-thread.ts';
import { TaskRunner, type Task } from '../dataset/run-task.ts';
import { checkEvaluates } from '../model/model.ts';
import { nextStride } from '../output/paced-run.ts';
import { harden, type Channel } from './sandbox-harden.ts';
import type { SandboxRequest } from './sandbox-messages.ts';
import { userModelFromRecipe } from '../model/user-model.ts';

/** How often a task reports its steps, for the CLI's progress bar. */
const PROGRESS_MS = 100;

function serve(channel: Channel): void {
  let model: Model | undefined;
  let runner: TaskRunner | undefined;
  // Requests are answered in the order they came, each after the one before: a model is built before it is used.
  let queue = Promise.resolve();
  const answer = async (request: SandboxRequest) => {
    try {
      if (request.kind === 'model') model = await userModelFromRecipe(request.recipe);
      else if (request.kind === 'probe') probe(model!, request.set, request.index, request.t0);
      else if (request.kind === 'setup') runner = new TaskRunner(model!, request.setup);
      else return runTask(channel, runner!, request.task);
      channel.send({ kind: 'done' });
    } catch (error) {
      channel.send({ kind: 'error', error: errorAsData(error) });
    }
  };
  channel.onRequest((request) => {
    queue = queue.then(() => answer(request));
  });
  // The CLI is gone (it exited, or was killed): nobody wants the numbers.
  channel.onDisconnect(() => channel.exit(0));
  channel.send({ kind: 'started' });
}

/** The first evaluation at one initial state, as the CLI's own models get it (dataset-run.ts). */
function probe(model: Model, set: InitialSet, index: number, t0: number): void {
  const state = new Float64Array(model.dim);
  fillInitial(set, index, 1, state, { dim: model.dim, hamiltonian: model.hamiltonian, t0, names: model.names });
  checkEvaluates(model, state, t0);
}

/**
 * Computes a task in stretches of rows, telling the CLI the steps taken
 * every PROGRESS_MS, then sends its numbers. The task runs without a return
 * to the event loop: the CLI stops a sandbox by killing it.
 */
function runTask(channel: Channel, runner: TaskRunner, task: Task): void {
  const { out } = runner.begin(task);
  const span = task.rowTo - task.rowFrom;
  let stride = 1;
  let steps = 0;
  let reported = 0;
  let last = performance.now();
  for (let done = 0; done < span; ) {
    const rows = Math.min(stride, span - done);
    const start = performance.now();
    steps += runner.produce(task, out, done, rows);
    done += rows;
    const now = performance.now();
    if (rows === stride) stride = nextStride(stride, now - start);
    if (now - last >= PROGRESS_MS) {
      channel.send({ kind: 'progress', steps: steps - reported });
      reported = steps;
      last = now;
    }
  }
  const result = runner.end(task, out, steps);
  channel.send({ kind: 'result', id: task.id, data: result.data!, steps: steps - reported });
  // The message holds a copy of the numbers: the buffer serves the next task.
  runner.recycle(result.data!.buffer as ArrayBuffer);
}

serve(harden());
