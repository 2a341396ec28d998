/// <reference types="astro/client" />

/** Minimal types for the Observable packages, which ship none. */
declare module '@observablehq/parser' {
  import type { ParsedCell } from '../cells/index.ts';

  /** Parses one Observable JavaScript cell; throws a SyntaxError with `loc` {line, column}. */
  export function parseCell(input: string, options?: { globals?: Set<string> }): ParsedCell;
}

declare module '@observablehq/runtime' {
  /** Receives a variable's state changes. */
  export interface Observer {
    pending?(): void;
    fulfilled?(value: unknown, name: string | null): void;
    rejected?(error: unknown, name: string | null): void;
  }

  export interface Variable {
    /** Redefines the variable; the runtime recomputes it and everything downstream. */
    define(name: string | null, inputs: readonly string[], definition: (...inputs: never[]) => unknown): Variable;
    delete(): Variable;
  }

  export interface Module {
    variable(observer?: Observer): Variable;
    /** The named variable's value once computed; rejects with its error, or when nothing defines the name. */
    value(name: string): Promise<unknown>;
  }

  export class Runtime {
    /** Builtin definitions are functions the runtime calls for the value. */
    constructor(builtins?: Record<string, () => unknown>, global?: (name: string) => unknown);
    module(): Module;
    dispose(): void;
  }

  export class RuntimeError extends Error {
    constructor(message: string, input?: string);
    /** The name of the variable the error came from, when it came through an input. */
    readonly input?: string;
  }
}
