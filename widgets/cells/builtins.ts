/**
 * Everything a cell may name without defining it.
 *
 * Observable runtime 6 ships no standard library and, by default, looks any
 * unknown name up on `window` — so a typo such as `name` or `status` would
 * quietly resolve to a window property. The book passes its builtins
 * explicitly and makes every other name an error (see runtime.ts).
 *
 * To add widgets, edit widgets/library.ts, not this file: its `library`
 * object is spread over these builtins. An entry wrapped in `lazy(…)`
 * (lazy-builtin.ts) loads only when a cell first names it.
 *
 * `invalidation` needs no entry: the runtime gives each cell a promise that
 * resolves when the cell is redefined or the page disposes it, for stopping
 * animation loops and observers.
 */
import { library } from '../library.ts';
import { html } from './html.ts';
import { builtinDefinition } from './lazy-builtin.ts';
import { observeNow, observeWidth } from './observe.ts';

/** How the runtime wants a builtin: a function it calls for the value. */
export type BuiltinDefinition = () => unknown;

/** Plain JavaScript globals a cell may use by name. */
const JAVASCRIPT_GLOBALS = [
  'Array', 'ArrayBuffer', 'BigInt', 'Boolean', 'DataView', 'Date', 'Error', 'EvalError', 'Infinity',
  'Intl', 'JSON', 'Map', 'Math', 'NaN', 'Number', 'Object', 'Promise', 'Proxy', 'RangeError',
  'ReferenceError', 'Reflect', 'RegExp', 'Set', 'String', 'Symbol', 'SyntaxError', 'TypeError',
  'URIError', 'WeakMap', 'WeakSet', 'Float32Array', 'Float64Array', 'Int8Array', 'Int16Array',
  'Int32Array', 'Uint8Array', 'Uint8ClampedArray', 'Uint16Array', 'Uint32Array', 'BigInt64Array',
  'BigUint64Array', 'isFinite', 'isNaN', 'parseFloat', 'parseInt', 'structuredClone', 'queueMicrotask',
] as const;

/** Browser globals a cell may use by name: timing, drawing, observing. */
const BROWSER_GLOBALS = [
  'console', 'performance', 'document', 'requestAnimationFrame', 'cancelAnimationFrame',
  'setTimeout', 'clearTimeout', 'setInterval', 'clearInterval', 'ResizeObserver',
  'IntersectionObserver', 'Path2D', 'ImageData', 'DOMMatrix', 'devicePixelRatio',
] as const;

/**
 * Free functions such as `setTimeout` throw "Illegal invocation" in some
 * engines when called without their global as `this`; constructors must not
 * be bound (a bound class loses its statics).
 */
function fromGlobal(name: string): unknown {
  const value: unknown = Reflect.get(globalThis, name);
  const isConstructorName = name[0] === name[0]?.toUpperCase();
  return typeof value === 'function' && !isConstructorName ? value.bind(globalThis) : value;
}

/** Math's functions and constants by bare name: sin, cos, sqrt, hypot, PI, E, … */
function mathByName(): Record<string, unknown> {
  const entries = Object.getOwnPropertyNames(Math).map((name) => [name, Reflect.get(Math, name)] as const);
  return Object.fromEntries(entries);
}

/** The values a cell sees, before wrapping for the runtime. */
export function builtinValues(): Record<string, unknown> {
  const values: Record<string, unknown> = {};
  for (const name of [...JAVASCRIPT_GLOBALS, ...BROWSER_GLOBALS]) {
    if (name in globalThis) values[name] = fromGlobal(name);
  }
  return { ...values, ...mathByName(), html, ...library };
}

/**
 * The builtins object for `new Runtime(…)`. `root` is the element whose
 * width the `width` builtin follows (the chapter's text column).
 */
export function createBuiltins(root: Element): Record<string, BuiltinDefinition> {
  const definitions: Record<string, BuiltinDefinition> = {};
  for (const [name, value] of Object.entries(builtinValues())) definitions[name] = builtinDefinition(value);
  definitions.width = () => observeWidth(root);
  definitions.now = () => observeNow();
  return definitions;
}
