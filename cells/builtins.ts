/**
 * Everything a cell may name without defining it.
 *
 * Observable runtime 6 ships no standard library and, by default, looks any
 * unknown name up on `window` — so a typo such as `name` or `status` would
 * quietly resolve to a window property. The book passes its builtins
 * explicitly and makes every other name an error (see runtime.ts).
 *
 * The book's own catalogue (widgets/catalogue.ts) comes from the caller, as a
 * loader per name, and is spread over the standard builtins. A loader is
 * called when a cell first names its entry, and only once: the page fetches
 * a widget's module only if some cell uses it.
 *
 * `invalidation` needs no entry: the runtime gives each cell a promise that
 * resolves when the cell is redefined or the page disposes it, for stopping
 * animation loops and observers.
 */
import { standardValues } from './globals.ts';
import { html } from './html.ts';
import { explainLoadFailure } from './load-failure.ts';
import { observeNow, observeWidth } from './observe.ts';

/** How the runtime wants a builtin: a function it calls for the value. */
export type BuiltinDefinition = () => unknown;

/** Names a caller adds to the builtins, each with the loader of its value. */
export type Loaders = Readonly<Record<string, () => Promise<unknown>>>;

/** The runtime calls a function-valued builtin for its value, so even a plain value is wrapped in one. */
export function plainDefinition(value: unknown): BuiltinDefinition {
  return () => value;
}

/**
 * A definition that calls `load` the first time the runtime asks, and hands
 * every later cell the same promise. A load that fails (offline) says so in
 * the reader's words, and is tried again when a cell next asks.
 */
export function loadedDefinition(load: () => Promise<unknown>, name = 'part'): BuiltinDefinition {
  let loading: Promise<unknown> | null = null;
  return () =>
    (loading ??= load().catch((error: unknown) => {
      loading = null;
      throw explainLoadFailure(error, `The book's ${name}`);
    }));
}

/**
 * The builtins object for `new Runtime(…)`. `root` is the element whose
 * width the `width` builtin follows (the chapter's text column).
 */
export function createBuiltins(root: Element, catalogue: Loaders): Record<string, BuiltinDefinition> {
  const definitions: Record<string, BuiltinDefinition> = {};
  for (const [name, value] of Object.entries({ ...standardValues(), html })) definitions[name] = plainDefinition(value);
  for (const [name, load] of Object.entries(catalogue)) definitions[name] = loadedDefinition(load, name);
  definitions.width = () => observeWidth(root);
  definitions.now = () => observeNow();
  return definitions;
}
