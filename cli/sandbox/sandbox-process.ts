/**
 * The sandbox, seen from the CLI: a child process of Node in which the
 * user's JavaScript (an H left opaque, a vector field) is built and run,
 * while the CLI keeps everything else — the arguments, the output file, the
 * progress bar, the signals.
 *
 * The boundary is Node's permission model (sandbox-flags.ts): the child may
 * read the compiled CLI's own files and do nothing else with the file
 * system, start no process or thread, load no addon. Its environment is
 * empty, so no token or password in the user's environment reaches it; its
 * working directory is the root, which it may not read. Inside, it takes
 * `process` and the network's globals away from the user's code before
 * compiling it (sandbox-harden.ts).
 *
 * The child answers requests (sandbox-messages.ts) over Node's IPC channel,
 * in order; the CLI checks every reply, since the code in there is not
 * trusted. A child that dies — the user's code called process.exit, ran out
 * of memory, crashed — fails the request under way with a sentence naming
 * that code, and a child the CLI stops is killed outright.
 */
import { spawn, type ChildProcess } from 'node:child_process';
import { realpathSync } from 'node:fs';
import { dirname, join, parse } from 'node:path';
import { fileURLToPath } from 'node:url';
import { InputError, type InitialSet } from '../../core/index.ts';
import type { Task, TaskResult, TaskSetup } from '../dataset/run-task.ts';
import { Interrupted } from '../interrupt.ts';
import type { ModelRecipe } from '../model/model.ts';
import { sandboxFlags } from './sandbox-flags.ts';
import { checkReply, printable, resultLength, type SandboxRequest } from './sandbox-messages.ts';

/** Whose code runs in a sandbox, as messages name it. */
export type UserCode = 'H' | 'the vector field';

/** The end of the child's stderr kept, to tell why it died (V8's out-of-memory report is a few lines). */
const STDERR_TAIL = 4096;

/**
 * Sandboxes not yet gone, killed if the CLI exits without closing them
 * (stdout closed under it by `| head` ends it with process.exit): code in an
 * endless loop would never notice that its CLI is gone.
 */
const running = new Set<ChildProcess>();
let killedOnExit = false;
function killOnExit(child: ChildProcess): void {
  running.add(child);
  child.once('exit', () => running.delete(child));
  if (killedOnExit) return;
  killedOnExit = true;
  process.once('exit', () => {
    for (const sandbox of running) sandbox.kill('SIGKILL');
  });
}

type Waiter =
  | { expect: 'done'; resolve: () => void; reject: (error: Error) => void }
  | { expect: 'result'; task: Task; width: number; resolve: (result: TaskResult) => void; reject: (error: Error) => void };

/**
 * The compiled sandbox script. From the bundle (build/cli/), it sits beside
 * this module's chunk. From the TypeScript sources (tests, tsx), the sandbox
 * still runs the bundle, made fresh first if the sources changed: TypeScript
 * cannot load in there, since tsx needs a worker thread and esbuild a child
 * process, which the sandbox is denied.
 */
async function sandboxScript(): Promise<string> {
  const here = import.meta.url;
  if (/\.js$/.test(here)) return fileURLToPath(new URL('./sandbox-child.js', here));
  // A path esbuild cannot follow: the build recipe is never bundled into the CLI.
  const builder = new URL('../../bin/cli-bundle.mjs', here).href;
  try {
    const { ensureCli } = (await import(builder)) as { ensureCli(): Promise<string> };
    return join(dirname(await ensureCli()), 'sandbox-child.js');
  } catch (error) {
    throw new Error(`the sandbox runs the compiled CLI, which could not be built (npm run build:cli says why): ${(error as Error)?.message ?? error}`);
  }
}

export class Sandbox {
  /** called with the steps a task reports as it goes */
  onProgress?: (steps: number) => void;
  private readonly waiting: Waiter[] = [];
  private failure: Error | undefined;
  private started = false;
  private closing = false;
  private stderr = '';
  private readonly exited: Promise<void>;

  /**
   * A sandbox with the model of `recipe` built, ready for requests. Once
   * `signal` is aborted (Ctrl-C), the child is killed and every request
   * fails with the signal's reason: the user's code may be in an endless
   * loop, which only killing ends.
   */
  static async open(recipe: ModelRecipe, what: UserCode, signal?: AbortSignal): Promise<Sandbox> {
    signal?.throwIfAborted();
    const sandbox = new Sandbox(await sandboxScript(), what);
    if (signal) {
      const stop = () => sandbox.fail(signal.reason as Error);
      if (signal.aborted) stop();
      else signal.addEventListener('abort', stop, { once: true });
      void sandbox.exited.then(() => signal.removeEventListener('abort', stop));
    }
    try {
      await sandbox.request({ kind: 'model', recipe });
    } catch (error) {
      await sandbox.close();
      throw error;
    }
    return sandbox;
  }

  private readonly child: ChildProcess;

