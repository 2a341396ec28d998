/**
 * A run's model where the run uses it: built in this process when all its
 * code is the compiler's (an expression, or a JS function translated to
 * one), or in sandboxes when it runs the user's JavaScript (an H left
 * opaque, a vector field; see sandbox-process.ts). The run asks the same of
 * both: the model's facts, one first evaluation, and executors for its
 * tasks. A model built here runs exactly as it did before the sandbox
 * existed; only the user's code pays for a process.
 */
import { fillInitial, type InitialSet, type Model } from '../../core/index.ts';
import { localExecutor, workerExecutor, type Executor } from '../dataset/executors.ts';
import type { Task, TaskResult, TaskSetup } from '../dataset/run-task.ts';
import { checkEvaluates, modelFromRecipe, userCodeOf, type ModelRecipe } from './model.ts';
import { factsOfModel, factsOfRecipe, type ModelFacts } from './model-facts.ts';
import { Sandbox, type UserCode } from '../sandbox/sandbox-process.ts';

export interface ExecutorOptions {
  /** numbers in a row of the run's output */
  width: number;
  signal?: AbortSignal;
  /** called with steps as the executors take them, when they report their own progress */
  tick(steps: number): void;
}

export interface RunModel {
  readonly facts: ModelFacts;
  /** whether its executors may be asked to format rows as text (a sandbox hands back numbers only) */
  readonly formatsText: boolean;
  /** Evaluates the model at the initial state of trajectory `index` of `set`: an H that throws, or returns a string, is said now. */
  probe(set: InitialSet, index: number, t0: number): Promise<void>;
  /** `count` executors for the run's tasks; `ownProgress` when they call tick themselves, else each result's steps count once written. */
  executors(count: number, setup: TaskSetup, options: ExecutorOptions): Promise<{ executors: Executor[]; ownProgress: boolean }>;
  /** Stops whatever it started; never throws. */
  close(): Promise<void>;
}

/** The run model of `recipe`: here, or sandboxed if it runs the user's code; `signal` stops a sandbox. */
export async function openRunModel(recipe: ModelRecipe, signal?: AbortSignal): Promise<RunModel> {
  const user = userCodeOf(recipe);
  return user ? sandboxedModel(recipe, user.what, await Sandbox.open(recipe, user.what, signal)) : localModel(recipe, modelFromRecipe(recipe));
}

function localModel(recipe: ModelRecipe, model: Model): RunModel {
  return {
    facts: factsOfModel(model),
    formatsText: true,
    async probe(set, index, t0) {
      const state = new Float64Array(model.dim);
      fillInitial(set, index, 1, state, { dim: model.dim, hamiltonian: model.hamiltonian, t0, names: model.names });
      checkEvaluates(model, state, t0);
    },
    async executors(count, setup, { signal, tick }) {
      // One thread: this one, in stretches that hear Ctrl-C. More: worker threads, each building the model from the recipe.
      if (count === 1) return { executors: [localExecutor(model, setup, signal, tick)], ownProgress: true };
      return { executors: Array.from({ length: count }, () => workerExecutor({ recipe, setup })), ownProgress: false };
    },
    async close() {},
  };
}

/**
 * The model in sandboxes: `first`, opened to learn whether the user's code
 * builds and evaluates, then runs tasks with as many more as the run has
 * workers, each a process of its own (no worker threads in a sandbox).
 */
function sandboxedModel(recipe: ModelRecipe, what: UserCode, first: Sandbox): RunModel {
  const sandboxes = [first];
  return {
    facts: factsOfRecipe(recipe),
    formatsText: false,
    probe: (set, index, t0) => first.probe(set, index, t0),
    async executors(count, setup, { width, signal, tick }) {
      const more = await Promise.allSettled(Array.from({ length: count - 1 }, () => Sandbox.open(recipe, what, signal)));
      for (const opened of more) if (opened.status === 'fulfilled') sandboxes.push(opened.value);
      const refused = more.find((opened) => opened.status === 'rejected');
      if (refused) throw refused.reason;
      await Promise.all(sandboxes.map((sandbox) => sandbox.setup(setup)));
      return { executors: sandboxes.map((sandbox) => sandboxExecutor(sandbox, width, tick)), ownProgress: true };
    },
    async close() {
      await Promise.all(sandboxes.map((sandbox) => sandbox.close()));
    },
  };
}

/** A sandbox as an executor: two tasks queued, progress as it reports it, the rest of a task's steps with its result. */
function sandboxExecutor(sandbox: Sandbox, width: number, tick: (steps: number) => void): Executor {
  sandbox.onProgress = tick;
  return {
    async run(task: Task): Promise<TaskResult> {
      const result = await sandbox.task(task, width);
      tick(result.steps);
      return result;
    },
    depth: 2,
    // The numbers came as a copy: there is no buffer to hand back.
    recycle() {},
    close: () => sandbox.close(),
  };
}
