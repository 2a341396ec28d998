/**
 * The page's notebook: one Observable runtime module holding every cell of
 * the chapter, so cells that name each other recompute together.
 */
import { Runtime, RuntimeError, type Module, type Observer, type Variable } from '@observablehq/runtime';
import type { BuiltinDefinition } from './builtins.ts';
import type { CellDefinition } from './cell-definition.ts';
import { explainLoadFailure } from './load-failure.ts';
import { formatError, type CellSpec } from './spec.ts';

export type { Observer as CellObserver, Variable as CellVariable };

/**
 * Replaces the runtime's `window` lookup: a name that is neither a cell nor a
 * builtin is an error, never a window property.
 */
function undefinedName(name: string): never {
  throw new RuntimeError(`${name} is not defined`);
}

/** Why a superseded definition's promise was let go; the runtime ignores it, as it does any stale value. */
class Superseded extends Error {
  override name = 'Superseded';
}

/** The signal of the cell whose code is running right now (synchronously), if any. */
let running: AbortSignal | undefined;

/**
 * The signal that aborts when the cell now running is defined again: work a
 * cell starts (a model build, say) can take it, so that an edit making the
 * work obsolete also stops it. Only known while the cell's code runs
 * synchronously, which is when a cell calls such a function.
 */
export function currentCellSignal(): AbortSignal | undefined {
  return running;
}

/** Rejects with {@link Superseded} when `signal` aborts. */
function whenAborted(signal: AbortSignal): Promise<never> {
  return new Promise((_, reject) => signal.addEventListener('abort', () => reject(new Superseded('redefined')), { once: true }));
}

/**
 * The definition, made to let go of its value when the cell is defined
 * again. The runtime waits for a variable's previous value before computing
 * its new definition, so a promise that never settles (`x = new Promise(() => {})`)
 * would keep the cell pending for ever, fixes and Reset included.
 */
function supersedable(definition: CellDefinition, signal: AbortSignal): CellDefinition {
  return ((...inputs: never[]) => {
    const outer = running;
    running = signal;
    let value: unknown;
    try {
      value = definition(...inputs);
    } finally {
      running = outer;
    }
    if (value instanceof Promise) return Promise.race([value, whenAborted(signal)]);
    if (typeof value === 'object' && value !== null && Symbol.asyncIterator in value) {
      const iterator = value as unknown as AsyncIterator<unknown>;
      const next = iterator.next.bind(iterator);
      iterator.next = (...args: [] | [unknown]) => Promise.race([next(...args), whenAborted(signal)]);
    }
    return value;
  }) as CellDefinition;
}

export class Notebook {
  readonly #runtime: Runtime;
  readonly #module: Module;
  /** Which variable currently defines each name, for telling cell inputs from unknown names. */
  readonly #definers = new Map<string, Variable>();
  /** Aborts when a variable is defined again, releasing its old definition's pending value. */
  readonly #current = new Map<Variable, AbortController>();

  constructor(builtins: Record<string, BuiltinDefinition>) {
    this.#runtime = new Runtime(builtins, undefinedName);
    this.#module = this.#runtime.module();
  }

  /** A new, still undefined variable whose changes go to `observer`. */
  add(observer: Observer): Variable {
    return this.#module.variable(observer);
  }

  /** (Re)defines `variable`; the old definition's `invalidation` resolves. */
  define(variable: Variable, spec: CellSpec, definition: CellDefinition): void {
    for (const [name, definer] of this.#definers) if (definer === variable) this.#definers.delete(name);
    if (spec.name) this.#definers.set(spec.name, variable);
    this.#current.get(variable)?.abort();
    const controller = new AbortController();
    this.#current.set(variable, controller);
    variable.define(spec.name, spec.inputs, supersedable(definition, controller.signal));
  }

  /** Deletes a variable (a cell the reader deleted); cells that read its name see it undefined. */
  remove(variable: Variable): void {
    for (const [name, definer] of this.#definers) if (definer === variable) this.#definers.delete(name);
    this.#current.get(variable)?.abort();
    this.#current.delete(variable);
    variable.delete();
  }

  /** The value `name` has once computed (a rejection carries what its cell failed with). */
  value(name: string): Promise<unknown> {
    return this.#module.value(name);
  }

  /** True when a cell (not a builtin, not an unknown name) defines `name`. */
  isCell(name: string): boolean {
    return this.#definers.has(name);
  }

  /**
   * The line shown under a failed cell. A failure that came through an input
   * names that input, so the reader looks in the right cell; an unknown name
   * is reported by the cell that used it.
   */
  describeFailure(error: unknown, name: string | null): string {
    if (error instanceof RuntimeError && error.input && error.input !== name && this.isCell(error.input)) {
      return `RuntimeError: input ${error.input} failed: ${error.message}`;
    }
    // A widget that loads more of its code as it goes (a view, a worker's page side) may meet a lost connection too.
    return formatError(explainLoadFailure(error, 'Part of the book this cell uses'));
  }

  dispose(): void {
    this.#runtime.dispose();
  }
}