  private constructor(
    script: string,
    private readonly what: UserCode,
  ) {
    const real = realpathSync(script);
    this.child = spawn(process.execPath, [...sandboxFlags([dirname(real)]), real], {
      stdio: ['ignore', 'ignore', 'pipe', 'ipc'],
      serialization: 'advanced',
      env: {},
      cwd: parse(real).root,
      windowsHide: true,
    });
    killOnExit(this.child);
    this.child.stderr!.setEncoding('utf8');
    this.child.stderr!.on('data', (chunk: string) => {
      this.stderr = (this.stderr + chunk).slice(-STDERR_TAIL);
    });
    this.child.on('message', (message) => this.receive(message));
    this.exited = new Promise((resolve) => {
      this.child.on('exit', (code, signal) => {
        if (!this.closing) this.fail(this.death(code, signal));
        resolve();
      });
      this.child.on('error', (error) => {
        this.fail(new Error(`the sandbox for ${this.whose()} failed: ${error.message}`));
        // A process that never started never exits either.
        if (this.child.pid === undefined) resolve();
      });
    });
  }

  /** Evaluates the model once at the initial state of trajectory `index` of `set`; rejects with the fault, in words. */
  probe(set: InitialSet, index: number, t0: number): Promise<void> {
    return this.request({ kind: 'probe', set, index, t0 });
  }

  /** Hands over what the run's tasks share. */
  setup(setup: TaskSetup): Promise<void> {
    return this.request({ kind: 'setup', setup });
  }

  /** Runs a task; its rows are `width` numbers each. */
  task(task: Task, width: number): Promise<TaskResult> {
    return new Promise((resolve, reject) => this.send({ kind: 'task', task }, { expect: 'result', task, width, resolve, reject }));
  }

  /** Kills the child, failing whatever it was asked; resolves once it is gone. */
  async close(): Promise<void> {
    if (!this.closing) {
      this.closing = true;
      this.fail(new Error('the sandbox was stopped'));
      this.child.kill('SIGKILL');
    }
    await this.exited;
  }

  private request(message: SandboxRequest): Promise<void> {
    return new Promise((resolve, reject) => this.send(message, { expect: 'done', resolve, reject }));
  }

  private send(message: SandboxRequest, waiter: Waiter): void {
    if (this.failure) return waiter.reject(this.failure);
    this.waiting.push(waiter);
    this.child.send(message, (error) => {
      if (!error || this.closing) return;
      // A channel broken under the message (EPIPE) is a child that is dying — the user's code crashed it a moment
      // before — and its exit, which comes next, says why; the broken channel only says so if nothing else did.
      const unsent = new Error(`the sandbox for ${this.whose()} could not be sent its work: ${error.message}`);
      void this.exited.then(() => this.fail(unsent));
    });
  }

  /** One message from the child, checked for its form and for being the reply awaited. */
  private receive(message: unknown): void {
    if (this.failure) return;
    const reply = checkReply(message);
    if (reply?.kind === 'started' && !this.started) {
      this.started = true;
      return;
    }
    if (!reply || reply.kind === 'started' || !this.started) return this.fail(this.tampered());
    if (reply.kind === 'progress') return this.onProgress?.(reply.steps);
    const waiter = this.waiting.shift();
    if (!waiter) return this.fail(this.tampered());
    if (reply.kind === 'error') return waiter.reject(reply.error);
    if (reply.kind === 'done' && waiter.expect === 'done') return waiter.resolve();
    if (reply.kind === 'result' && waiter.expect === 'result' && reply.id === waiter.task.id && reply.data.length === resultLength(waiter.task, waiter.width)) {
      return waiter.resolve({ id: reply.id, data: reply.data, steps: reply.steps });
    }
    this.fail(this.tampered());
  }

  /** Fails every request waiting, and any made from now on, with `error`. */
  private fail(error: Error): void {
    this.failure ??= error;
    for (const waiter of this.waiting.splice(0)) waiter.reject(this.failure);
    if (!this.closing) {
      // A child that broke the protocol is not asked anything more.
      this.closing = true;
      this.child.kill('SIGKILL');
    }
  }

  private whose(): string {
    return this.what === 'H' ? "H's code" : "the vector field's code";
  }

  private tampered(): Error {
    return new InputError(`${this.whose()} sent the CLI something other than its results from the sandbox it runs in; nothing was written`);
  }

  /** The child ended on its own: why, in one line. */
  private death(code: number | null, signal: NodeJS.Signals | null): Error {
    // Ctrl-C on a terminal reaches the whole process group, the sandbox too, which may die of it before the CLI hears it.
    if (signal === 'SIGINT' || signal === 'SIGTERM') return new Interrupted(signal);
    const how = code !== null ? `exit status ${code}` : `signal ${signal}`;
    if (!this.started) {
      const said = printable(this.stderr.trim().split('\n').filter(Boolean).pop() ?? '', 200);
      return new Error(`the sandbox for ${this.whose()} did not start (${how})${said ? `: ${said}` : ''}`);
    }
    if (/heap out of memory|allocation failed/i.test(this.stderr)) return new InputError(`${this.whose()} ran out of memory in the sandbox it runs in`);
    return new InputError(`${this.whose()} ended the sandboxed process it runs in (${how})`);
  }
}
