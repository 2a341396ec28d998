/**
 * The page's notebook: one Observable runtime module holding every cell of
 * the chapter, so cells that name each other recompute together.
 */
import { Runtime, RuntimeError, type Module, type Observer, type Variable } from '@observablehq/runtime';
import type { BuiltinDefinition } from './builtins.ts';
import type { CellDefinition } from './compile.ts';
import { formatError, type CellSpec } from './spec.ts';

export type { Observer as CellObserver, Variable as CellVariable };

/**
 * Replaces the runtime's `window` lookup: a name that is neither a cell nor a
 * builtin is an error, never a window property.
 */
function undefinedName(name: string): never {
  throw new RuntimeError(`${name} is not defined`);
}

export class Notebook {
  readonly #runtime: Runtime;
  readonly #module: Module;
  /** Which variable currently defines each name, for telling cell inputs from unknown names. */
  readonly #definers = new Map<string, Variable>();

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
    variable.define(spec.name, spec.inputs, definition);
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
    return formatError(error);
  }

  dispose(): void {
    this.#runtime.dispose();
  }
}
