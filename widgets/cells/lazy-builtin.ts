/**
 * Builtins that load on first use. A cell's builtins are only computed when
 * some cell names them, so a library entry written as
 *
 *   simulator: lazy(() => import('./simulator/simulator.ts').then((m) => m.simulator)),
 *
 * keeps that module out of the page's first load: it is fetched when a cell
 * that uses `simulator` first runs, and the cell waits for it like for any
 * promise.
 */

const LOAD = Symbol('phasebook.lazyBuiltin');

/** A builtin value that arrives from `load()` when a cell first needs it. */
export interface LazyBuiltin<T> {
  readonly [LOAD]: () => Promise<T>;
}

export function lazy<T>(load: () => Promise<T>): LazyBuiltin<T> {
  return { [LOAD]: load };
}

function isLazy(value: unknown): value is LazyBuiltin<unknown> {
  return typeof value === 'object' && value !== null && LOAD in value;
}

/**
 * The runtime definition of a builtin: the runtime calls a function-valued
 * builtin for its value, so even a plain value is wrapped in one.
 */
export function builtinDefinition(value: unknown): () => unknown {
  if (!isLazy(value)) return () => value;
  let loading: Promise<unknown> | null = null;
  return () => (loading ??= value[LOAD]());
}
