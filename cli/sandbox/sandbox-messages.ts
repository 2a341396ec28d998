/**
 * What the CLI and its sandbox (sandbox-child.ts) say to each other, and the
 * CLI's reading of what comes back.
 *
 * The sandbox runs code the CLI does not trust, so everything it sends is
 * read as data from a stranger: a reply must be the one the CLI waits for,
 * a task's numbers exactly as many as the task asked for, and an error's
 * words are cut to one printable line before they reach the terminal, where
 * control characters could rewrite what the user sees. A message that fails
 * these checks ends the run as the user code's fault.
 */
import { BlowUpError, InputError, type InitialSet } from '../../core/index.ts';
import type { WorkerError } from '../dataset/worker-thread.ts';
import type { Task, TaskSetup } from '../dataset/run-task.ts';
import type { ModelRecipe } from '../model/model.ts';

/** From the CLI: one request at a time, each answered by one reply, in order; tasks may queue. */
export type SandboxRequest =
  /** build the model of the recipe (the user's code is compiled here) */
  | { kind: 'model'; recipe: ModelRecipe }
  /** evaluate the model once at the initial state of trajectory `index` (firstEvaluation, and --energy's projection) */
  | { kind: 'probe'; set: InitialSet; index: number; t0: number }
  /** what the tasks of the run share */
  | { kind: 'setup'; setup: TaskSetup }
  | { kind: 'task'; task: Task };

/** From the sandbox. */
export type SandboxReply =
  /** sent once, before any user code is compiled: the process started as it should */
  | { kind: 'started' }
  /** a model, probe or setup request done */
  | { kind: 'done' }
  /** steps taken since the last report, while a task runs */
  | { kind: 'progress'; steps: number }
  /** a task's numbers, and its steps not yet reported */
  | { kind: 'result'; id: number; data: Float64Array; steps: number }
  /** the request under way failed */
  | { kind: 'error'; error: WorkerError };

/** Longest message from the sandbox shown to the user. */
const MESSAGE_CHARS = 400;

/**
 * Text from the sandbox as one printable line: C0 and C1 control characters
 * (ESC, CR, BEL…), line breaks and the marks that reorder text on screen
 * (bidirectional overrides and isolates) become spaces, and a long text is
 * cut.
 */
export function printable(text: string, limit = MESSAGE_CHARS): string {
  const line = text.replace(/[\u0000-\u001f\u007f-\u009f\u200e\u200f\u2028-\u202e\u2066-\u2069]+/g, ' ').trim();
  return line.length > limit ? `${line.slice(0, limit)}…` : line;
}

const isCount = (v: unknown): v is number => typeof v === 'number' && Number.isSafeInteger(v) && v >= 0;

/** The CLI's error for a WorkerError the sandbox sent, or undefined if it is not one. */
function errorOf(data: unknown): Error | undefined {
  const e = data as Partial<Record<string, unknown>> | null;
  if (typeof e !== 'object' || e === null) return undefined;
  if (e.kind === 'input' && typeof e.message === 'string') return new InputError(printable(e.message));
  if (e.kind === 'blow-up' && typeof e.t === 'number' && typeof e.component === 'string' && typeof e.value === 'number') {
    const trajectory = isCount(e.trajectory) ? e.trajectory : undefined;
    return new BlowUpError(e.t, printable(e.component, 40), e.value, trajectory);
  }
  if (e.kind === 'internal' && typeof e.message === 'string') return new Error(printable(e.message));
  return undefined;
}

/** A reply checked for its form; its fit with the request waiting for it is the caller's to check. */
export type CheckedReply =
  | { kind: 'started' | 'done' }
  | { kind: 'progress'; steps: number }
  | { kind: 'result'; id: number; data: Float64Array; steps: number }
  | { kind: 'error'; error: Error };

/** `message` as a reply, or undefined when it has no reply's form. */
export function checkReply(message: unknown): CheckedReply | undefined {
  const m = message as Partial<Record<string, unknown>> | null;
  if (typeof m !== 'object' || m === null) return undefined;
  switch (m.kind) {
    case 'started':
    case 'done':
      return { kind: m.kind };
    case 'progress':
      return isCount(m.steps) ? { kind: 'progress', steps: m.steps } : undefined;
    case 'result':
      return isCount(m.id) && isCount(m.steps) && m.data instanceof Float64Array ? { kind: 'result', id: m.id, data: m.data, steps: m.steps } : undefined;
    case 'error': {
      const error = errorOf(m.error);
      return error ? { kind: 'error', error } : undefined;
    }
    default:
      return undefined;
  }
}

/** The numbers a task's result must hold: its rows of its trajectories, each `width` wide. */
export function resultLength(task: Task, width: number): number {
  return task.count * (task.rowTo - task.rowFrom) * width;
}
