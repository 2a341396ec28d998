/**
 * Everything a cell may name without defining it.
 *
 * Observable runtime 6 ships no standard library and, by default, looks any
 * unknown name up on `window` — so a typo such as `name` or `status` would
 * quietly resolve to a window property. The book passes its builtins
 * explicitly and makes every other name an error (see runtime.ts).
 *
 * The book's own catalogue (widgets/library.ts) comes from the caller and
 * is spread over the standard builtins. An entry wrapped in `lazy(…)`
 * (lazy-builtin.ts) loads only when a cell first names it.
 *
 * `invalidation` needs no entry: the runtime gives each cell a promise that
 * resolves when the cell is redefined or the page disposes it, for stopping
 * animation loops and observers.
 */
import { standardValues } from './globals.ts';
import { html } from './html.ts';
import { builtinDefinition } from './lazy-builtin.ts';
import { observeNow, observeWidth } from './observe.ts';

/** How the runtime wants a builtin: a function it calls for the value. */
export type BuiltinDefinition = () => unknown;

/** The values a cell sees, before wrapping for the runtime: the standard ones, then `catalogue`'s. */
export function builtinValues(catalogue: Readonly<Record<string, unknown>>): Record<string, unknown> {
  return { ...standardValues(), html, ...catalogue };
}

/**
 * The builtins object for `new Runtime(…)`. `root` is the element whose
 * width the `width` builtin follows (the chapter's text column).
 */
export function createBuiltins(root: Element, catalogue: Readonly<Record<string, unknown>>): Record<string, BuiltinDefinition> {
  const definitions: Record<string, BuiltinDefinition> = {};
  for (const [name, value] of Object.entries(builtinValues(catalogue))) definitions[name] = builtinDefinition(value);
  definitions.width = () => observeWidth(root);
  definitions.now = () => observeNow();
  return definitions;
}
