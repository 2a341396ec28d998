/**
 * Runs a plan's tasks on executors and hands their results to the writer in
 * the plan's order, whatever order they finish in.
 *
 * An executor takes the next run not yet started and does its tasks in turn
 * (a run's state lives where it started); in time order each keeps one run.
 * Results that arrive ahead of their turn wait, but at most `ahead` of them:
 * an executor whose next result is not the one to write pauses until there
 * is room, so memory stays bounded however uneven the work. The task to be
 * written next is never held back, so the run cannot stall. An executor is
 * given up to its `depth` tasks at once (a worker's queue), each still in
 * the plan's order for it.
 */
import type { Executor } from './executors.ts';
import type { Plan } from './plan-tasks.ts';
import type { Task, TaskResult } from './run-task.ts';
import type { BlockOrder } from '../formats/dataset-shape.ts';

export interface ScheduleOptions {
  order: BlockOrder;
  /** results held at most beyond the one to write next */
  ahead: number;
  write(task: Task, result: TaskResult): void;
  /** called with each result's steps, after it is written (the local executor reports its own) */
  done?(result: TaskResult): void;
  signal?: AbortSignal;
}

export async function schedule(plan: Plan, executors: readonly Executor[], options: ScheduleOptions): Promise<void> {
  const { ahead, write, signal } = options;
  let nextRun = 0;
  let nextWrite = 0;
  const held = new Map<number, { result: TaskResult; from: Executor }>();
  let waiters: (() => void)[] = [];
  let failure: unknown;
  const wake = () => {
    const all = waiters;
    waiters = [];
    for (const w of all) w();
  };
  const drain = () => {
    while (held.has(nextWrite)) {
      const { result, from } = held.get(nextWrite)!;
      held.delete(nextWrite);
      write(plan.task(nextWrite), result);
      options.done?.(result);
      const payload = result.data ?? result.text;
      if (payload) from.recycle(payload);
      nextWrite++;
    }
    wake();
  };
  const check = () => {
    if (failure !== undefined) throw failure;
    signal?.throwIfAborted();
  };
  // A signal stops the workers at once, mid-task: an interrupted run ends within milliseconds.
  const onAbort = () => {
    wake();
    for (const e of executors) void e.close();
  };
  signal?.addEventListener('abort', onAbort);

  /** The tasks an executor does, in order: every chunk of each run it takes (a run is taken when its first chunk is reached). */
  function* tasksOf(fixed: number | undefined): Generator<number> {
    for (;;) {
      const run = fixed ?? (nextRun < plan.runs ? nextRun++ : undefined);
      if (run === undefined || run >= plan.runs) return;
      for (let chunk = 0; chunk < plan.chunks; chunk++) yield plan.seq(run, chunk);
      if (fixed !== undefined) return;
    }
  }

  const loop = async (executor: Executor, fixed: number | undefined) => {
    const ids = tasksOf(fixed);
    const inFlight: { id: number; result: Promise<TaskResult> }[] = [];
    let next = ids.next();
    for (;;) {
      while (!next.done && inFlight.length < Math.max(1, executor.depth)) {
        const id = next.value;
        check();
        if (held.size >= ahead && id !== nextWrite) {
          // No room: collect what is under way first, or wait for the writer.
          if (inFlight.length > 0) break;
          await new Promise<void>((resolve) => waiters.push(resolve));
          continue;
        }
        const result = executor.run(plan.task(id));
        // Awaited in turn below; a failure of one not yet awaited must not go unhandled meanwhile.
        result.catch(() => {});
        inFlight.push({ id, result });
        next = ids.next();
      }
      const first = inFlight.shift();
      if (!first) return;
      const result = await first.result;
      check();
      held.set(first.id, { result, from: executor });
      drain();
    }
  };

  try {
    await Promise.all(
      executors.map((executor, i) =>
        loop(executor, plan.order === 'time' ? i : undefined).catch((error) => {
          failure ??= error;
          wake();
          // Stop the others at once: a worker deep in a task is terminated.
          return Promise.all(executors.map((e) => e.close()));
        }),
      ),
    );
  } finally {
    signal?.removeEventListener('abort', onAbort);
  }
  signal?.throwIfAborted();
  if (failure !== undefined) throw failure;
}
